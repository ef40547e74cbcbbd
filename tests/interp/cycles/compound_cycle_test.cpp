// G70–G75 through the interpreter, each move list expanded by hand from lathe-cycles.md §3–5.
// Positions are (radius, Z): X60 is radius 30. The tool starts at X200 Z200 = (100, 200).

#include <gtest/gtest.h>

#include <string>

#include <fmt/format.h>

#include "interp/execution/block_executor.hpp"
#include "interp/text/lexer.hpp"
#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;
using test::expectMoves;
using test::kFeed;
using test::kRapid;
using test::run;

TEST(G70, RunsTheContourAsWrittenThenRapidsBackAndGoesOnAfterIt) {
  // The contour is roughed by G73 first (its moves are left out below); G70 then runs it as
  // written from A, with the contour's own F.
  const auto result = run(
      "G00 X60 Z2 F0.3\n"        // 1: A = (30, 2)
      "G73 U2 W0 R2\n"           // 2
      "G73 P10 Q30\n"            // 3
      "N10 G00 X20 F0.1\n"       // 4
      "N20 G01 Z-10\n"           // 5: at N10's F0.1
      "N30 X40 Z-20 F0.2\n"      // 6
      "G70 P10 Q30\n"            // 7
      "G00 X100\n");             // 8: after G70
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const auto& moves = result.toolpath.moves;
  ASSERT_GE(moves.size(), 5u);
  const std::vector<Move> finishing(moves.end() - 5, moves.end());
  expectMoves(finishing, {{kRapid, 30, 2, 10, 2, 0, 0},
                          {kFeed, 10, 2, 10, -10, 0.1, 0},
                          {kFeed, 10, -10, 20, -20, 0.2, 0},
                          {kRapid, 20, -20, 30, 2, 0, 0},   // G70: back to A
                          {kRapid, 30, 2, 50, 2, 0, 0}});   // line 8
  // The contour's moves carry their own blocks' lines; the return to A carries G70's.
  const int lines[] = {4, 5, 6, 7, 8};
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(finishing[i].line, lines[i]) << i;
}

TEST(G70, AContourAfterItIsAnError) {
  // GSK980TDi §3.23.4 note 1: G70 finishes a contour roughed before it.
  expectError(run("G00 X60 Z2 F0.3\nG70 P10 Q20\nM30\nN10 G00 X20\nN20 G01 Z-10\n"), 2, 1,
              "G70's contour N10 starts on line 4, after it: G70 finishes a contour roughed before it and must "
              "follow its blocks (GSK980TDi §3.23.4 note 1)");
}

TEST(CompoundCycleErrors, ANumberTwoContoursShareIsAnErrorNamingBoth) {
  // GSK980TDi §3.23.1 note 14: N10 and N20 number both G71's contour and G73's.
  const std::string_view program =
      "G00 X60 Z2 F0.3\n"
      "G71 U2 R0.5\n"
      "G71 P10 Q20\n"
      "N10 G00 X20\n"
      "N20 G01 Z-10\n"
      "G73 U2 W0 R2\n"
      "G73 P10 Q20\n"
      "N10 G00 X30\n"
      "N20 G01 Z-20\n";
  expectError(run(program), 3, 5,
              "G71 P10: N10 numbers two blocks, on lines 4 and 8; the contours of the compound cycles in one "
              "program need N numbers of their own");
}

TEST(CompoundCycleErrors, ALabelOfMoreThanFiveDigitsIsNamedAsWritten) {
  expectError(run("N123456 G00 X20\n"), 1, 1, "N123456 is not a sequence number: it has 6 digits, at most 5");
  expectError(run("G00 X60 Z2 F0.3\nG70 P4294967306 Q20\nN10 G00 X20\nN20 G01 Z-10\n"), 2, 5,
              "P4294967306 is not a sequence number (e.g. P10 for N10): it has 10 digits, at most 5");
  EXPECT_TRUE(run("N00010 G00 X20\n").ok());  // leading zeros are not digits of the number
}

