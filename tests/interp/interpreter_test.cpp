// The interpreter end to end: every expected move is worked out by hand from the spec.
// Positions are (radius, Z): X130 is radius 65. The tool starts at X200 Z200 = (100, 200).

#include "interp/interpreter.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;
using test::expectMoves;
using test::kFeed;
using test::kRapid;
using test::run;

// Seed 000, the GSK980TDi G94 programming example (blank Φ125 × 112).
constexpr std::string_view kSeedProgram =
    "G00 X130 Z5 M3 S500;\n"   // line 1
    "G94 X0 Z0 F200;\n"        // 2: face to the centre
    "X120 Z-110 F300;\n"       // 3: retained R0, new end point
    "G00 X120 Z0;\n"           // 4: clears the retained values
    "G94 X108 Z-30 R-10;\n"    // 5: taper faces, A = (60, 0)
    "X96 R-20;\n"              // 6: Z-30 retained
    "X84 R-30;\n"
    "X72 R-40;\n"
    "X60 R-50;\n"
    "M30;\n"                   // 10
    "G00 X0 Z0;\n";            // after the end: never read

TEST(Interpreter, SeedProgramExpandsByHand) {
  const auto result = run(kSeedProgram);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  EXPECT_EQ(result.toolpath.blockCount, 10);
  expectMoves(result.toolpath.moves,
              {
                  {kRapid, 100, 200, 65, 5, 0, 0},  // line 1
                  // line 2: A (65,5), C (0,0), B (65,0), D (0,5)
                  {kRapid, 65, 5, 65, 0, 0, 1},
                  {kFeed, 65, 0, 0, 0, 200, 2},
                  {kFeed, 0, 0, 0, 5, 200, 3},
                  {kRapid, 0, 5, 65, 5, 0, 4},
                  // line 3: C (60,-110), B (65,-110), D (60,5)
                  {kRapid, 65, 5, 65, -110, 0, 1},
                  {kFeed, 65, -110, 60, -110, 300, 2},
                  {kFeed, 60, -110, 60, 5, 300, 3},
                  {kRapid, 60, 5, 65, 5, 0, 4},
                  {kRapid, 65, 5, 60, 0, 0, 0},  // line 4
                  // line 5: A (60,0), C (54,-30), B (60,-40), D (54,0)
                  {kRapid, 60, 0, 60, -40, 0, 1},
                  {kFeed, 60, -40, 54, -30, 300, 2},
                  {kFeed, 54, -30, 54, 0, 300, 3},
                  {kRapid, 54, 0, 60, 0, 0, 4},
                  // line 6: C (48,-30), B (60,-50)
                  {kRapid, 60, 0, 60, -50, 0, 1},
                  {kFeed, 60, -50, 48, -30, 300, 2},
                  {kFeed, 48, -30, 48, 0, 300, 3},
                  {kRapid, 48, 0, 60, 0, 0, 4},
                  // line 7: C (42,-30), B (60,-60)
                  {kRapid, 60, 0, 60, -60, 0, 1},
                  {kFeed, 60, -60, 42, -30, 300, 2},
                  {kFeed, 42, -30, 42, 0, 300, 3},
                  {kRapid, 42, 0, 60, 0, 0, 4},
                  // line 8: C (36,-30), B (60,-70)
                  {kRapid, 60, 0, 60, -70, 0, 1},
                  {kFeed, 60, -70, 36, -30, 300, 2},
                  {kFeed, 36, -30, 36, 0, 300, 3},
                  {kRapid, 36, 0, 60, 0, 0, 4},
                  // line 9: C (30,-30), B (60,-80)
                  {kRapid, 60, 0, 60, -80, 0, 1},
                  {kFeed, 60, -80, 30, -30, 300, 2},
                  {kFeed, 30, -30, 30, 0, 300, 3},
                  {kRapid, 30, 0, 60, 0, 0, 4},
              });
  const auto& moves = result.toolpath.moves;
  const int expectedLine[] = {1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 5, 5, 5, 5, 6, 6, 6, 6,
                              7, 7, 7, 7, 8, 8, 8, 8, 9, 9, 9, 9};
  for (std::size_t i = 0; i < moves.size(); ++i) {
    EXPECT_EQ(moves[i].line, expectedLine[i]) << "move " << i;
    EXPECT_EQ(moves[i].block, expectedLine[i] - 1) << "move " << i;
    EXPECT_EQ(moves[i].column, 1);
    EXPECT_TRUE(moves[i].spindleOn);
    EXPECT_EQ(moves[i].feedMode, FeedMode::PerRevolution);
    EXPECT_EQ(moves[i].tool, 1);
    EXPECT_EQ(moves[i].toolOffset, 0);
  }
}

