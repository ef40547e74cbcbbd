// Custom Macro B's loops and jumps together with the program flow of M98/M99: M99 P back into
// or out of a caller's WHILE loop, M99 ending a main program inside a loop, a G65 macro
// returning by M99 P, and the step limit on endless loops that run through M98 and M99 P. The
// tool starts at X200 Z200 = (100, 200); every expected move is worked out by hand.

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;
using test::expectMoves;
using test::kRapid;
using test::messageOf;
using test::run;
using test::withMaxSteps;

TEST(MacroFlow, M99PToABlockInsideTheCallersLoopGoesOnWithTheLoop) {
  // Each pass calls O100, whose M99 P7 returns to N7 (W-1) past the G00 U2 after the call:
  // three passes, three W-1, no U2.
  const auto result = run(
      "G00 X50 Z2\n"
      "#1 = 0\n"
      "WHILE [#1 LT 3] DO 1\n"
      "#1 = #1 + 1\n"
      "M98 P100\n"
      "G00 U2\n"
      "N7 G00 W-1\n"
      "END 1\n"
      "M30\n"
      "O100\n"
      "M99 P7\n");
  ASSERT_TRUE(result.ok()) << messageOf(result);
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 25, 2, 0, 0},
                                      {kRapid, 25, 2, 25, 1, 0, 0},
                                      {kRapid, 25, 1, 25, 0, 0, 0},
                                      {kRapid, 25, 0, 25, -1, 0, 0}});
}

TEST(MacroFlow, M99POutOfTheCallersLoopLeavesIt) {
  // Pass 1: O100 moves U-2 (Φ48) and returns after the call: W-1. Pass 2 (#1 = 2): O100 jumps
  // to N30, whose M99 P20 returns to N20 outside the loop: X60. The loop is left, so the GOTO
  // back into its body reaches END 1 with no loop running: the controls' alarm, at END.
  const std::string program =
      "G00 X50 Z2\n"
      "#1 = 0\n"
      "WHILE [#1 LT 5] DO 1\n"
      "#1 = #1 + 1\n"
      "M98 P100\n"
      "N6 G00 W-1\n"
      "END 1\n"
      "N20 G00 X60\n"
      "IF [#1 EQ 2] GOTO 6\n"
      "M30\n"
      "O100\n"
      "IF [#1 EQ 2] GOTO 30\n"
      "G00 U-2\n"
      "M99\n"
      "N30 M99 P20\n";
  expectError(run(program), 7, 1, "END 1 is reached, but its loop (DO 1 of line 3) is not running");
  // Without the jump back, the run ends at M30 after the moves worked out above.
  std::string ending = program;
  ending.replace(ending.find("IF [#1 EQ 2] GOTO 6"), 19, "G00 Z5");
  const auto result = run(ending);
  ASSERT_TRUE(result.ok()) << messageOf(result);
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 25, 2, 0, 0},
                                      {kRapid, 25, 2, 24, 2, 0, 0},
                                      {kRapid, 24, 2, 24, 1, 0, 0},
                                      {kRapid, 24, 1, 30, 1, 0, 0},
                                      {kRapid, 30, 1, 30, 5, 0, 0}});
}

TEST(MacroFlow, AMacroReturningByM99PGivesBackTheCallersVariables) {
  // O9000 sees #1 = 3 (A3) and moves to X30 Z2; M99 P5 returns to N5, past the U2, where #1 is
  // the caller's 7 again: X7 (r 3.5).
  const auto result = run(
      "#1 = 7\n"
      "G65 P9000 A3\n"
      "G00 U2\n"
      "N5 G00 X#1 Z0\n"
      "M30\n"
      "O9000\n"
      "G00 X[#1*10] Z2\n"
      "M99 P5\n");
  ASSERT_TRUE(result.ok()) << messageOf(result);
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 15, 2, 0, 0}, {kRapid, 15, 2, 3.5, 0, 0, 0}});
}

TEST(MacroFlow, M99InsideAWhileLoopOfTheMainProgramEndsItOnce) {
  // The loop would run forever; M99 ends the main program (the control would start it over):
  // one pass, with the warning.
  const auto result = run("G00 X50 Z2\nWHILE [1 EQ 1] DO 1\nG00 W-1\nM99\nEND 1\n", withMaxSteps(100));
  ASSERT_TRUE(result.ok()) << messageOf(result);
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 25, 2, 0, 0}, {kRapid, 25, 2, 25, 1, 0, 0}});
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].severity, Severity::Warning);
  EXPECT_EQ(result.diagnostics[0].line, 4);
  EXPECT_NE(result.diagnostics[0].message.find("M99 ends the main program"), std::string::npos);
}

TEST(MacroFlow, ABlockRunAgainWarnsOnce) {
  // Three passes of a WHILE, and three runs of a subprogram by L3, each through a block with two
  // motion codes: one warning each, at that block.
  const std::pair<const char*, int> programs[] = {
      {"G00 X50 Z2\n#1 = 0\nWHILE [#1 LT 3] DO 1\nG00 G01 W-1 F0.1\n#1 = #1 + 1\nEND 1\nM30\n", 4},
      {"G00 X50 Z2\nM98 P100 L3\nM30\nO100\nG00 G01 W-1 F0.1\nM99\n", 5}};
  for (const auto& [program, line] : programs) {
    SCOPED_TRACE(program);
    const auto result = run(program);
    ASSERT_TRUE(result.ok()) << messageOf(result);
    EXPECT_EQ(result.toolpath.moves.size(), 4u);
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(result.diagnostics[0].line, line);
    EXPECT_EQ(result.diagnostics[0].column, 5);
    EXPECT_NE(result.diagnostics[0].message.find("G00 and G01 are both motion"), std::string::npos);
  }
}

TEST(MacroFlow, StepLimitStopsAnEndlessLoopThroughM99PAndNamesIt) {
  // N10 calls O100, whose M99 P10 returns to N10: for ever. The loop is written at the M99's P.
  for (long long limit : {10, 11, 12, 1000}) {
    SCOPED_TRACE(limit);
    expectError(run("G00 X50 Z2\nN10 G00 U0\nM98 P100\nM30\nO100\nG00 W0\nM99 P10\n", withMaxSteps(limit)), 7, 5,
                "still in this loop after");
  }
}

TEST(MacroFlow, StepLimitStopsAnEndlessLoopThroughM98AndGoto) {
  expectError(run("N10 M98 P100\nGOTO 10\nM30\nO100\nG00 U0\nM99\n", withMaxSteps(1000)), 2, 1,
              "still in this loop after 1000 blocks run again");
  // The same through a G65 macro.
  expectError(run("N10 G65 P9000 A1\nGOTO 10\nM30\nO9000\nG00 U#1\nG00 U-#1\nM99\n", withMaxSteps(1000)), 2, 1,
              "still in this loop after 1000 blocks run again");
}

}  // namespace
}  // namespace lathesim::interp