TEST(G73, TwoPassesShiftedByReliefAndAllowance) {
  // d = 2: pass 1 shifted (Δu/2 + Δi, Δw + Δk) = (0.5 + 4, 0.5 + 2) = (4.5, 2.5), pass 2 by
  // the allowance (0.5, 0.5). The contour from A (30, 2): N10 rapid to (10, 2), N20 feed to
  // (10, -10). Legs at the G73 block's F0.25; N20's F0.1 is ignored.
  const auto result = run(
      "G00 X60 Z2\n"                      // 1
      "G73 U4 W2 R2\n"                    // 2
      "G73 P10 Q20 U1 W0.5 F0.25\n"       // 3
      "N10 G00 X20\n"                     // 4
      "N20 G01 Z-10 F0.1\n"               // 5
      "G00 X100\n");                      // 6: runs next, the contour skipped
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 30, 2, 0, 0},
                                      {kRapid, 30, 2, 34.5, 4.5, 0, 1},
                                      {kRapid, 34.5, 4.5, 14.5, 4.5, 0, 2},
                                      {kFeed, 14.5, 4.5, 14.5, -7.5, 0.25, 3},
                                      {kRapid, 14.5, -7.5, 30.5, 2.5, 0, 1},
                                      {kRapid, 30.5, 2.5, 10.5, 2.5, 0, 2},
                                      {kFeed, 10.5, 2.5, 10.5, -9.5, 0.25, 3},
                                      {kRapid, 10.5, -9.5, 30, 2, 0, 4},
                                      {kRapid, 30, 2, 50, 2, 0, 0}});
  // The legs along the contour carry its blocks' lines (N20's is line 5), the others the cycle
  // block's.
  EXPECT_EQ(result.toolpath.moves[1].line, 3);
  EXPECT_EQ(result.toolpath.moves[2].line, 4);  // step 2: the ns block's move, shifted
  EXPECT_EQ(result.toolpath.moves[3].line, 5);
  EXPECT_EQ(result.toolpath.moves[4].line, 3);
  EXPECT_EQ(result.toolpath.moves[8].line, 6);
}

TEST(G73, ThreePassesWithAFeedNsBlock) {
  // Δi = 6 (radius), d = 3: X shifts 6·(3−k)/2 = 6, 3, 0; no Z relief, no allowance.
  // Contour from A (30, 2): (10, 0) at G01 (the ns block), (10, -10), (15, -10).
  const auto result = run(
      "G00 X60 Z2\nG73 U6 W0 R3\nG73 P10 Q30 F0.2\n"
      "N10 G01 X20 Z0 F0.1\nN20 Z-10\nN30 X30\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 30, 2, 0, 0},
                                      {kRapid, 30, 2, 36, 2, 0, 1},
                                      {kFeed, 36, 2, 16, 0, 0.2, 2},
                                      {kFeed, 16, 0, 16, -10, 0.2, 3},
                                      {kFeed, 16, -10, 21, -10, 0.2, 3},
                                      {kRapid, 21, -10, 33, 2, 0, 1},
                                      {kFeed, 33, 2, 13, 0, 0.2, 2},
                                      {kFeed, 13, 0, 13, -10, 0.2, 3},
                                      {kFeed, 13, -10, 18, -10, 0.2, 3},
                                      {kRapid, 18, -10, 30, 2, 0, 1},
                                      {kFeed, 30, 2, 10, 0, 0.2, 2},
                                      {kFeed, 10, 0, 10, -10, 0.2, 3},
                                      {kFeed, 10, -10, 15, -10, 0.2, 3},
                                      {kRapid, 15, -10, 30, 2, 0, 4}});
}

TEST(G73, OnePassRunsAsTwo) {
  // d = 1 runs as d = 2 (GSK): pass 1 shifted by Δi = 2, pass 2 by nothing.
  const auto result = run("G00 X60 Z2\nG73 U2 R1\nG73 P10 Q10 F0.2\nN10 G01 X40\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 30, 2, 0, 0},
                                      {kRapid, 30, 2, 32, 2, 0, 1},
                                      {kFeed, 32, 2, 22, 2, 0.2, 2},
                                      {kRapid, 22, 2, 30, 2, 0, 1},
                                      {kFeed, 30, 2, 20, 2, 0.2, 2},
                                      {kRapid, 20, 2, 30, 2, 0, 4}});
}