TEST(Interpreter, SeveralBlocksOnOneLineKeepTheirColumns) {
  const auto result = run("G00 X42 Z0.5; G94 X25.5 Z-5 F100; Z-10;");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves,
              {{kRapid, 100, 200, 21, 0.5, 0, 0},
               {kRapid, 21, 0.5, 21, -5, 0, 1},
               {kFeed, 21, -5, 12.75, -5, 100, 2},
               {kFeed, 12.75, -5, 12.75, 0.5, 100, 3},
               {kRapid, 12.75, 0.5, 21, 0.5, 0, 4},
               {kRapid, 21, 0.5, 21, -10, 0, 1},
               {kFeed, 21, -10, 12.75, -10, 100, 2},
               {kFeed, 12.75, -10, 12.75, 0.5, 100, 3},
               {kRapid, 12.75, 0.5, 21, 0.5, 0, 4}});
  const auto& moves = result.toolpath.moves;
  EXPECT_EQ(moves[0].column, 1);
  EXPECT_EQ(moves[1].column, 15);
  EXPECT_EQ(moves[5].column, 35);
  EXPECT_EQ(moves[5].block, 2);
  EXPECT_EQ(result.toolpath.blockCount, 3);
}

TEST(Interpreter, SyntaxVariantsMeanTheSame) {
  // Spaces inside numbers, no spaces between words, lower case, comments, %, O and N.
  const auto result = run(
      "%\nO1234 (外圆端面)\nN10 g00 x4 2 z0 .5\nN20G94X25 .5Z-5F100(粗车);\n%\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  EXPECT_EQ(result.toolpath.blockCount, 3);  // O1234, N10, N20
  expectMoves(result.toolpath.moves,
              {{kRapid, 100, 200, 21, 0.5, 0, 0},
               {kRapid, 21, 0.5, 21, -5, 0, 1},
               {kFeed, 21, -5, 12.75, -5, 100, 2},
               {kFeed, 12.75, -5, 12.75, 0.5, 100, 3},
               {kRapid, 12.75, 0.5, 21, 0.5, 0, 4}});
  EXPECT_EQ(result.toolpath.moves[0].line, 3);
  EXPECT_EQ(result.toolpath.moves[0].block, 1);
}

TEST(Interpreter, ModalCycleRepeatsWithOnlyZ) {
  // After the first pass, "Z-10" keeps X50 and R-2 from the G94 block.
  const auto result = run("G00 X60 Z2\nG94 X50 Z-5 R-2 F0.2\nZ-10\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves,
              {{kRapid, 100, 200, 30, 2, 0, 0},
               {kRapid, 30, 2, 30, -7, 0, 1},
               {kFeed, 30, -7, 25, -5, 0.2, 2},
               {kFeed, 25, -5, 25, 2, 0.2, 3},
               {kRapid, 25, 2, 30, 2, 0, 4},
               {kRapid, 30, 2, 30, -12, 0, 1},
               {kFeed, 30, -12, 25, -10, 0.2, 2},
               {kFeed, 25, -10, 25, 2, 0.2, 3},
               {kRapid, 25, 2, 30, 2, 0, 4}});
}

TEST(Interpreter, BlockWithoutCycleWordsDoesNotRepeatTheCycle) {
  const auto result = run("G00 X60 Z2\nG94 X50 Z-5 F0.2\nF0.3\nM05\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  EXPECT_EQ(result.toolpath.moves.size(), 5u);
}

TEST(Interpreter, DwellKeepsTheRetainedValues) {
  const auto result = run("G00 X60 Z2\nG94 X50 Z-5 F0.2\nG04 X1.5\nZ-10\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  // 1 rapid, 4 legs, the dwell at A (30, 2), 4 legs.
  ASSERT_EQ(result.toolpath.moves.size(), 10u);
  expectMoves({result.toolpath.moves[5]}, {{MoveKind::Dwell, 30, 2, 30, 2, 0, 0}});
  expectMoves({result.toolpath.moves[7]}, {{kFeed, 30, -10, 25, -10, 0.2, 2}});
}

TEST(Interpreter, RapidClearsTheRetainedValues) {
  // G00 X60 Z2 (line 3) ends the cycle: "G94 Z-10" has no X any more.
  const auto result = run("G00 X60 Z2\nG94 X50 Z-5 F0.2\nG00 X60 Z2\nG94 Z-10\n");
  expectError(result, 4, 1, "G94 needs X(U) and Z(W): the end point's X(U)");
}

TEST(Interpreter, G50ClearsTheRetainedValues) {
  const auto result = run("G00 X60 Z2\nG94 X50 Z-5 F0.2\nG50 X60 Z2\nX40\n");
  expectError(result, 4, 1, "the end point's Z(W)");
}

TEST(Interpreter, LinearFeedClearsTheRetainedValues) {
  const auto result = run("G00 X60 Z2\nG94 X50 Z-5 F0.2\nG01 X60\nG94 X40\n");
  expectError(result, 4, 1, "G94 needs X(U) and Z(W)");
}

TEST(Interpreter, RapidAndFeedWithAbsoluteAndIncrementalWords) {
  const auto result = run("G00 U-100 W-150\nG99 G01 X80 W-20 F0.15\nG98 U10 Z0 F120\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 50, 50, 0, 0},
                                      {kFeed, 50, 50, 40, 30, 0.15, 0},
                                      {kFeed, 40, 30, 45, 0, 120, 0}});
  EXPECT_EQ(result.toolpath.moves[1].feedMode, FeedMode::PerRevolution);
  EXPECT_EQ(result.toolpath.moves[2].feedMode, FeedMode::PerMinute);
}

TEST(Interpreter, ZeroLengthMoveIsNotEmitted) {
  const auto result = run("G00 X200 Z200\nG01 W0 F0.1\nG00 X100\n");
  ASSERT_TRUE(result.ok());
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 50, 200, 0, 0}});
  EXPECT_EQ(result.toolpath.moves[0].block, 2);
  EXPECT_EQ(result.toolpath.blockCount, 3);
}

