// Custom Macro B in whole programs: expressions evaluated each time a block runs, WHILE and
// GOTO, G65 with its arguments and local variable levels, <vacant> addresses, #3000/#3006,
// the loop-structure errors and the step limit. Positions are (radius, Z); the tool starts at
// X200 Z200 = (100, 200). Every expected move is worked out by hand from the program.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;
using test::expectMoves;
using test::kFeed;
using test::kRapid;
using test::messageOf;
using test::run;
using test::withMaxSteps;

TEST(MacroProgram, WhileLoopRunsItsBlocksWithTheVariablesOfEachPass) {
  // Three grooves: plunge to X32, out to X44, W-10, counted by #1.
  const auto result = run(
      "G00 X44 Z-10\n"
      "#1 = 0\n"
      "WHILE [#1 LT 3] DO 1\n"
      "G01 X32 F0.05\n"
      "G00 X44\n"
      "W-10\n"
      "#1 = #1 + 1\n"
      "END 1\n"
      "M30\n");
  ASSERT_TRUE(result.ok()) << messageOf(result);
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 22, -10, 0, 0},
                                      {kFeed, 22, -10, 16, -10, 0.05, 0},
                                      {kRapid, 16, -10, 22, -10, 0, 0},
                                      {kRapid, 22, -10, 22, -20, 0, 0},
                                      {kFeed, 22, -20, 16, -20, 0.05, 0},
                                      {kRapid, 16, -20, 22, -20, 0, 0},
                                      {kRapid, 22, -20, 22, -30, 0, 0},
                                      {kFeed, 22, -30, 16, -30, 0.05, 0},
                                      {kRapid, 16, -30, 22, -30, 0, 0},
                                      {kRapid, 22, -30, 22, -40, 0, 0}});
  EXPECT_EQ(result.toolpath.moves[4].line, 4);  // the loop's moves carry their own lines
}

TEST(MacroProgram, ExpressionsInAddressesAreEvaluatedEachTimeTheBlockRuns) {
  // Pass #1 = 1, 2, 3: X40-2#1 (Φ38, 36, 34 → radius 19, 18, 17), Z-5#1.
  const auto result = run(
      "G00 X40 Z2\n"
      "#1 = 1\n"
      "WHILE [#1 LE 3] DO 1\n"
      "G01 X[40-2*#1] Z-[5*#1] F#9\n"
      "#1 = #1 + 1\n"
      "END 1\n"
      "M30\n");
  ASSERT_FALSE(result.ok());  // F#9 is vacant: F is left out and no feed was ever set
  expectError(result, 4, 1, "feed rate F is not set");
  EXPECT_NE(messageOf(result).find("F#9 at column 25 was left out: #9 is vacant"), std::string::npos)
      << messageOf(result);

  const auto fed = run(
      "G00 X40 Z2\n"
      "#9 = 0.2\n"
      "#1 = 1\n"
      "WHILE [#1 LE 3] DO 1\n"
      "G01 X[40-2*#1] Z-[5*#1] F#9\n"
      "#1 = #1 + 1\n"
      "END 1\n"
      "M30\n");
  ASSERT_TRUE(fed.ok()) << messageOf(fed);
  expectMoves(fed.toolpath.moves, {{kRapid, 100, 200, 20, 2, 0, 0},
                                   {kFeed, 20, 2, 19, -5, 0.2, 0},
                                   {kFeed, 19, -5, 18, -10, 0.2, 0},
                                   {kFeed, 18, -10, 17, -15, 0.2, 0}});
}

