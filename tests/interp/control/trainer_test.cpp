// School trainers' programs as they are written (Denford VR Turning, Boxford, Emco): the tool
// change M06 beside its T word in either order, M06 T01 naming tool 1 with its offset 1, the
// [BILLET line skipped as a directive (setup/ reads it as the bar), and a cut made before any
// tool is called.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;
using test::expectMoves;
using test::kFeed;
using test::kRapid;
using test::run;

using test::toolsOf;

// A Denford-style program, its moves expanded by hand. Offsets 1 and 2 are zero (the test
// options have none), so the tool's programmed point is where the words say. Radii: X32 is
// r16, X26 r13, X28 r14, X40 r20.
TEST(Trainer, DenfordProgramRunsWithItsToolChanges) {
  const std::string program =
      "[BILLET X30 Z60\n"
      "G21 G40 G99\n"
      "M06 T0101\n"
      "M03 S1500\n"
      "G00 X32 Z2\n"
      "G01 X26 F0.2\n"
      "G01 Z-20\n"
      "G00 X32\n"
      "T02 M06\n"
      "G00 X28 Z1\n"
      "G01 Z-10 F0.1\n"
      "G00 X40 Z50\n"
      "M05\n"
      "M30\n";
  const auto result = run(program);
  ASSERT_TRUE(result.ok()) << test::messageOf(result);
  expectMoves(result.toolpath.moves, {
                                         {kRapid, 100, 200, 16, 2, 0, 0},
                                         {kFeed, 16, 2, 13, 2, 0.2, 0},
                                         {kFeed, 13, 2, 13, -20, 0.2, 0},
                                         {kRapid, 13, -20, 16, -20, 0, 0},
                                         {kRapid, 16, -20, 14, 1, 0, 0},
                                         {kFeed, 14, 1, 14, -10, 0.1, 0},
                                         {kRapid, 14, -10, 20, 50, 0, 0},
                                     });
  EXPECT_EQ(toolsOf(result), (std::vector<std::pair<int, int>>{{1, 1}, {1, 1}, {1, 1}, {1, 1}, {2, 2}, {2, 2}, {2, 2}}));
  // No warning: T02 beside M06 is tool 2, not offset 2 of tool 1. The only diagnostic is the
  // note of the skipped [BILLET directive.
  EXPECT_TRUE(test::warningsOf(result).empty()) << test::warningsOf(result)[0].message;
}

TEST(Trainer, M06AndItsTWordInEitherOrderAndForm) {
  for (const std::string change : {"M06 T02", "T02 M06", "M6 T2", "M06 T0202", "T0202 M06", "m06 t02"}) {
    SCOPED_TRACE(change);
    const auto result = run("M06 T01\nG00 X40 Z2\n" + change + "\nG00 X30\n");
    ASSERT_TRUE(result.ok()) << test::messageOf(result);
    EXPECT_EQ(toolsOf(result), (std::vector<std::pair<int, int>>{{1, 1}, {2, 2}}));
    EXPECT_TRUE(test::warningsOf(result).empty());
  }
  // Without M06 a short T word stays an offset of the tool in place, with its warning.
  const auto bare = run("M06 T01\nG00 X40 Z2\nT02\nG00 X30\n");
  EXPECT_EQ(toolsOf(bare), (std::vector<std::pair<int, int>>{{1, 1}, {1, 2}}));
  ASSERT_EQ(test::warningsOf(bare).size(), 1u);
  EXPECT_EQ(test::warningsOf(bare)[0].line, 3);
}

TEST(Trainer, M06WithNoTWordIsWarnedOfAndChangesNothing) {
  const auto result = run("T0101\nG00 X40 Z2\nG00 X50 M06\nG01 Z-5 F0.1\n");
  ASSERT_TRUE(result.ok()) << test::messageOf(result);
  EXPECT_EQ(toolsOf(result), (std::vector<std::pair<int, int>>{{1, 1}, {1, 1}, {1, 1}}));
  const auto warnings = test::warningsOf(result);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].line, 3);
  EXPECT_EQ(warnings[0].column, 9);
  EXPECT_EQ(warnings[0].message,
            "M06 changes to the tool a T word in its block names, and this block has none: the tool in place stays "
            "(write M06 T0101)");
}