TEST(Interpreter, G50DeclaresWhereTheToolIsAndMovesTheFrameNotTheTool) {
  // The tool stands at (r 100, Z200) of the setup. G50 X150 Z100 calls that (75, 100): the
  // program's zero lies at (100 − 75, 200 − 100) = (25, 100) of the setup. G00 X50 Z10 =
  // program (25, 10) = setup (50, 110). G50 U10 W-5 calls the tool's (25, 10) (30, 5): the
  // zero moves by (−5, +5) to (20, 105). G00 X40 = program (20, 5) = setup (40, 110). The
  // tool never jumps: each move starts where the last ended.
  const auto result = run("G50 X150 Z100\nG00 X50 Z10\nG50 U10 W-5\nG00 X40\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves,
              {{kRapid, 100, 200, 50, 110, 0, 0}, {kRapid, 50, 110, 40, 110, 0, 0}});
  EXPECT_EQ(result.toolpath.moves[1].workShift, RZ(20, 105));
}

TEST(Interpreter, ASubprogramCalledBeforeAndAfterG50CutsInTwoPlaces) {
  // O100 is G01 W-2 from wherever the tool is, then back: called at program Z0, then after
  // G50 W30 (the tool's Z0 is now called Z30, so the zero moves 30 mm toward the chuck) the
  // same program Z0 is setup Z-30.
  const auto result =
      run("G00 X40 Z0\nM98 P100\nG50 W30\nG00 Z0\nM98 P100\nM30\nO100\nG01 W-2 F0.1\nG00 W2\nM99\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 0, 0, 0},
                                      {kFeed, 20, 0, 20, -2, 0.1, 0},
                                      {kRapid, 20, -2, 20, 0, 0, 0},
                                      {kRapid, 20, 0, 20, -30, 0, 0},
                                      {kFeed, 20, -30, 20, -32, 0.1, 0},
                                      {kRapid, 20, -32, 20, -30, 0, 0}});
}