TEST(MacroProgram, AddressValuesAreRoundedToTheLeastIncrement) {
  // X#1 = X12.34567 → X12.346 (radius 6.173); Z[#1/2] = 6.172835 → Z6.173.
  // X[#2+#2] = 2.00666 → X2.007; ROUND in an address rounds to 0.001: Z[ROUND[#2]+ROUND[#2]]
  // = 1.003 + 1.003 = 2.006 (the Fanuc and Haas manuals' example).
  const auto result = run(
      "#1 = 12.34567\n"
      "G00 X#1 Z[#1/2]\n"
      "#2 = 1.00333\n"
      "G00 X[#2+#2] Z[ROUND[#2]+ROUND[#2]]\n"
      "#3 = 1000.5\n"
      "#4 = 3.5\n"
      "M#4 S#3\n"
      "G00 X10\n"
      "M30\n");
  ASSERT_TRUE(result.ok()) << messageOf(result);
  const auto& moves = result.toolpath.moves;
  ASSERT_EQ(moves.size(), 3u);
  EXPECT_NEAR(moves[0].to.x(), 6.173, 1e-12);
  EXPECT_NEAR(moves[0].to.y(), 6.173, 1e-12);
  EXPECT_NEAR(moves[1].to.x(), 1.0035, 1e-12);
  EXPECT_NEAR(moves[1].to.y(), 2.006, 1e-12);
  // M#4 with 3.5 is M04 (half away from zero): the spindle turns; S[1000.5] is S1001.
  EXPECT_TRUE(moves[2].spindleOn);
  EXPECT_DOUBLE_EQ(moves[2].spindleS, 1001.0);
}

TEST(MacroProgram, GCodesFromVariablesAreNotRounded) {
  const auto result = run("#1 = 1\nG#1 X50 Z2 F0.2\n#1 = 1.5\nG#1 X40\n");
  expectError(result, 4, 1, "unknown G code G1.5");
}

TEST(MacroProgram, NegatedVariableAndBracketsInAddresses) {
  // X#[#2-2] is X#1 = X7 (radius 3.5); Z-#2 is Z-3; U-[#1-5] is U-2.
  const auto good = run("#1 = 7\n#2 = 3\nG00 X#[#2-2] Z-#2\nU-[#1-5]\nM30\n");
  ASSERT_TRUE(good.ok()) << messageOf(good);
  expectMoves(good.toolpath.moves, {{kRapid, 100, 200, 3.5, -3, 0, 0}, {kRapid, 3.5, -3, 2.5, -3, 0, 0}});
}

TEST(MacroProgram, VacantAddressIsLeftOutWithAWarning) {
  const auto result = run("G00 X#1 Z5\nM30\n");
  ASSERT_TRUE(result.ok()) << messageOf(result);
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 100, 5, 0, 0}});
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].severity, Severity::Warning);
  EXPECT_EQ(result.diagnostics[0].line, 1);
  EXPECT_EQ(result.diagnostics[0].column, 5);
  EXPECT_NE(result.diagnostics[0].message.find("X#1: #1 is vacant, so X is left out"), std::string::npos);
}

TEST(MacroProgram, VacantAddressWhereAValueIsNeededIsAnError) {
  expectError(run("G00 X50 Z2\nG90 X#1 Z-20 F0.2\n"), 2, 1, "(X#1 at column 5 was left out: #1 is vacant)");
  expectError(run("G65 P#5\n"), 1, 1, "G65 needs P");
  expectError(run("#1 = #[#7]\n"), 1, 6, "variable number #[…] is vacant");
  expectError(run("GOTO #9\nN1 M30\n"), 1, 6, "GOTO's sequence number is vacant");
}

TEST(MacroProgram, GotoForwardBackwardAndToAnExpression) {
  // N10 runs twice: once from the top, once from GOTO 10; GOTO #5 (= 30) skips N20.
  const auto result = run(
      "#1 = 0\n"
      "N10 G00 U-2\n"
      "#1 = #1 + 1\n"
      "IF [#1 LT 2] GOTO 10\n"
      "#5 = 30\n"
      "GOTO #5\n"
      "N20 G00 W-50\n"
      "N30 IF [#1 EQ 2] THEN #2 = 4\n"
      "G00 W-#2\n"
      "M30\n");
  ASSERT_TRUE(result.ok()) << messageOf(result);
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 99, 200, 0, 0},
                                      {kRapid, 99, 200, 98, 200, 0, 0},
                                      {kRapid, 98, 200, 98, 196, 0, 0}});
}

TEST(MacroProgram, GotoToAMissingNumberIsAnError) {
  expectError(run("G00 X50\nGOTO 30\nN20 M30\n"), 2, 6, "GOTO 30: there is no block N30 in this program");
  expectError(run("GOTO 0\n"), 1, 6, "sequence numbers run from 1 to 99999");
  expectError(run("N10 G00 X50\nGOTO 10\nN10 G00 X60\n"), 2, 6, "this program has N10 twice (lines 1 and 3)");
}

