// A run whose outputs need no move afterwards streams the moves from the interpreter into the
// simulation (app/run_pipeline.hpp): it must report exactly what the run that keeps them
// reports, and its peak memory must not grow with the program's length.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

// `lathesim run` of `program` at 0.4 mm voxels writing `outputs`: toolpath.vtp makes it keep
// every move, csv alone lets them stream.
RunFiles run(const fs::path& program, const std::vector<std::string>& setup, const std::string& outputs,
             const test::ScratchDir& scratch) {
  const fs::path out = scratch.path() / outputs;
  std::vector<std::string> args{"run", program.string(), "--voxel", "0.4", "--outputs", outputs, "--out", out.string()};
  args.insert(args.end(), setup.begin(), setup.end());
  const test::ProcessOutcome outcome = test::runProcess(LATHESIM_BINARY, args, scratch.path());
  EXPECT_EQ(outcome.status, 0) << outcome.err;
  return {reportOf(out), test::readFile(out / "toolpath.csv")};
}

void expectStreamedAsKept(const fs::path& program, const std::vector<std::string>& setup) {
  test::ScratchDir scratch("streamed");
  const RunFiles kept = run(program, setup, "report,csv,vtp", scratch);
  const RunFiles streamed = run(program, setup, "report,csv", scratch);
  expectSameReport(streamed.report, kept.report, program.string());
  EXPECT_EQ(streamed.csv, kept.csv) << program;
  EXPECT_FALSE(streamed.report["blocks"].empty()) << program;
}

// Parts that use what the simulation reads beside the moves: cycle starts, threads, a part-off
// and a parts catcher, work shifts, subprograms, nose radius compensation, dog-leg rapids.
TEST(StreamedRun, BundledPartsReportAsWhenTheMovesAreKept) {
  for (const char* part : {"g92-two-start", "g76-m30x2", "m98-grooves", "shop-pin-partoff-g75", "tube-bore-partoff",
                           "g50-shift-twice", "g71-g70-shaft", "nose-comp-g42", "dogleg-groove-retract", "shop-g55-safety"}) {
    const fs::path dir = fs::path(LATHESIM_PARTS_DIR) / part;
    expectStreamedAsKept(dir / "program.nc", {"--setup", (dir / "setup.toml").string()});
  }
}

TEST(StreamedRun, LongProgramReportsAsWhenTheMovesAreKept) {
  test::ScratchDir scratch("long-program");
  const fs::path program = scratch.path() / "long.nc";
  test::writeFile(program, straightProgram(3000));
  expectStreamedAsKept(program, {});
}

// The moves alone of the longer program's extra blocks take 40 000 × 272 B = 11 MB when held:
// the runs that held them peaked 12.3 MB higher for 50 000 blocks than for 10 000 (and then
// built the report's rows as a JSON tree, after the peak is noted, 0.4 KB a block more).
TEST(StreamedRun, PeakMemoryDoesNotGrowWithTheProgram) {
  test::ScratchDir scratch("peak-memory");
  const auto peakMb = [&](int blocks) {
    const fs::path program = scratch.path() / ("straight-" + std::to_string(blocks) + ".nc");
    test::writeFile(program, straightProgram(blocks));
    const fs::path out = scratch.path() / std::to_string(blocks);
    const test::ProcessOutcome outcome = test::runProcess(
        LATHESIM_BINARY, {"run", program.string(), "--voxel", "0.5", "--outputs", "report", "--out", out.string()},
        scratch.path());
    EXPECT_EQ(outcome.status, 0) << outcome.err;
    return nlohmann::json::parse(test::readFile(out / "report.json"))["peak_memory_mb"].get<double>();
  };
  const double shorter = peakMb(10000), longer = peakMb(50000);
  EXPECT_LT(longer - shorter, 4.0) << "peak " << shorter << " MB for 10 000 blocks, " << longer << " MB for 50 000";
}

}  // namespace
}  // namespace lathesim::app