TEST(G73, ContourIsFoundInTheCyclesOwnProgram) {
  // Main and subprogram both have an N10; the subprogram's G73 uses its own (X40), and after
  // its nf block the subprogram goes on to M99. The legs are those of OnePassRunsAsTwo.
  const auto result = run(
      "G00 X60 Z2\nM98 P100\nM30\nN10 G00 X10\n"
      "O0100\nG73 U2 R1\nG73 P10 Q10 F0.2\nN10 G01 X40\nM99\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 30, 2, 0, 0},
                                      {kRapid, 30, 2, 32, 2, 0, 1},
                                      {kFeed, 32, 2, 22, 2, 0.2, 2},
                                      {kRapid, 22, 2, 30, 2, 0, 1},
                                      {kFeed, 30, 2, 20, 2, 0.2, 2},
                                      {kRapid, 20, 2, 30, 2, 0, 4}});
  EXPECT_EQ(result.toolpath.moves[1].line, 7);
}

TEST(G74, PeckDrillWithThreePecks) {
  // A = (0, 2), Z end -20, Δk = Q8000 = 8 mm, e = 1: feed to Z-6, back to -5, feed to -14,
  // back to -13, feed the last 6 mm to -20, rapid back to Z2 (= A: no step 6).
  const auto result = run("G00 X0 Z2\nG74 R1\nG74 Z-20 Q8000 F0.1\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 0, 2, 0, 0},
                                      {kFeed, 0, 2, 0, -6, 0.1, 1},
                                      {kRapid, 0, -6, 0, -5, 0, 2},
                                      {kFeed, 0, -5, 0, -14, 0.1, 1},
                                      {kRapid, 0, -14, 0, -13, 0, 2},
                                      {kFeed, 0, -13, 0, -20, 0.1, 1},
                                      {kRapid, 0, -20, 0, 2, 0, 4}});
}

TEST(G74, DecimalPointMeansMillimetres) {
  // Q8. is 8 mm, like Q8000: the same three pecks.
  const auto a = run("G00 X0 Z2\nG74 R1\nG74 Z-20 Q8. F0.1\n");
  const auto b = run("G00 X0 Z2\nG74 R1\nG74 Z-20 Q8000 F0.1\n");
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_EQ(a.toolpath.moves.size(), b.toolpath.moves.size());
  EXPECT_EQ(a.toolpath.moves.size(), 7u);
}

TEST(G74, FaceGrooveStepsInXWithRelief) {
  // A = (15, 1), end (X20 → 10, Z-4): one 5 mm peck (Q5. = 5 mm) per plunge. P4000 = Δi
  // 4 mm as a diameter: plunges 2 apart in radius at 15, 13, 11, then 10 (clamped).
  // R2000 = Δd 2 mm diameter: relief 1 in radius away from the end (toward +X).
  const auto result = run("G00 X30 Z1\nG74 R0.5\nG74 X20 Z-4 P4000 Q5. R2000 F0.1\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 15, 1, 0, 0},
                                      {kFeed, 15, 1, 15, -4, 0.1, 1},
                                      {kRapid, 15, -4, 16, -4, 0, 3},
                                      {kRapid, 16, -4, 16, 1, 0, 4},
                                      {kRapid, 16, 1, 13, 1, 0, 5},
                                      {kFeed, 13, 1, 13, -4, 0.1, 1},
                                      {kRapid, 13, -4, 14, -4, 0, 3},
                                      {kRapid, 14, -4, 14, 1, 0, 4},
                                      {kRapid, 14, 1, 11, 1, 0, 5},
                                      {kFeed, 11, 1, 11, -4, 0.1, 1},
                                      {kRapid, 11, -4, 12, -4, 0, 3},
                                      {kRapid, 12, -4, 12, 1, 0, 4},
                                      {kRapid, 12, 1, 10, 1, 0, 5},
                                      {kFeed, 10, 1, 10, -4, 0.1, 1},
                                      {kRapid, 10, -4, 11, -4, 0, 3},
                                      {kRapid, 11, -4, 11, 1, 0, 4},
                                      {kRapid, 11, 1, 15, 1, 0, 6}});
}