TEST(MacroProgram, NestedLoopsAndAGotoOutOfALoop) {
  // DO 2 inside DO 1: 2 × 2 moves of U-1; then a loop left by GOTO after its first pass.
  const auto result = run(
      "#1 = 0\n"
      "WHILE [#1 LT 2] DO 1\n"
      "#2 = 0\n"
      "WHILE [#2 LT 2] DO 2\n"
      "G00 U-2\n"
      "#2 = #2 + 1\n"
      "END 2\n"
      "#1 = #1 + 1\n"
      "END 1\n"
      "WHILE [#1 LT 100] DO 1\n"
      "G00 W-1\n"
      "GOTO 50\n"
      "END 1\n"
      "N50 WHILE [#1 LT 3] DO 1\n"  // the same number again, after the first DO 1 ended
      "G00 W-1\n"
      "#1 = #1 + 1\n"
      "END 1\n"
      "M30\n");
  ASSERT_TRUE(result.ok()) << messageOf(result);
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 99, 200, 0, 0},
                                      {kRapid, 99, 200, 98, 200, 0, 0},
                                      {kRapid, 98, 200, 97, 200, 0, 0},
                                      {kRapid, 97, 200, 96, 200, 0, 0},
                                      {kRapid, 96, 200, 96, 199, 0, 0},
                                      {kRapid, 96, 199, 96, 198, 0, 0}});
}

TEST(MacroProgram, LoopStructureErrors) {
  expectError(run("#1 = 0\nWHILE [#1 LT 3] DO 1\n#1 = #1 + 1\nM30\n"), 2, 1, "DO 1 has no END 1");
  expectError(run("G00 X50\nEND 1\n"), 2, 1, "END 1 has no DO 1 open before it");
  expectError(run("WHILE [1 EQ 1] DO 1\nWHILE [1 EQ 1] DO 2\nEND 1\nEND 2\n"), 3, 1,
              "loops may nest but not cross");
  expectError(run("WHILE [1 EQ 1] DO 1\nWHILE [1 EQ 1] DO 1\nEND 1\nEND 1\n"), 2, 19,
              "nested loops need different numbers");
  expectError(run("WHILE [1 EQ 1] DO 4\nEND 4\n"), 1, 19, "loop numbers are 1, 2 and 3");
  // GOTO into a loop: its END is reached with its WHILE never run.
  expectError(run("GOTO 20\nWHILE [1 EQ 1] DO 1\nN20 G00 U-1\nEND 1\nM30\n"), 4, 1,
              "a GOTO may jump out of a loop, not into one");
}

TEST(MacroProgram, StepLimitNamesTheEndlessLoop) {
  expectError(run("#1 = 0\nWHILE [#1 GE 0] DO 1\n#1 = #1 + 1\nEND 1\nM30\n", withMaxSteps(1000)), 2, 1,
              "still in this loop after 1000 blocks run again");
  expectError(run("N10 #1 = #1 + 1\nG00 U0\nIF [#1 GT -1] GOTO 10\nM30\n", withMaxSteps(1000)), 3, 15,
              "still in this loop");
  // DO without WHILE is Fanuc's endless loop.
  expectError(run("G00 X50\nDO 2\nG00 W0\nEND 2\n", withMaxSteps(500)), 2, 1, "still in this loop");
}

TEST(MacroProgram, StepLimitBlamesTheOuterEndlessLoopNotTheInnerFiniteOne) {
  const std::string outerEndless =
      "#2 = 0\n"
      "WHILE [#2 GE 0] DO 1\n"
      "#1 = 0\n"
      "WHILE [#1 LT 5] DO 2\n"
      "#1 = #1 + 1\n"
      "END 2\n"
      "END 1\n";
  const std::string innerEndless =
      "#2 = 0\n"
      "WHILE [#2 LT 3] DO 1\n"
      "WHILE [#2 GE 0] DO 2\n"
      "#1 = 1\n"
      "END 2\n"
      "#2 = #2 + 1\n"
      "END 1\n";
  // Whatever block the limit falls on, the same loop is named.
  for (long long limit : {100, 101, 102, 103, 104, 105, 1000}) {
    SCOPED_TRACE(limit);
    expectError(run(outerEndless, withMaxSteps(limit)), 2, 1, "still in this loop");
    expectError(run(innerEndless, withMaxSteps(limit)), 3, 1, "still in this loop");
  }
}