TEST(Interpreter, BareG50ChangesNothing) {
  // GSK980TDi §3.18: an axis G50 does not name keeps its coordinate.
  const auto result = run("G50\nG00 X40 Z0\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 0, 0, 0}});
}

TEST(Interpreter, InchValuesBecomeMillimetres) {
  const auto result = run("G20 G00 X2 Z1\nG01 X1 Z-0.5 F0.01\nG21 G00 X100 W10\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 25.4, 25.4, 0, 0},
                                      {kFeed, 25.4, 25.4, 12.7, -12.7, 0.254, 0},
                                      {kRapid, 12.7, -12.7, 50, -2.7, 0, 0}});
}

TEST(Interpreter, InchFaceCycle) {
  // G20: X4 = 101.6 mm diameter, Z-0.5 = -12.7 mm, R-0.1 = -2.54 mm, F0.004 = 0.1016 mm/rev.
  const auto result = run("G20 G00 X5 Z0\nG94 X4 Z-0.5 R-0.1 F0.004\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 63.5, 0, 0, 0},
                                      {kRapid, 63.5, 0, 63.5, -15.24, 0, 1},
                                      {kFeed, 63.5, -15.24, 50.8, -12.7, 0.1016, 2},
                                      {kFeed, 50.8, -12.7, 50.8, 0, 0.1016, 3},
                                      {kRapid, 50.8, 0, 63.5, 0, 0, 4}});
}

TEST(Interpreter, ProgramStopsAreListedNotTimed) {
  // M00 and M01 wait for the operator: listed in order, with no move of their own; each run of a
  // subprogram that holds one lists it again.
  const auto result = run("G00 X50 Z2\nM01\nM98 P21000\nM30\nO1000\nM00\nM99\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  EXPECT_EQ(result.toolpath.moves.size(), 1u);
  ASSERT_EQ(result.toolpath.stops.size(), 3u);
  EXPECT_EQ(result.toolpath.stops[0].line, 2);
  EXPECT_EQ(result.toolpath.stops[0].code, "M01");
  EXPECT_EQ(result.toolpath.stops[1].line, 6);
  EXPECT_EQ(result.toolpath.stops[1].code, "M00");
  EXPECT_EQ(result.toolpath.stops[2].line, 6);
}

TEST(Interpreter, ASlashInsideABlockSkipsTheRestOfItWhenBlockSkipIsOn) {
  // Fanuc's optional block skip in mid-block (⚠): "/Z5" is dropped with the switch on, and the
  // slash alone is dropped with it off.
  const auto on = run("G00 X20 /Z5 M08\n");
  ASSERT_TRUE(on.ok()) << on.diagnostics[0].message;
  expectMoves(on.toolpath.moves, {{kRapid, 100, 200, 10, 200, 0, 0}});
  auto options = test::defaultOptions();
  options.control.blockSkip = false;
  const auto off = run("G00 X20 /Z5 M08\n", options);
  ASSERT_TRUE(off.ok()) << off.diagnostics[0].message;
  expectMoves(off.toolpath.moves, {{kRapid, 100, 200, 10, 5, 0, 0}});
}

TEST(Interpreter, TheClosingPercentEndsTheProgram) {
  // Text after the closing % is not run, and a warning says so where it starts.
  const auto result = run("%\nG00 X20 Z2\n%\n  G00 X999\n");
  ASSERT_TRUE(result.ok());
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 10, 2, 0, 0}});
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].line, 4);
  EXPECT_EQ(result.diagnostics[0].column, 3);
  EXPECT_EQ(result.diagnostics[0].message, "the program ends at the % on line 3: this text after it is not run");
  // A closing % with nothing after it: no warning.
  EXPECT_TRUE(run("%\nG00 X20 Z2\n%\n\n").diagnostics.empty());
}