TEST(G75, GrooveWiderThanTheToolInTwoPlunges) {
  // A = (21, -10), end (X30 → 15, Z-14). P4000 = Δi 4 mm diameter: pecks of 2 in radius,
  // e = 0.5: 21 → 19, back to 19.5, → 17, back to 17.5, → 15. Q4000 = 4 mm: the second
  // plunge at Z-14. No relief. Back to X21, over to Z-14, again, then back to A.
  const auto result = run("G00 X42 Z-10\nG75 R0.5\nG75 X30 Z-14 P4000 Q4000 F0.05\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 21, -10, 0, 0},
                                      {kFeed, 21, -10, 19, -10, 0.05, 1},
                                      {kRapid, 19, -10, 19.5, -10, 0, 2},
                                      {kFeed, 19.5, -10, 17, -10, 0.05, 1},
                                      {kRapid, 17, -10, 17.5, -10, 0, 2},
                                      {kFeed, 17.5, -10, 15, -10, 0.05, 1},
                                      {kRapid, 15, -10, 21, -10, 0, 4},
                                      {kRapid, 21, -10, 21, -14, 0, 5},
                                      {kFeed, 21, -14, 19, -14, 0.05, 1},
                                      {kRapid, 19, -14, 19.5, -14, 0, 2},
                                      {kFeed, 19.5, -14, 17, -14, 0.05, 1},
                                      {kRapid, 17, -14, 17.5, -14, 0, 2},
                                      {kFeed, 17.5, -14, 15, -14, 0.05, 1},
                                      {kRapid, 15, -14, 21, -14, 0, 4},
                                      {kRapid, 21, -14, 21, -10, 0, 6}});
}

// R(Δd) when the block moves only the peck axis (no Z for G75): A = (22, -10) to X30 (r 15),
// P20000 a peck longer than the 7 mm to go, so one plunge; Δd = R500 = 0.5 mm along Z. The
// GSK relieves toward + (§3.23.5: the shift axis omitted), whatever Δd's sign; the Fanuc
// (⚠) the way Δd's sign says.
TEST(G75, ReliefWithoutAShiftAxisGoesWhereTheControlSays) {
  for (const auto& [rule, word, reliefZ] :
       {std::tuple{PeckReliefWithoutShift::TowardPlus, "R500", -9.5},
        std::tuple{PeckReliefWithoutShift::TowardPlus, "R-500", -9.5},
        std::tuple{PeckReliefWithoutShift::BySign, "R500", -9.5},
        std::tuple{PeckReliefWithoutShift::BySign, "R-500", -10.5}}) {
    SCOPED_TRACE(word);
    InterpreterOptions options = test::defaultOptions();
    options.control.peckReliefWithoutShift = rule;
    const auto result = run("G00 X44 Z-10\nG75 X30 P20000 " + std::string(word) + " F0.05\n", options);
    ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
    expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 22, -10, 0, 0},
                                        {kFeed, 22, -10, 15, -10, 0.05, 1},
                                        {kRapid, 15, -10, 15, reliefZ, 0, 3},
                                        {kRapid, 15, reliefZ, 22, reliefZ, 0, 4},
                                        {kRapid, 22, reliefZ, 22, -10, 0, 6}});
  }
}

TEST(G71, RoughsThenG70Finishes) {
  // A = (20, 2), Δd = 2, e = 0.5, no allowance; contour A → (15, 2) rapid, → (15, -10),
  // → (20, -10). Levels at X 18 and 16 (3·2 would reach past B′ at 15): each cut along Z to
  // the contour's shoulder at Z-10, 45° retract by e at feed, rapid back to Z2, infeed Δd + e
  // (rapid: the ns block is G00); then infeed to B′, the semi-finishing pass, rapid to A.
  // G70 then runs N10–N30 at their own F0.1 and rapids back to A.
  const auto result = run(
      "G99 G00 X40 Z2 S500 M03\n"     // 1
      "G71 U2 R0.5\n"                 // 2
      "G71 P10 Q30 U0 W0 F0.2\n"      // 3
      "N10 G00 X30\n"                 // 4
      "N20 G01 Z-10 F0.1\n"           // 5
      "N30 X40\n"                     // 6
      "G70 P10 Q30\n"                 // 7
      "M30\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 2, 0, 0},
                                      {kRapid, 20, 2, 18, 2, 0, 2},
                                      {kFeed, 18, 2, 18, -10, 0.2, 3},
                                      {kFeed, 18, -10, 18.5, -9.5, 0.2, 4},
                                      {kRapid, 18.5, -9.5, 18.5, 2, 0, 5},
                                      {kRapid, 18.5, 2, 16, 2, 0, 6},
                                      {kFeed, 16, 2, 16, -10, 0.2, 3},
                                      {kFeed, 16, -10, 16.5, -9.5, 0.2, 4},
                                      {kRapid, 16.5, -9.5, 16.5, 2, 0, 5},
                                      {kRapid, 16.5, 2, 15, 2, 0, 6},
                                      {kFeed, 15, 2, 15, -10, 0.2, 7},
                                      {kFeed, 15, -10, 20, -10, 0.2, 7},
                                      {kRapid, 20, -10, 20, 2, 0, 8},
                                      // G70
                                      {kRapid, 20, 2, 15, 2, 0, 0},
                                      {kFeed, 15, 2, 15, -10, 0.1, 0},
                                      {kFeed, 15, -10, 20, -10, 0.1, 0},
                                      {kRapid, 20, -10, 20, 2, 0, 0}});
  EXPECT_EQ(result.toolpath.moves[2].line, 3);
  // The infeed to B′ (the ns block's move) and the semi-finishing pass along N20 and N30 carry
  // their blocks' lines, as G70's cut does; the rapid back to A is the cycle's own.
  EXPECT_EQ(result.toolpath.moves[8].line, 3);
  EXPECT_EQ(result.toolpath.moves[9].line, 4);
  EXPECT_EQ(result.toolpath.moves[10].line, 5);
  EXPECT_EQ(result.toolpath.moves[11].line, 6);
  EXPECT_EQ(result.toolpath.moves[12].line, 3);
  EXPECT_EQ(result.toolpath.moves[14].line, 5);
  EXPECT_EQ(result.toolpath.moves[16].line, 7);
}