TEST(MacroProgram, StepLimitNamesARepeatedCall) {
  // O1000 runs 9999 times, each run a loop of 3 passes: far over 2000 blocks; the call is
  // the loop that spans the most.
  const auto result = run(
      "G00 X50 Z2\n"
      "M98 P1000 L9999\n"
      "M30\n"
      "O1000\n"
      "#1 = 0\n"
      "WHILE [#1 LT 3] DO 1\n"
      "#1 = #1 + 1\n"
      "END 1\n"
      "M99\n",
      withMaxSteps(2000));
  expectError(result, 2, 5, "still in this loop after 2000 blocks run again");
}

TEST(MacroProgram, StepLimitCountsOnlyBlocksRunAgain) {
  // Five blocks run once each: far under any limit, even 1.
  EXPECT_TRUE(run("G00 X50\nG00 Z5\nG00 X60\nG00 Z6\nM30\n", withMaxSteps(1)).ok());
  // The second call runs O1000's four blocks again: the fourth of them (M99) passes 3. No
  // loop jumps back, so the block where the limit falls is named.
  expectError(run("M98 P1000\nM98 P1000\nM98 P1000\nM30\nO1000\nG00 U-1\nG00 U1\nM99\n", withMaxSteps(3)), 8, 1,
              "the program has reached 3 blocks run again");
}

TEST(MacroProgram, MacroCallArgumentSpecificationI) {
  // Every letter's value is its variable's number: the macro checks #1–#26 by itself and
  // raises an alarm on the first mismatch; #10 #12 #14 #15 #16 have no letter and stay vacant.
  const auto result = run(
      "G65 P9000 A1 B2 C3 I4 J5 K6 D7 E8 F9 H11 M13 Q17 R18 S19 T20 U21 V22 W23 X24 Y25 Z26\n"
      "M30\n"
      "O9000\n"
      "#30 = 1\n"
      "#31 = 0\n"
      "WHILE [#30 LE 26] DO 1\n"
      "IF [#[#30] EQ #0] GOTO 10\n"
      "IF [#[#30] NE #30] THEN #3000 = 1 (WRONG ARGUMENT)\n"
      "#31 = #31 + 1\n"
      "N10 #30 = #30 + 1\n"
      "END 1\n"
      "IF [#31 NE 21] THEN #3000 = 2 (WRONG COUNT)\n"
      "M99\n");
  EXPECT_TRUE(result.ok()) << messageOf(result);
}

TEST(MacroProgram, MacroCallArgumentSpecificationIIAndTheLaterWordWins) {
  // I J K sets: A1 I4 J5 K6 I7 J8 K9 I10 J11 → #1, #4–#11. Then the Fanuc manual's example:
  // G65 A1.0 B2.0 I-3.0 I4.0 D5.0 → #1 1, #2 2, #3 vacant, #4 -3, #7 5 (D after I4.0).
  const auto result = run(
      "G65 P9001 A1 I4 J5 K6 I7 J8 K9 I10 J11\n"
      "G65 A1.0 B2.0 I-3.0 I4.0 D5.0 P9002\n"
      "M30\n"
      "O9001\n"
      "#20 = 4\n"
      "WHILE [#20 LE 11] DO 1\n"
      "IF [#[#20] NE #20] THEN #3000 = 1 (TYPE II)\n"
      "#20 = #20 + 1\n"
      "END 1\n"
      "IF [#1 NE 1] THEN #3000 = 2 (A)\n"
      "IF [#12 NE #0] THEN #3000 = 3 (12 SET)\n"
      "M99\n"
      "O9002\n"
      "IF [#1 NE 1] THEN #3000 = 4 (A)\n"
      "IF [#2 NE 2] THEN #3000 = 5 (B)\n"
      "IF [#3 NE #0] THEN #3000 = 6 (C)\n"
      "IF [#4 NE -3] THEN #3000 = 7 (I)\n"
      "IF [#5 NE #0] THEN #3000 = 8 (J)\n"
      "IF [#7 NE 5] THEN #3000 = 9 (D LATER)\n"
      "M99\n");
  EXPECT_TRUE(result.ok()) << messageOf(result);
}