TEST(Interpreter, BlockDeleteSkipsSlashBlocksWhenOn) {
  const std::string_view program = "/G00 X20 Z20\nG00 X40 Z40\n";
  const auto on = run(program);
  ASSERT_TRUE(on.ok());
  EXPECT_EQ(on.toolpath.blockCount, 2);
  expectMoves(on.toolpath.moves, {{kRapid, 100, 200, 20, 40, 0, 0}});
  EXPECT_EQ(on.toolpath.moves[0].block, 1);

  auto options = test::defaultOptions();
  options.control.blockSkip = false;
  const auto off = run(program, options);
  ASSERT_TRUE(off.ok());
  expectMoves(off.toolpath.moves,
              {{kRapid, 100, 200, 10, 20, 0, 0}, {kRapid, 10, 20, 20, 40, 0, 0}});
}

TEST(Interpreter, ToolWords) {
  const auto result = run("G00 X100\nT0202 G00 X90\nT0100\nG00 X80\nT0200 X70\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const auto& moves = result.toolpath.moves;
  ASSERT_EQ(moves.size(), 4u);
  EXPECT_EQ(moves[0].tool, 1);  // the first tool of the setup, offset 0
  EXPECT_EQ(moves[0].toolOffset, 0);
  EXPECT_EQ(moves[1].tool, 2);
  EXPECT_EQ(moves[1].toolOffset, 2);
  EXPECT_EQ(moves[2].tool, 1);
  EXPECT_EQ(moves[2].toolOffset, 0);
  EXPECT_EQ(moves[3].tool, 2);
  EXPECT_EQ(moves[3].toolOffset, 0);
}

TEST(Interpreter, UnknownToolIsAnErrorNamingIt) {
  expectError(run("G00 X100\nG00 T0909 X90\n"), 2, 5,
              "tool 9 (T0909) is not defined in the setup; defined tools: 1, 2");
}

TEST(Interpreter, SpindleStartsBeforeAndStopsAfterTheBlockMotion) {
  const auto result = run("G00 X100\nM03 S800 X90\nM05 X80\nX70\nM04 X60\n");
  ASSERT_TRUE(result.ok());
  const auto& moves = result.toolpath.moves;
  ASSERT_EQ(moves.size(), 5u);
  EXPECT_FALSE(moves[0].spindleOn);
  EXPECT_TRUE(moves[1].spindleOn);
  EXPECT_TRUE(moves[2].spindleOn);
  EXPECT_FALSE(moves[3].spindleOn);
  EXPECT_TRUE(moves[4].spindleOn);
}

TEST(Interpreter, ProgramEndStopsReading) {
  // Nothing after M02 is read, not even a malformed word.
  const auto result = run("G00 X100 M08\nM09 M02\nG00 X20.3.\n(unclosed\n");
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(result.toolpath.blockCount, 2);
  EXPECT_EQ(result.toolpath.moves.size(), 1u);
}

TEST(Interpreter, MotionModeWithoutAxisWordsMakesNoMove) {
  const auto result = run("G01 F0.2\nG00\nX50\n");
  ASSERT_TRUE(result.ok());
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 25, 200, 0, 0}});
}

TEST(Interpreter, ResultRecordsProgramAndStart) {
  const auto result = interpret("G00 X10", "part.nc", test::defaultOptions());
  EXPECT_EQ(result.toolpath.programName, "part.nc");
  EXPECT_DOUBLE_EQ(result.toolpath.startPosition.x(), 100.0);
  EXPECT_DOUBLE_EQ(result.toolpath.startPosition.y(), 200.0);
}

// ---- errors: the specific message, at its line and column ----

TEST(InterpreterErrors, FirstErrorStopsAndKeepsEarlierMoves) {
  const auto result = run("G00 X100\nG00 X20.3.\nG00 X50\n");
  expectError(result, 2, 5, "malformed number in X20.3.");
  EXPECT_EQ(result.toolpath.moves.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].file, "test.nc");
  EXPECT_EQ(result.diagnostics[0].sourceLine, "G00 X20.3.");
}

TEST(InterpreterErrors, FeedMoveWithoutF) {
  expectError(run("G00 X100\nG01 X50 Z-5\n"), 2, 1, "feed rate F is not set");
  expectError(run("G00 X100 Z5\nG94 X50 Z-5\n"), 2, 1, "feed rate F is not set");
  // F0 is a feed of 0 (GSK §3.26); a move cut at it would wait forever on the machine.
  expectError(run("G01 F0.1\nN5 X50\nG01 F0 X40\n"), 3, 1,
              "G01 cuts at F0, a feed of 0: the machine would wait there forever; give F > 0");
  expectError(run("G00 X100 Z5 F0\nG94 X50 Z-5\n"), 2, 1, "G94 cuts at F0");
  expectError(run("G01 F-1 X40\n"), 1, 5, "F-1 is not a feed rate: expected a number ≥ 0");
  EXPECT_TRUE(run("G01 F0\nG00 X40\n").ok());  // F0 with no cut at it is harmless
}