TEST(G71, FirstBlockValuesDefaultToTheParameters) {
  // Without a first block Δd = 1 (GSK No.51), e = 0.5 (No.52): from A (20, 2) to B′ (17, 2)
  // the levels are 19 and 18 (3·1 reaches B′), then the infeed to B′.
  const auto result = run("G00 X40 Z2\nG71 P10 Q20 F0.2\nN10 G00 X34\nN20 G01 Z-5\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const auto& moves = result.toolpath.moves;
  ASSERT_GE(moves.size(), 3u);
  expectMoves({moves[1], moves[2]},
              {{kRapid, 20, 2, 19, 2, 0, 2}, {kFeed, 19, 2, 19, -5, 0.2, 3}});
  // Said, not silent: the values are the machine's, not the program's.
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].line, 2);
  EXPECT_EQ(result.diagnostics[0].message,
            "G71 P… Q… runs without a first block G71 U(Δd) R(e): Δd 1 mm and e 0.5 mm come from the control's "
            "parameters (g71_depth, g71_retract), not from the program");
  // A control whose parameters differ roughs differently: g71_depth 1.5 gives levels 18.5 only.
  InterpreterOptions options = test::defaultOptions();
  options.control.roughingDepthMm = 1.5;
  const auto deeper = run("G00 X40 Z2\nG71 P10 Q20 F0.2\nN10 G00 X34\nN20 G01 Z-5\n", options);
  ASSERT_TRUE(deeper.ok());
  expectMoves({deeper.toolpath.moves[1], deeper.toolpath.moves[2]},
              {{kRapid, 20, 2, 18.5, 2, 0, 2}, {kFeed, 18.5, 2, 18.5, -5, 0.2, 3}});
  // With a first block, no warning.
  EXPECT_TRUE(run("G00 X40 Z2\nG71 U1 R1\nG71 P10 Q20 F0.2\nN10 G00 X34\nN20 G01 Z-5\n").diagnostics.empty());
}

TEST(G72, FirstBlockValuesDefaultToTheParametersWithAWarning) {
  // Δd = 1 in Z (No.51), e = 0.5 (No.52): from A (22, 2) the first level is Z1, cut along X to the
  // axis, then the 45° retract at feed (the GSK's) by 0.5 in both axes.
  const auto result = run("G00 X44 Z2\nG72 P10 Q20 F0.2\nN10 G00 Z-1.5\nN20 G01 X0\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const auto& moves = result.toolpath.moves;
  ASSERT_GE(moves.size(), 4u);
  expectMoves({moves[1], moves[2], moves[3]}, {{kRapid, 22, 2, 22, 1, 0, 2},
                                               {kFeed, 22, 1, 0, 1, 0.2, 3},
                                               {kFeed, 0, 1, 0.5, 1.5, 0.2, 4}});
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].line, 2);
  EXPECT_EQ(result.diagnostics[0].message,
            "G72 P… Q… runs without a first block G72 W(Δd) R(e): Δd 1 mm and e 0.5 mm come from the control's "
            "parameters (g71_depth, g71_retract), not from the program");
}