TEST(MacroProgram, EachMacroCallHasItsOwnLocalVariablesAndM98SharesThem) {
  const auto result = run(
      "#1 = 5\n"
      "G65 P9100\n"
      "IF [#1 NE 5] THEN #3000 = 1 (MAIN LOCAL CHANGED)\n"
      "M98 P9200\n"
      "IF [#1 NE 7] THEN #3000 = 2 (M98 DOES NOT SHARE)\n"
      "#100 = 0\n"
      "G65 P9300\n"
      "IF [#100 NE 8] THEN #3000 = 3 (COMMON NOT SHARED)\n"
      "M30\n"
      "O9100\n"
      "IF [#1 NE #0] THEN #3000 = 4 (NEW LEVEL NOT VACANT)\n"
      "#1 = 9\n"
      "M99\n"
      "O9200\n"
      "#1 = 7\n"
      "M99\n"
      "O9300\n"
      "#100 = 8\n"
      "M99\n");
  EXPECT_TRUE(result.ok()) << messageOf(result);
}

TEST(MacroProgram, MacroMayCallItselfFourLevelsDeep) {
  const std::string macro =
      "M30\n"
      "O9300\n"              // line 4
      "IF [#1 LE 0] GOTO 99\n"
      "G01 U-2 F0.1\n"
      "G65 P9300 A[#1-1]\n"  // line 7
      "N99 M99\n";
  const auto result = run("G00 X40 Z2\nG65 P9300 A3\n" + macro);
  ASSERT_TRUE(result.ok()) << messageOf(result);
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 2, 0, 0},
                                      {kFeed, 20, 2, 19, 2, 0.1, 0},
                                      {kFeed, 19, 2, 18, 2, 0.1, 0},
                                      {kFeed, 18, 2, 17, 2, 0.1, 0}});
  // A4 needs a fifth level.
  expectError(run("G00 X40 Z2\nG65 P9300 A4\n" + macro), 7, 5, "nests at most 4");
}

TEST(MacroProgram, MacroCallRepeatsWithL) {
  const auto result = run("G00 X40 Z2\nG65 P9400 L3 A-2\nM30\nO9400\nG01 U#1 F0.1\nM99\n");
  ASSERT_TRUE(result.ok()) << messageOf(result);
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 2, 0, 0},
                                      {kFeed, 20, 2, 19, 2, 0.1, 0},
                                      {kFeed, 19, 2, 18, 2, 0.1, 0},
                                      {kFeed, 18, 2, 17, 2, 0.1, 0}});
}

TEST(MacroProgram, MacroKeptInItsOwnFileIsCalledAndItsErrorsNameTheFile) {
  const std::filesystem::path directory = std::filesystem::temp_directory_path() / "lathesim_macro_library_test";
  std::filesystem::create_directories(directory);
  std::ofstream(directory / "O9500.nc") << "O9500\nG01 U#1 F0.1\nIF [#1 LT -5] THEN #3000 = 1 (TOO DEEP)\nM99\n";
  InterpreterOptions options = test::defaultOptions();
  options.programDirectories = {directory};
  const auto result = run("G00 X40 Z2\nG65 P9500 A-2\nM30\n", options);
  ASSERT_TRUE(result.ok()) << messageOf(result);
  // The move made in the macro's file carries the line of the call (2).
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 2, 0, 0}, {kFeed, 20, 2, 19, 2, 0.1, 0}});
  EXPECT_EQ(result.toolpath.moves[1].line, 2);
  const auto alarm = run("G00 X40 Z2\nG65 P9500 A-6\nM30\n", options);
  expectError(alarm, 3, 20, "the program raises alarm 3001 with #3000 = 1: TOO DEEP");
  EXPECT_EQ(alarm.diagnostics[0].file, (directory / "O9500.nc").string());
  std::filesystem::remove_all(directory);
}

TEST(MacroProgram, MacroCallErrors) {
  expectError(run("G65 P9999\n"), 1, 5, "G65 calls O9999, which is neither in this program nor in a file");
  expectError(run("G65 P1000 A1 A2\n"), 1, 14, "A is given twice");
  expectError(run("G65 G00 P1000\n"), 1, 5, "a macro call takes only P, L and arguments");
  expectError(run("G65 P1000 L0\n"), 1, 11, "L0 is not a repeat count");
}

