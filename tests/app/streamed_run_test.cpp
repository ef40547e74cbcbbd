// A run whose outputs need no move afterwards streams the moves from the interpreter into the
// simulation (app/run_pipeline.hpp): it must report exactly what the run that keeps them
// reports, and its peak memory, pictures and all, must not grow with the program's length.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/support/lathesim_process.hpp"

namespace lathesim::app {
namespace {

namespace fs = std::filesystem;

// `blocks` one-move G01 blocks, alternating between two diameters (what
// scripts/long_program_memory.sh measures).
std::string straightProgram(int blocks) {
  std::string program = "G99 M03 S800\nG00 X40 Z2\n";
  for (int i = 0; i < blocks; ++i)
    program += "G01 X" + std::to_string(i % 2 ? 40 : 42) + " Z-" + std::to_string(i % 50) + " F0.1\n";
  return program + "M30\n";
}

// report.json without what differs from run to run (the timings and the memory figures).
nlohmann::json reportOf(const fs::path& out) {
  nlohmann::json report = nlohmann::json::parse(test::readFile(out / "report.json"));
  for (const char* key : {"timing_s", "peak_memory_mb", "grid_memory_mb"}) report.erase(key);
  return report;
}

// The two reports the same; numbers to 1e-9 of their size: a thread's sweep sums its removal
// in parallel, in an order that varies from run to run in the last digit.
void expectSameReport(const nlohmann::json& streamed, const nlohmann::json& kept, const std::string& where) {
  if (kept.is_number_float()) {
    EXPECT_NEAR(streamed.get<double>(), kept.get<double>(), 1e-9 * std::max(1.0, std::abs(kept.get<double>()))) << where;
  } else if (kept.is_structured() && streamed.type() == kept.type() && streamed.size() == kept.size()) {
    for (auto k = kept.begin(), s = streamed.begin(); k != kept.end(); ++k, ++s) {
      if (kept.is_object()) {
        EXPECT_EQ(s.key(), k.key()) << where;
      }
      expectSameReport(*s, *k, where + "/" + (kept.is_object() ? k.key() : std::to_string(std::distance(kept.begin(), k))));
    }
  } else {
    EXPECT_EQ(streamed, kept) << where;
  }
}

struct RunFiles {
  nlohmann::json report;
  std::string csv;
};

// `lathesim run` of `program` at 0.4 mm voxels writing `outputs`, and with `extra` arguments:
// --animate makes it keep every move (the video draws the toolpath as far as each frame);
// without it they stream, to the pictures' drawing and toolpath.vtp's spool as well.
RunFiles run(const fs::path& program, const std::vector<std::string>& setup, const std::string& outputs,
             const std::vector<std::string>& extra, const test::ScratchDir& scratch) {
  const fs::path out = scratch.path() / (outputs + std::to_string(extra.size()));
  std::vector<std::string> args{"run", program.string(), "--voxel", "0.4", "--outputs", outputs, "--out", out.string()};
  args.insert(args.end(), setup.begin(), setup.end());
  args.insert(args.end(), extra.begin(), extra.end());
  const test::ProcessOutcome outcome = test::runProcess(LATHESIM_BINARY, args, scratch.path());
  RunFiles files{reportOf(out), test::readFile(out / "toolpath.csv")};
  // A part meant to crash (parts/dogleg-groove-retract) exits 4, its outputs written.
  const bool crashes = !files.report.value("collisions", nlohmann::json::array()).empty();
  EXPECT_EQ(outcome.status, crashes ? 4 : 0) << outcome.err;
  return files;
}

void expectStreamedAsKept(const fs::path& program, const std::vector<std::string>& setup) {
  test::ScratchDir scratch("streamed");
  const RunFiles kept = run(program, setup, "report,csv", {"--animate", "--frames", "2", "--video-size", "160x120"}, scratch);
  const RunFiles streamed = run(program, setup, "report,csv,vtp,png", {}, scratch);
  expectSameReport(streamed.report, kept.report, program.string());
  EXPECT_EQ(streamed.csv, kept.csv) << program;
  EXPECT_FALSE(streamed.report["blocks"].empty()) << program;
}

using test::ffmpegInstalled;

// Parts that use what the simulation reads beside the moves: cycle starts, threads, a part-off
// and a parts catcher, work shifts, subprograms, nose radius compensation, dog-leg rapids.
TEST(StreamedRun, BundledPartsReportAsWhenTheMovesAreKept) {
  for (const char* part : {"g92-two-start", "g76-m30x2", "m98-grooves", "shop-pin-partoff-g75", "tube-bore-partoff",
                           "g50-shift-twice", "g71-g70-shaft", "nose-comp-g42", "dogleg-groove-retract", "shop-g55-safety"}) {
    if (!ffmpegInstalled()) GTEST_SKIP() << "the run that keeps every move is --animate's, which needs ffmpeg";
    const fs::path dir = fs::path(LATHESIM_PARTS_DIR) / part;
    expectStreamedAsKept(dir / "program.nc", {"--setup", (dir / "setup.toml").string()});
  }
}

TEST(StreamedRun, LongProgramReportsAsWhenTheMovesAreKept) {
  if (!ffmpegInstalled()) GTEST_SKIP() << "the run that keeps every move is --animate's, which needs ffmpeg";
  test::ScratchDir scratch("long-program");
  const fs::path program = scratch.path() / "long.nc";
  test::writeFile(program, straightProgram(3000));
  expectStreamedAsKept(program, {});
}

// The peak memory of `lathesim run` with its default outputs (part.png, report.html with its
// 3D view, toolpath.vtp, toolpath.csv, part.stl, stock.vdb) and of `lathesim check` against a
// drawing, measured from outside (wait4), for 2 000, 8 000 and 24 000 blocks. Held, the longer
// program's 22 000 extra moves alone take 22 000 × 272 B = 6 MB, and the run that held them
// grew 1.3 KB a block (from 100 000 to 300 000 blocks: 383 to 637 MB, with the pictures' and
// toolpath.vtp's copies of the toolpath); streamed, what grows is the spools' files, not the
// process: 3 MB allows for the noise.
TEST(StreamedRun, PeakMemoryMeasuredFromOutsideDoesNotGrowWithTheProgram) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer holds freed memory in quarantine (256 MB): the peak would measure it";
#endif
  test::ScratchDir scratch("peak-memory");
  const fs::path drawing = scratch.path() / "drawing.toml";  // a Φ41 shaft on the default bar
  test::writeFile(drawing, "[[profile]]\nx = 41\nz = 0\n[[profile]]\nx = 41\nz = -110\n");
  const auto peakMb = [&](const std::string& command, int blocks) {
    const fs::path program = scratch.path() / ("straight-" + std::to_string(blocks) + ".nc");
    if (!fs::exists(program)) test::writeFile(program, straightProgram(blocks));
    const fs::path out = scratch.path() / (command + std::to_string(blocks));
    std::vector<std::string> args{command, program.string(), "--voxel", "0.5", "--size", "400x300", "--out", out.string()};
    if (command == "check") args.insert(args.end(), {"--target", drawing.string()});
    const test::MeasuredOutcome outcome = test::runMeasured(LATHESIM_BINARY, args, scratch.path());
    // check: 3, out of tolerance, as the zig-zag leaves the part
    EXPECT_EQ(outcome.status, command == "check" ? 3 : 0) << outcome.err;
    EXPECT_TRUE(fs::exists(out / "part.png")) << command;
    EXPECT_TRUE(fs::exists(out / "toolpath.vtp")) << command;
    const std::size_t rows = nlohmann::json::parse(test::readFile(out / "report.json"))["blocks"].size();
    EXPECT_EQ(rows, static_cast<std::size_t>(blocks) + 1) << command;  // and the G00 before them
    fs::remove_all(out);
    return outcome.peakMb;
  };
  for (const std::string command : {"run", "check"}) {
    const double shortest = peakMb(command, 2000), middle = peakMb(command, 8000), longest = peakMb(command, 24000);
    EXPECT_LT(std::max(middle, longest) - shortest, 3.0)
        << command << ": peak " << shortest << " / " << middle << " / " << longest << " MB for 2 000 / 8 000 / 24 000 blocks";
  }
}

}  // namespace
}  // namespace lathesim::app