TEST(G73, FirstBlockValuesDefaultToTheParametersWithAWarning) {
  // Δi = Δk = 0 and d = 1 (No.53–55), d = 1 cut as two passes (GSK): both at no shift, A (30, 2)
  // → (20, 2) by the ns block's G01, back, again, and back to A.
  const auto result = run("G00 X60 Z2\nG73 P10 Q10 F0.2\nN10 G01 X40\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 30, 2, 0, 0},
                                      {kFeed, 30, 2, 20, 2, 0.2, 2},
                                      {kRapid, 20, 2, 30, 2, 0, 1},
                                      {kFeed, 30, 2, 20, 2, 0.2, 2},
                                      {kRapid, 20, 2, 30, 2, 0, 4}});
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].message,
            "G73 P… Q… runs without a first block G73 U(Δi) W(Δk) R(d): Δi 0 mm, Δk 0 mm and d 1 come from the "
            "control's parameters (g73_relief_x, g73_relief_z, g73_passes), not from the program");
}

TEST(G71, GsksKAndJWordsAreRead) {
  // K0/K1 (the monotonic check, always made) and J0 change nothing; J1's extra pass is refused.
  const std::string_view base = "G00 X40 Z2\nG71 U1 R1\nG71 P10 Q20 F0.2 ";
  const auto plain = run(std::string(base) + "\nN10 G00 X34\nN20 G01 Z-5\n");
  for (const char* words : {"K0", "K1", "K1 J0"}) {
    const auto result = run(std::string(base) + words + "\nN10 G00 X34\nN20 G01 Z-5\n");
    ASSERT_TRUE(result.ok()) << words << ": " << result.diagnostics[0].message;
    EXPECT_EQ(result.toolpath.moves.size(), plain.toolpath.moves.size()) << words;
  }
  expectError(run(std::string(base) + "J1\nN10 G00 X34\nN20 G01 Z-5\n"), 3, 18,
              "G71 J1: the GSK's extra pass along the rough contour is not simulated");
}

TEST(G72, FirstBlockWIsTheDepthAndPassesRunAlongX) {
  // G72 W2 R0.5: Δd 2 in Z, e 0.5. A = (22, 2); contour: N10 rapid to (22, -5) (type I: Z
  // only), N20 a face to the axis. Levels Z 0, -2, -4 (a fourth at -6 would pass B′ at -5);
  // each cut along X to the contour's end at r 0 (the level never meets the face), a 45°
  // retract (+0.5, +0.5), rapid back in X to r 22, infeed Δd + e; then to B′, the
  // semi-finishing face and the rapid back to A.
  const auto result = run("G00 X44 Z2\nG72 W2 R0.5\nG72 P10 Q20 F0.2\nN10 G00 Z-5\nN20 G01 X0\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 22, 2, 0, 0},
                                      {kRapid, 22, 2, 22, 0, 0, 2},
                                      {kFeed, 22, 0, 0, 0, 0.2, 3},
                                      {kFeed, 0, 0, 0.5, 0.5, 0.2, 4},
                                      {kRapid, 0.5, 0.5, 22, 0.5, 0, 5},
                                      {kRapid, 22, 0.5, 22, -2, 0, 6},
                                      {kFeed, 22, -2, 0, -2, 0.2, 3},
                                      {kFeed, 0, -2, 0.5, -1.5, 0.2, 4},
                                      {kRapid, 0.5, -1.5, 22, -1.5, 0, 5},
                                      {kRapid, 22, -1.5, 22, -4, 0, 6},
                                      {kFeed, 22, -4, 0, -4, 0.2, 3},
                                      {kFeed, 0, -4, 0.5, -3.5, 0.2, 4},
                                      {kRapid, 0.5, -3.5, 22, -3.5, 0, 5},
                                      {kRapid, 22, -3.5, 22, -5, 0, 6},
                                      {kFeed, 22, -5, 0, -5, 0.2, 7},
                                      {kRapid, 0, -5, 22, 2, 0, 8}});
}

TEST(G71, BothAxesInTheNsBlockMakeTypeII) {
  // A pocket (X goes down, up, down again) is refused by type I, accepted by type II, which
  // the ns block selects by giving Z(W) as well as X(U): W0 is enough.
  const std::string pocket = "N20 G01 Z-10 F0.1\nN30 X26 Z-15\nN40 X20 Z-20\nN50 X40\n";
  const auto typeI = run("G00 X40 Z2\nG71 P10 Q50 F0.2\nN10 G00 X20\n" + pocket);
  expectError(typeI, 6, 1, "type I contour must be monotonic");
  const auto typeII = run("G00 X40 Z2\nG71 P10 Q50 F0.2\nN10 G00 X20 W0\n" + pocket);
  EXPECT_TRUE(typeII.ok()) << typeII.diagnostics[0].message;
}