TEST(MacroProgram, AlarmAndStopMessages) {
  expectError(run("G00 X50\n#1 = 12\nIF [#1 GT 10] THEN #3000 = 1 (TOO BIG)\nM30\n"), 3, 20,
              "the program raises alarm 3001 with #3000 = 1: TOO BIG");
  // A stop is a note, listed once however often the block runs; the run goes on.
  const auto stopped = run("G00 X50\n#3006 = 1 (MEASURE THE PART)\nG00 Z5\nM98 P1000 L2\nM30\nO1000\n#3006 = 2\nM99\n");
  ASSERT_TRUE(stopped.ok()) << messageOf(stopped);
  EXPECT_EQ(stopped.toolpath.moves.size(), 2u);
  ASSERT_EQ(stopped.diagnostics.size(), 2u);
  EXPECT_EQ(stopped.diagnostics[0].severity, Severity::Note);
  EXPECT_EQ(stopped.diagnostics[1].line, 7);
  EXPECT_NE(stopped.diagnostics[1].message.find("(#3006 = 2): no message given"), std::string::npos);
  EXPECT_EQ(stopped.diagnostics[0].line, 2);
  EXPECT_NE(stopped.diagnostics[0].message.find("program stop (#3006 = 1): MEASURE THE PART"), std::string::npos);
}

TEST(MacroProgram, StatementsAndWordsDoNotShareABlock) {
  expectError(run("G00 X50 #1 = 2\n"), 1, 9, "a macro statement after NC words");
  expectError(run("#1 = 2 G00 X50\n"), 1, 8, "after a macro statement");
  expectError(run("N#1 G00 X50\n"), 1, 1, "N takes no variable");
  expectError(run("G00 X#1+2\n"), 1, 8, "an expression in an address is written in brackets");
  expectError(run("#1\n"), 1, 3, "expected '=' and a value");
}

TEST(MacroProgram, BlockDeleteSkipsMacroStatements) {
  const auto result = run("#1 = 1\n/#1 = 2\nG00 X[10*#1]\nM30\n");
  ASSERT_TRUE(result.ok()) << messageOf(result);
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 5, 200, 0, 0}});
}

TEST(MacroProgram, ContourWrittenWithVariablesMatchesTheSameContourInNumbers) {
  const std::string numbers =
      "G00 X52 Z2\nG71 U2 R0.5\nG71 P10 Q20 U0.5 W0.1 F0.2\n"
      "N10 G00 X30\nG01 Z-20\nX40 Z-30\nN20 X52\nG70 P10 Q20\nM30\n";
  const std::string variables =
      "#1 = 30\n#2 = 10\nG00 X52 Z2\nG71 U2 R0.5\nG71 P10 Q20 U0.5 W0.1 F0.2\n"
      "N10 G00 X#1\nG01 Z-[2*#2]\nX[#1+#2] Z-[3*#2]\nN20 X52\nG70 P10 Q20\nM30\n";
  const auto expected = run(numbers);
  const auto actual = run(variables);
  ASSERT_TRUE(expected.ok()) << messageOf(expected);
  ASSERT_TRUE(actual.ok()) << messageOf(actual);
  ASSERT_EQ(actual.toolpath.moves.size(), expected.toolpath.moves.size());
  for (std::size_t i = 0; i < expected.toolpath.moves.size(); ++i) {
    EXPECT_EQ(actual.toolpath.moves[i].from, expected.toolpath.moves[i].from) << i;
    EXPECT_EQ(actual.toolpath.moves[i].to, expected.toolpath.moves[i].to) << i;
    EXPECT_EQ(actual.toolpath.moves[i].line, expected.toolpath.moves[i].line + 2) << i;
  }
  expectError(run("G00 X52 Z2\nG71 U2 R0.5\nG71 P10 Q20 U0.5 W0.1 F0.2\nN10 G00 X30\n#1 = 2\nN20 X52\n"), 5, 1,
              "a macro statement is not allowed in the contour of G71");
}

}  // namespace
}  // namespace lathesim::interp