TEST(InterpreterErrors, G94UnderG17OrG19SaysThereIsNoYAxis) {
  expectError(run("G00 X100 Z5\nG17 G94 X50 Z-5 F0.1\n"), 2, 5, "G94 under G17: this machine has no Y axis");
  expectError(run("G19\nG00 X100 Z5 F0.1\nG94 X50 Z-5\n"), 3, 1, "G94 under G19: this machine has no Y axis");
  // Plain moves are fine under G17, and G18 restores cycles.
  EXPECT_TRUE(run("G17 G00 X100 Z5\nG18 G94 X50 Z-5 F0.1\n").ok());
}

TEST(Interpreter, OfTwoCodesOfOneGroupTheLastIsInForceWithAWarning) {
  // G00 G01 X20: a feed (Fanuc: the last code of a group wins); M03 M05: the spindle stopped.
  const auto result = run("G00 G01 X20 F0.1\nM03 M05 S500\nG01 Z-10\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kFeed, 100, 200, 10, 200, 0.1, 0}, {kFeed, 10, 200, 10, -10, 0.1, 0}});
  EXPECT_FALSE(result.toolpath.moves[1].spindleOn);
  ASSERT_EQ(result.diagnostics.size(), 2u);
  EXPECT_EQ(result.diagnostics[0].line, 1);
  EXPECT_EQ(result.diagnostics[0].column, 5);
  EXPECT_EQ(result.diagnostics[0].message,
            "G00 and G01 are both motion (group 01) codes: the last, G01, is in force (as on a Fanuc); give one of "
            "them");
  EXPECT_EQ(result.diagnostics[1].message,
            "M03 and M05 are both spindle codes: the last, M05, is in force (as on a Fanuc); give one of them");
}

TEST(InterpreterErrors, RepeatedWord) {
  expectError(run("G00 X20 X30\n"), 1, 9, "X is given twice in this block (X20 and X30)");
}

TEST(Interpreter, AbsoluteAndIncrementalForOneAxisAsTheControlReadsThem) {
  // GSK980TDi §3.2: X wins over U, Z over W, the other ignored (warned).
  const auto gsk = run("G00 X20 U10\nG01 W-3 Z5 F1\n");
  ASSERT_TRUE(gsk.ok()) << gsk.diagnostics[0].message;
  expectMoves(gsk.toolpath.moves, {{kRapid, 100, 200, 10, 200, 0, 0}, {kFeed, 10, 200, 10, 5, 1, 0}});
  ASSERT_EQ(gsk.diagnostics.size(), 2u);
  EXPECT_EQ(gsk.diagnostics[0].column, 9);
  EXPECT_EQ(gsk.diagnostics[0].message,
            "U10 is ignored: X20 in the same block gives the X axis (the absolute word wins, GSK980TDi §3.2)");
  EXPECT_EQ(gsk.diagnostics[1].column, 5);
  // fanuc-0i-t (⚠): an alarm.
  InterpreterOptions fanuc = test::defaultOptions();
  fanuc.control.absoluteWithIncremental = AbsoluteWithIncremental::Alarm;
  expectError(run("G00 X20 U10\n", fanuc), 1, 9, "X20 and U10 both give the X axis");
  expectError(run("G01 W-3 Z5 F1\n", fanuc), 1, 9, "Z5 and W-3 both give the Z axis");
}

TEST(InterpreterErrors, UnknownAndUnsupportedCodes) {
  expectError(run("G05 X20\n"), 1, 1, "unknown G code G05");
  expectError(run("G1.5 X20\n"), 1, 1, "unknown G code G1.5");
  expectError(run("M07\n"), 1, 1, "unknown M code M07");
  expectError(run("G112\n"), 1, 1, "G112 (polar coordinate interpolation) needs a C axis");
}

TEST(InterpreterErrors, LeftoverWord) {
  expectError(run("G00 X20 R5\n"), 1, 9, "R5 is not used by any code in this block");
  expectError(run("G01 X20 F1 P3 I2\n"), 1, 12, "P3 is not used");
}

TEST(Interpreter, AOneShotCodeTakesTheAxisWordsAndAMotionCodeBesideItOnlyBecomesModal) {
  // G28 G00 U0 W0 (a common safety line): G28 returns straight to the reference (the start
  // here, (100, 200)); G00 is the motion the next block's X20 Z0 makes.
  const auto result = run("G01 X40 Z10 F0.2\nG28 G00 U0 W0\nX20 Z0\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kFeed, 100, 200, 20, 10, 0.2, 0},
                                      {kRapid, 20, 10, 100, 200, 0, 2},
                                      {kRapid, 100, 200, 10, 0, 0, 0}});
}