// ---- errors ----

constexpr std::string_view kContour = "M30\nN10 G00 X20\nN20 G01 Z-10 F0.1\n";

std::string withContour(std::string_view cycle) {
  return fmt::format("G00 X60 Z2\n{}\n{}", cycle, kContour);
}

TEST(CompoundCycleErrors, MissingQ) {
  expectError(run(withContour("G70 P10")), 2, 1,
              "G70 needs P(ns) and Q(nf), the N numbers of the contour's first and last blocks; "
              "Q is missing");
}

TEST(CompoundCycleErrors, SequenceNumberNotFound) {
  expectError(run(withContour("G70 P10 Q99")), 2, 9, "G70 Q99: there is no block N99 in this program");
}

TEST(CompoundCycleErrors, LastBeforeFirst) {
  expectError(run(withContour("G73 P20 Q10 F0.2")), 2, 9, "G73 P20 Q10: N10 comes before N20");
}

TEST(CompoundCycleErrors, ForbiddenGCodeInTheContour) {
  expectError(run("G00 X60 Z2\nG70 P10 Q20\nM30\nN10 G00 X20\nN20 G90 X30 Z-10 F0.1\n"), 5, 5,
              "G90 is not allowed in the contour of G70 (N10–N20): only G00–G03, G04, G96/G97, "
              "G98/G99 and G40–G42");
}

TEST(CompoundCycleErrors, SubprogramCallInTheContour) {
  expectError(run("G00 X60 Z2\nG70 P10 Q20\nM30\nN10 G00 X20\nN20 M98 P1000\n"), 5, 5,
              "M98 is not allowed in the contour of G70 (N10–N20)");
}

TEST(CompoundCycleErrors, FirstBlockNotG00OrG01) {
  expectError(run("G00 X60 Z2\nG70 P10 Q20\nM30\nN10 X20\nN20 G01 Z-10 F0.1\n"), 4, 1,
              "the first block of the contour of G70 (N10–N20) must hold G00 or G01");
}

TEST(CompoundCycleErrors, DuplicateSequenceNumberInTheContour) {
  expectError(
      run("G00 X60 Z2\nG70 P10 Q30\nM30\nN10 G00 X20\nN20 G01 Z-10 F0.1\nN20 X30\nN30 Z-20\n"), 6,
      1, "N20 appears twice in the contour of G70 (N10–N30)");
}

TEST(CompoundCycleErrors, MoreThan200ContourBlocks) {
  // N1 … N201: 201 blocks.
  std::string program = "G00 X60 Z2\nG70 P1 Q201\nM30\nN1 G01 X20 F0.1\n";
  for (int n = 2; n <= 201; ++n) program += fmt::format("N{} W-0.1\n", n);
  expectError(run(program), 2, 1, "the contour of G70 (N1–N201) has 201 blocks; at most 200");
}

TEST(CompoundCycleErrors, ErrorInsideTheContourIsLocatedThere) {
  // N20's arc is too short for its chord: G71 fails where it is written.
  expectError(run("G00 X60 Z2\nG71 U1 R0.5\nG71 P10 Q20 F0.2\nN10 G00 X20\nN20 G02 X30 Z-10 R1\n"), 5, 18,
              "R1 is too small");
}

TEST(CompoundCycleErrors, RoughingDepthMustBePositive) {
  expectError(run("G71 U0 R0.5\n"), 1, 5, "G71 U0 is not a depth of cut Δd: expected a number > 0");
}

TEST(CompoundCycleErrors, PatternPassesMustBeAWholeNumber) {
  expectError(run("G73 U2 W0 R0\n"), 1, 11, "G73 R0 is not a number of passes d");
}

TEST(CompoundCycleErrors, CycleWithoutFeed) {
  expectError(run("G00 X0 Z2\nG74 Z-20 Q8000\n"), 2, 1, "feed rate F is not set: G74 cuts at feed");
}

TEST(CompoundCycleErrors, PeckEndGivenTwice) {
  expectError(run("G00 X0 Z2\nG74 Z-20 W-22 Q8000 F0.1\n"), 2, 10,
              "Z-20 and W-22 both give the Z axis; give one of them");
}