TEST(Trainer, M06NamesAToolTheSetupLacksAsAnyTWordDoes) {
  expectError(run("M06 T07\n"), 1, 5, "tool 7 (T07) is not defined in the setup; defined tools: 1, 2");
}

// A cut with no tool selected: no T word has named one while the setup names none mounted, or
// T0/T00 deselected it. The turret's tool is assumed, said once. Swept over the kinds of cut: a
// feed move, an arc, a thread, a cycle.
TEST(Trainer, ACutWithNoToolSelectedIsWarnedOfOnce) {
  InterpreterOptions unstated = test::defaultOptions();
  unstated.mountedToolStated = false;  // a setup that lists no tools
  for (const std::string cut : {"G01 Z-10 F0.2", "G02 X40 Z-10 R10 F0.2", "G32 Z-10 F1.5", "G90 X38 Z-10 F0.2"}) {
    for (const auto& [before, options] : {std::pair<std::string, InterpreterOptions>{"", unstated},
                                          {"T00\n", test::defaultOptions()},
                                          {"T0101\nG00 X50\nT0\n", test::defaultOptions()}}) {
      const std::string program = "M03 S500\n" + before + "G00 X40 Z2\n" + cut + "\nG01 Z-15\n";
      SCOPED_TRACE(program);
      const auto result = run(program, options);
      ASSERT_TRUE(result.ok()) << test::messageOf(result);
      const auto warnings = test::warningsOf(result);
      ASSERT_EQ(warnings.size(), 1u);
      EXPECT_EQ(warnings[0].line, 3 + static_cast<int>(std::count(before.begin(), before.end(), '\n')));
      EXPECT_EQ(warnings[0].message,
                "this block cuts with no tool selected (no T word has named one, or T0/T00 deselected it): the "
                "machine cuts with the tool its turret was left at, tool 1 assumed; call the tool first (T0101, or "
                "M06 T0101 on a trainer)");
    }
  }
  // Rapids alone cut nothing; the setup's mounted tool, or a tool called before the cut, is no slip.
  EXPECT_TRUE(test::warningsOf(run("G00 X40 Z2\nG00 X50\n", unstated)).empty());
  EXPECT_TRUE(test::warningsOf(run("G00 X40 Z2\nG01 Z-10 F0.2\n")).empty());
  EXPECT_TRUE(test::warningsOf(run("T0101\nG00 X40 Z2\nG01 Z-10 F0.2\n", unstated)).empty());
  EXPECT_TRUE(test::warningsOf(run("M06 T01\nG00 X40 Z2\nG01 Z-10 F0.2\n", unstated)).empty());
  // T01 under 2+2 is an offset of the tool in place: it selects no tool, and deselects none.
  EXPECT_EQ(test::warningsOf(run("T01\nG00 X40 Z2\nG01 Z-10 F0.2\n", unstated)).size(), 2u);
  EXPECT_EQ(test::warningsOf(run("T01\nG00 X40 Z2\nG01 Z-10 F0.2\n")).size(), 1u);
}

TEST(Trainer, ACutBeforeAnyToolCallIsAnErrorWhereTheControlSaysSo) {
  InterpreterOptions options = test::defaultOptions();
  options.control.cutWithoutTool = CutWithoutTool::Error;
  expectError(run("T00\nG00 X40 Z2\nG71 U1 R0.5\nG71 P10 Q20 U0.2 W0.1 F0.2\nN10 G00 X30\nN20 G01 Z-10\n",
                  options),
              4, 1, "this control does not cut with no tool selected (cut_without_tool = error)");
  EXPECT_TRUE(run("T0202\nG00 X40 Z2\nG01 Z-10 F0.2\n", options).ok());
  // The presets: the setup or preset names it; every preset lathesim has warns.
  for (const char* preset : {"gsk980tdi", "fanuc-0i-t", "haas"})
    EXPECT_EQ(controlPreset(preset)->parameters.cutWithoutTool, CutWithoutTool::Warning) << preset;
}

}  // namespace
}  // namespace lathesim::interp
