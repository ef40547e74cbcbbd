// Bad input given to `lathesim run` and `lathesim check`: a malformed number, a cycle's alarm,
// an error at the end of a long streamed program, an unknown setup key, a grid too fine for
// memory, a line --at-line cannot stop at, a drawing or STL that is not one. Each exits 1 (2
// for a command line short of what it needs), says where and what, and writes nothing. No
// test here simulates a whole part, so these run under the sanitizers within CI's time
// (scripts/sanitize.sh ci).

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "interp/text/text_lines.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::app {
namespace {

namespace fs = std::filesystem;
using interp::linesOf;
using test::ProcessOutcome;
using test::lathesim;
using test::ScratchDir;
using test::writeFile;

using test::kPartsDir;

using test::partFile;

using test::noOutputs;

TEST(BadInput, MalformedNumberIsReportedWithItsLocationAndCaretAndWritesNothing) {
  ScratchDir dir("bad");
  const fs::path program = dir.path() / "bad.nc";
  writeFile(program, "G00 X60 Z5;\nG00 X20.3. Z5;\n");
  const fs::path out = dir.path() / "out";
  const ProcessOutcome outcome = lathesim({"run", program.string(), "--out", out.string(), "--voxel", "0.5"}, dir.path());
  EXPECT_EQ(outcome.status, 1);
  const auto lines = linesOf(outcome.err);
  ASSERT_GE(lines.size(), 3u) << outcome.err;
  EXPECT_EQ(lines[0], program.string() +
                         ":2:5: error: malformed number in X20.3.: expected an optional sign, then digits with "
                         "at most one decimal point");
  EXPECT_EQ(lines[1], "G00 X20.3. Z5;");
  EXPECT_EQ(lines[2], "    ^");  // under the X at column 5
  EXPECT_TRUE(noOutputs(out));
}

// The O0006 part (parts/seed004-o0006): with W = +3 alarms at N40's R word.
TEST(BadInput, O0006AlarmsAtN40AndWritesNothing) {
  ScratchDir dir("o0006");
  const std::string program = partFile("seed004-o0006", "program.nc");
  const fs::path out = dir.path() / "out";
  const ProcessOutcome outcome = lathesim(
      {"run", program, "--setup", partFile("seed004-o0006", "setup.toml"), "--out", out.string(), "--voxel", "0.5"},
      dir.path());
  EXPECT_EQ(outcome.status, 1);
  const auto lines = linesOf(outcome.err);
  ASSERT_GE(lines.size(), 3u) << outcome.err;
  EXPECT_EQ(lines[0].rfind(program + ":5:21: error: R-5.5 and W3 have opposite signs and |R| > |W|", 0), 0u)
      << lines[0];
  EXPECT_EQ(lines[1], "N40 G94 X20 .0 Z5.0 R-5 .5 F100;");
  EXPECT_EQ(lines[2], std::string(20, ' ') + "^");
  EXPECT_TRUE(noOutputs(out));
}

TEST(BadInput, UnknownSetupKeyIsNamedAndWritesNothing) {
  ScratchDir dir("setup");
  const fs::path setup = dir.path() / "setup.toml";
  writeFile(setup, "[stock]\ndiameter = 50\nlength = 60\nface_z = 0\ncolour = \"red\"\n");
  const fs::path out = dir.path() / "out";
  const ProcessOutcome outcome = lathesim({"run", partFile("seed001-taper-r24", "program.nc"), "--setup", setup.string(),
                                           "--out", out.string(), "--voxel", "0.5"},
                                          dir.path());
  EXPECT_EQ(outcome.status, 1);
  EXPECT_NE(outcome.err.find("unknown key 'stock.colour'"), std::string::npos) << outcome.err;
  EXPECT_EQ(outcome.err.rfind(setup.string() + ":5:", 0), 0u) << outcome.err;
  EXPECT_TRUE(noOutputs(out));
}

TEST(BadInput, VoxelTooFineForMemoryIsRefusedAndWritesNothing) {
  ScratchDir dir("voxel");
  const fs::path out = dir.path() / "out";
  // No --setup: the default Φ125 × 112 bar, which at 1 µm would need terabytes.
  const ProcessOutcome outcome =
      lathesim({"run", partFile("seed000-face-taper", "program.nc"), "--out", out.string(), "--voxel", "0.001"}, dir.path());
  EXPECT_EQ(outcome.status, 1);
  EXPECT_NE(outcome.err.find("lathesim: error: a 0.001 mm voxel needs about"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("GiB"), std::string::npos) << outcome.err;
  EXPECT_TRUE(noOutputs(out));
}

// parts/seed000-face-taper's program has 10 lines, the last an M30.
TEST(BadInput, AtLineThatDoesNotExistOrMakesNoMoveIsNamedAndWritesNothing) {
  ScratchDir dir("at-line-bad");
  const fs::path out = dir.path() / "out";
  const auto atLine = [&](const std::string& line) {
    return lathesim({"run", partFile("seed000-face-taper", "program.nc"), "--setup", partFile("seed000-face-taper", "setup.toml"),
                     "--out", out.string(), "--voxel", "0.5", "--at-line", line},
                    dir.path());
  };
  ProcessOutcome outcome = atLine("11");
  EXPECT_EQ(outcome.status, 1);
  EXPECT_NE(outcome.err.find("--at-line 11: the program has no line 11 (it has lines 1 to 10)"), std::string::npos)
      << outcome.err;
  EXPECT_TRUE(noOutputs(out));
  outcome = atLine("10");
  EXPECT_EQ(outcome.status, 1);
  EXPECT_NE(outcome.err.find("--at-line 10: line 10 makes no move"), std::string::npos) << outcome.err;
  EXPECT_TRUE(noOutputs(out));
}

// A run that needs no move afterwards streams them from the interpreter into the simulation
// (app/run_pipeline.hpp): an error at the last of 2,000 blocks comes after the moves before it
// were simulated and spooled, and nothing of them is written.
TEST(BadInput, AnErrorAtTheLastBlockOfAStreamedRunLeavesNoOutput) {
  ScratchDir dir("late-error");
  const fs::path program = dir.path() / "late-error.nc";
  std::string text = "G99 M03 S800\nG00 X40 Z2\n";
  for (int i = 0; i < 2000; ++i) text += "G01 X" + std::to_string(i % 2 ? 40 : 42) + " Z-" + std::to_string(i % 50) + " F0.1\n";
  text += "G00 Z10 B-200.\nM30\n";
  writeFile(program, text);
  const fs::path out = dir.path() / "out" / "run";
  const ProcessOutcome outcome =
      lathesim({"run", program.string(), "--voxel", "0.5", "--outputs", "report,csv,stl", "--out", out.string()}, dir.path());
  EXPECT_EQ(outcome.status, 1);
  EXPECT_NE(outcome.err.find("late-error.nc:2003:9: error: B-200.: this lathe has no B axis"), std::string::npos)
      << outcome.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

/// `lathesim check` of seed 001's R-24 program at 0.25 mm with `extra` arguments, into dir/out.
ProcessOutcome checkSeed001(const ScratchDir& dir, const std::vector<std::string>& extra) {
  std::vector<std::string> args{"check",   partFile("seed001-taper-r24", "program.nc"),
                                "--setup", partFile("seed001-taper-r24", "setup.toml"),
                                "--voxel", "0.25",
                                "--out",   (dir.path() / "out").string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return lathesim(args, dir.path());
}

TEST(BadInput, CheckAgainstAnStlThatIsNotOneIsAnError) {
  ScratchDir dir("check-bad-stl");
  writeFile(dir.path() / "design.stl", "this is not an STL");
  const ProcessOutcome outcome = checkSeed001(dir, {"--target", (dir.path() / "design.stl").string()});
  EXPECT_EQ(outcome.status, 1);
  EXPECT_NE(outcome.err.find("design.stl: error: not an STL file with triangles"), std::string::npos) << outcome.err;
  EXPECT_TRUE(noOutputs(dir.path() / "out"));
}

TEST(BadInput, CheckAgainstABadDrawingIsAnErrorWithItsLine) {
  ScratchDir dir("check-bad");
  writeFile(dir.path() / "drawing.toml", "[[profile]]\nx = 30\nz = 0\n[[profile]]\nx = 50\nzz = -20\n");
  const ProcessOutcome outcome = checkSeed001(dir, {"--target", (dir.path() / "drawing.toml").string()});
  EXPECT_EQ(outcome.status, 1);
  EXPECT_NE(outcome.err.find("drawing.toml:6:1: error: unknown profile key 'zz'"), std::string::npos) << outcome.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(BadInput, CheckWithoutATargetIsABadCommandLine) {
  ScratchDir dir("check-none");
  const ProcessOutcome outcome = checkSeed001(dir, {});
  EXPECT_EQ(outcome.status, 2);
  EXPECT_NE(outcome.err.find("--target"), std::string::npos) << outcome.err;
}

}  // namespace
}  // namespace lathesim::app