TEST(CompoundCycleErrors, NegativeRetract) {
  expectError(run("G71 U1 R-1\n"), 1, 8, "G71 R-1 is not a retract distance e: expected a number ≥ 0");
}

TEST(CompoundCycleErrors, SequenceNumberWithADecimalPoint) {
  expectError(run(withContour("G70 P10.5 Q20")), 2, 5, "P10.5 is not a sequence number");
}

TEST(CompoundCycleErrors, ContourWithoutAMove) {
  // N10 goes to X60, where the tool already is; N20 only sets F.
  expectError(run("G00 X60 Z2\nG73 P10 Q20 F0.2\nN10 G00 X60\nN20 F0.1\n"), 2, 1,
              "the contour of G73 makes no move from the cycle start point");
}

TEST(CompoundCycleErrors, ContourCycleOnItsOwn) {
  // A block run without its program (as the contour blocks themselves are) cannot reach a
  // contour.
  RawBlock raw;
  raw.line = 1;
  raw.column = 1;
  raw.chars = {{"G", 1}, {"7", 2}, {"0", 3}, {"P", 4}, {"1", 5}, {"Q", 6}, {"2", 7}};
  auto words = tokenize(raw);
  ASSERT_TRUE(words.ok());
  auto block = parseBlock(words.value(), 1, 1);
  ASSERT_TRUE(block.ok());
  ModalState state;
  state.feed = 0.1;
  const auto outcome = executeBlock(block.value(), state, test::defaultOptions(), 0);
  ASSERT_FALSE(outcome.ok());
  EXPECT_NE(outcome.error().message.find("G70 needs its contour blocks, but this block is run "
                                         "on its own"),
            std::string::npos)
      << outcome.error().message;
}

TEST(CompoundCycleErrors, PeckDepthMissing) {
  expectError(run("G00 X0 Z2\nG74 Z-20 F0.1\n"), 2, 1,
              "G74 needs Q(Δk) > 0, the depth of each peck along Z");
}

TEST(CompoundCycleErrors, GrooveShiftMissingWhenZMoves) {
  expectError(run("G00 X42 Z-10\nG75 X30 Z-14 P4000 F0.05\n"), 2, 1,
              "G75 needs Q(Δk) > 0, the Z shift between plunges, because the end point's Z "
              "differs from the start");
}

}  // namespace
}  // namespace lathesim::interp

namespace lathesim::interp {
namespace {

// `N01;` holding nothing but its number is a label a P or Q may name: the contour then opens
// with the block after it (which holds the G00/G01) or closes with the label.
TEST(ContourLabels, EmptyNumberedBlocksAsPAndQGiveTheSameCycles) {
  const std::string plain =
      "G99 G00 X40 Z2 S500 M03\nG71 U2 R0.5\nG71 P10 Q30 U0 W0 F0.2\n"
      "N10 G00 X30\nN20 G01 Z-10 F0.1\nN30 X40\nG70 P10 Q30\nM30\n";
  const std::string labelled =
      "G99 G00 X40 Z2 S500 M03\nG71 U2 R0.5\nG71 P01 Q02 U0 W0 F0.2\n"
      "N01;\nG00 X30\nG01 Z-10 F0.1\nX40\nN02;\nG70 P01 Q02\nM30\n";
  const auto a = test::run(plain);
  const auto b = test::run(labelled);
  ASSERT_TRUE(a.ok()) << a.diagnostics[0].message;
  ASSERT_TRUE(b.ok()) << b.diagnostics[0].message;
  ASSERT_EQ(a.toolpath.moves.size(), b.toolpath.moves.size());
  for (std::size_t i = 0; i < a.toolpath.moves.size(); ++i) {
    EXPECT_EQ(a.toolpath.moves[i].from, b.toolpath.moves[i].from) << i;
    EXPECT_EQ(a.toolpath.moves[i].to, b.toolpath.moves[i].to) << i;
    EXPECT_EQ(a.toolpath.moves[i].kind, b.toolpath.moves[i].kind) << i;
  }
}

TEST(ContourLabels, TheBlockAfterALabelMustStillBeG00OrG01) {
  test::expectError(test::run("G00 X40 Z2\nG71 U2 R0.5\nG71 P01 Q02 F0.2\nN01;\nG02 X30 Z-5 R5\nN02 X40;\n"), 5, 1,
                    "must hold G00 or G01");
}

}  // namespace
}  // namespace lathesim::interp