TEST(Interpreter, ACycleCodeAloneSetsTheMotionAndMovesNothing) {
  // G90 on a safety line: no move; the X/Z block after it runs the cycle from where the tool is.
  const auto result = run("G00 X50 Z2\nG90\nX40 Z-10 F0.2\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 25, 2, 0, 0},
                                      {kRapid, 25, 2, 20, 2, 0, 1},
                                      {kFeed, 20, 2, 20, -10, 0.2, 2},
                                      {kFeed, 20, -10, 25, -10, 0.2, 3},
                                      {kRapid, 25, -10, 25, 2, 0, 4}});
  EXPECT_TRUE(run("G94\nG71\nG74\n").toolpath.moves.empty());
}

TEST(Interpreter, DwellWordsAsTheGskReadsThem) {
  // GSK980TDi §3.14: G04 alone is an exact stop (no time, no move); P wins over X, X over U; a
  // negative time dwells 0 s.
  const auto result = run("G04\nG04 X1 P1500\nG04 U3 X2\nG04 X-2\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  ASSERT_EQ(result.toolpath.moves.size(), 3u);
  EXPECT_DOUBLE_EQ(result.toolpath.moves[0].dwellS, 1.5);
  EXPECT_EQ(result.toolpath.moves[0].line, 2);
  EXPECT_DOUBLE_EQ(result.toolpath.moves[1].dwellS, 2);
  EXPECT_DOUBLE_EQ(result.toolpath.moves[2].dwellS, 0);
  ASSERT_EQ(result.diagnostics.size(), 2u);
  EXPECT_EQ(result.diagnostics[0].message, "X1 is ignored: P1500 gives G04's time (P before X before U, GSK980TDi §3.14)");
  EXPECT_EQ(result.diagnostics[0].column, 5);
  EXPECT_EQ(result.diagnostics[1].message, "U3 is ignored: X2 gives G04's time (P before X before U, GSK980TDi §3.14)");
}

TEST(InterpreterErrors, BadToolSpeedAndCoordinateWords) {
  expectError(run("M03 S-5\n"), 1, 5, "S-5 is not a spindle speed");
  EXPECT_TRUE(run("G50 S2000\n").ok());
}

TEST(InterpreterErrors, NoToolsDefined) {
  InterpreterOptions options;
  const auto result = run("G00 X10\nT0101\n", options);
  expectError(result, 2, 1, "tool 1 (T0101) is not defined in the setup; defined tools: none");
  EXPECT_EQ(result.toolpath.moves.at(0).tool, 0);
}

TEST(InterpreterErrors, DiagnosticCarriesTheSourceLineForTheCaret) {
  const auto result = interpret("G00 X100\n(粗车) G00 X20.3.\n", "bad.nc", test::defaultOptions());
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(format(result.diagnostics[0]),
            "bad.nc:2:10: error: malformed number in X20.3.: expected an optional sign, then "
            "digits with at most one decimal point\n"
            "(粗车) G00 X20.3.\n"
            "         ^");
}

TEST(InterpreterErrors, BlockThatFailsLeavesNoMove) {
  // Line 2 would move, but its leftover word fails the whole block first.
  const auto result = run("G00 X100\nG00 X50 K3\n");
  expectError(result, 2, 9, "K3 is not used");
  EXPECT_EQ(result.toolpath.moves.size(), 1u);
}

}  // namespace
}  // namespace lathesim::interp
