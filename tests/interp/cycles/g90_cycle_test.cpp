// G90 axial cycle: the four sign cases (U<0/U>0 with R<0/R>0), expanded by hand.
// A is the start, C the end, R the taper as a radius; B = (X_C + 2R, Z_A), D = (X_A, Z_C).
// Positions below are (radius, Z), so B's radius is r_C + R.

#include "interp/cycles/g90_cycle.hpp"

#include <gtest/gtest.h>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::Expected;
using test::expectLegs;
using test::expectError;
using test::expectMoves;
using test::kFeed;
using test::kRapid;
using test::run;

// Case 1: U<0 R<0, the usual OD taper. A = X60 Z2 (radius 30), C = X40 Z-20 (radius 20),
// B = (X30, Z2) = radius 15, D = (30, -20).
TEST(AxialCycleLegs, InwardWithNegativeTaper) {
  expectLegs(axialCycleLegs(RZ(30, 2), RZ(20, -20), -5),
             {{kRapid, 30, 2, 15, 2, 0, 1},
              {kFeed, 15, 2, 20, -20, 0, 2},
              {kFeed, 20, -20, 30, -20, 0, 3},
              {kRapid, 30, -20, 30, 2, 0, 4}});
}

// Case 2: U<0 R>0, |R| ≤ |U/2| (4 ≤ 10). A = X60 Z2, C = X40 Z-20, R4: B = radius 24.
TEST(AxialCycleLegs, InwardWithPositiveTaper) {
  expectLegs(axialCycleLegs(RZ(30, 2), RZ(20, -20), 4),
             {{kRapid, 30, 2, 24, 2, 0, 1},
              {kFeed, 24, 2, 20, -20, 0, 2},
              {kFeed, 20, -20, 30, -20, 0, 3},
              {kRapid, 30, -20, 30, 2, 0, 4}});
  EXPECT_FALSE(axialCycleTaperProblem(-20, 4));
}

// Case 3: U>0 R>0, an ID taper. A = X20 Z2 (radius 10), C = X40 Z-20 (radius 20), R3:
// B = radius 23, D = (10, -20).
TEST(AxialCycleLegs, OutwardWithPositiveTaper) {
  expectLegs(axialCycleLegs(RZ(10, 2), RZ(20, -20), 3),
             {{kRapid, 10, 2, 23, 2, 0, 1},
              {kFeed, 23, 2, 20, -20, 0, 2},
              {kFeed, 20, -20, 10, -20, 0, 3},
              {kRapid, 10, -20, 10, 2, 0, 4}});
}

// Case 4: U>0 R<0, |R| ≤ |U/2| (4 ≤ 10). A = X20 Z2, C = X40 Z-20, R-4: B = radius 16.
TEST(AxialCycleLegs, OutwardWithNegativeTaper) {
  expectLegs(axialCycleLegs(RZ(10, 2), RZ(20, -20), -4),
             {{kRapid, 10, 2, 16, 2, 0, 1},
              {kFeed, 16, 2, 20, -20, 0, 2},
              {kFeed, 20, -20, 10, -20, 0, 3},
              {kRapid, 10, -20, 10, 2, 0, 4}});
  EXPECT_FALSE(axialCycleTaperProblem(20, -4));
}

// R = -U/2 puts B at A's X: step 1 has no length and is left out.
TEST(AxialCycleLegs, ZeroLengthLegIsLeftOut) {
  expectLegs(axialCycleLegs(RZ(30, 2), RZ(20, -20), 10),
             {{kFeed, 30, 2, 20, -20, 0, 2},
              {kFeed, 20, -20, 30, -20, 0, 3},
              {kRapid, 30, -20, 30, 2, 0, 4}});
}

TEST(AxialCycleTaper, OppositeSignsNeedRNoLongerThanHalfU) {
  EXPECT_FALSE(axialCycleTaperProblem(-20, 10));   // |R| = |U/2|: allowed
  EXPECT_FALSE(axialCycleTaperProblem(-20, -30));  // same signs: any length
  EXPECT_FALSE(axialCycleTaperProblem(20, 30));
  EXPECT_FALSE(axialCycleTaperProblem(-20, 0));
  const auto problem = axialCycleTaperProblem(-20, 12);
  ASSERT_TRUE(problem);
  EXPECT_EQ(*problem,
            "R12 and U-20 have opposite signs and |R| > |U/2|; G90 needs |R| ≤ |U/2| (U is the "
            "end X minus the start X, a diameter; R is a radius)");
  EXPECT_TRUE(axialCycleTaperProblem(20, -10.5));
  EXPECT_FALSE(axialCycleTaperProblem(20, -10));
}

// The cases through the interpreter, written with U and W.
TEST(AxialCycleProgram, IncrementalEndPointCase1) {
  const auto result = run("G00 X60 Z2\nG90 U-20 W-22 R-5 F0.2\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 30, 2, 0, 0},
                                      {kRapid, 30, 2, 15, 2, 0, 1},
                                      {kFeed, 15, 2, 20, -20, 0.2, 2},
                                      {kFeed, 20, -20, 30, -20, 0.2, 3},
                                      {kRapid, 30, -20, 30, 2, 0, 4}});
}

TEST(AxialCycleProgram, IncrementalEndPointCase4) {
  const auto result = run("G00 X20 Z2\nG90 U20 W-22 R-4 F0.1\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 10, 2, 0, 0},
                                      {kRapid, 10, 2, 16, 2, 0, 1},
                                      {kFeed, 16, 2, 20, -20, 0.1, 2},
                                      {kFeed, 20, -20, 10, -20, 0.1, 3},
                                      {kRapid, 10, -20, 10, 2, 0, 4}});
}

TEST(AxialCycleProgram, TaperAlarmPointsAtR) {
  const auto result = run("G00 X60 Z2\nG90 X40 Z-20 R12 F0.1\n");
  expectError(result, 2, 14, "R12 and U-20 have opposite signs and |R| > |U/2|");
  EXPECT_EQ(result.toolpath.moves.size(), 1u);  // the failing block made no move
}

TEST(AxialCycleProgram, TaperAlarmWithRetainedRPointsAtX) {
  // R4 is kept; X56 makes U = -4, so |R| > |U/2| = 2.
  const auto result = run("G00 X60 Z2\nG90 X40 Z-20 R4 F0.1\nX56\n");
  expectError(result, 3, 1, "R4 and U-4 have opposite signs");
  EXPECT_EQ(result.toolpath.moves.size(), 5u);
}

// Seed 004: `G0 X60. Z1. G90 U-8. W-66. F0.23 ; U-16. ; U-24. ; U-32. ;`, with the `;`
// that G0 and G90 need between them (one block may hold only one group-01 code). Each U
// counts from A (X60), and W-66 is kept as the absolute Z-65.
TEST(AxialCycleProgram, ModalPassesWithOnlyU) {
  const auto result = run("G0 X60. Z1. ; G90 U-8. W-66. F0.23 ; U-16. ; U-24. ; U-32. ;");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  std::vector<Expected> expected{{kRapid, 100, 200, 30, 1, 0, 0}};
  for (double r : {26.0, 22.0, 18.0, 14.0}) {
    expected.push_back({kRapid, 30, 1, r, 1, 0, 1});
    expected.push_back({kFeed, r, 1, r, -65, 0.23, 2});
    expected.push_back({kFeed, r, -65, 30, -65, 0.23, 3});
    expected.push_back({kRapid, 30, -65, 30, 1, 0, 4});
  }
  expectMoves(result.toolpath.moves, expected);
}

// Seed 004: `G00 X65.0 Z2.0; G90 X60.0 Z-35.0 F0.5 ; X50.0 ;`: X50 keeps Z-35 and R-5.
TEST(AxialCycleProgram, ModalPassKeepsZAndR) {
  const auto result = run("G00 X65.0 Z2.0\nG90 X60.0 Z-35.0 R-5.0 F0.5\nX50.0\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 32.5, 2, 0, 0},
                                      {kRapid, 32.5, 2, 25, 2, 0, 1},
                                      {kFeed, 25, 2, 30, -35, 0.5, 2},
                                      {kFeed, 30, -35, 32.5, -35, 0.5, 3},
                                      {kRapid, 32.5, -35, 32.5, 2, 0, 4},
                                      {kRapid, 32.5, 2, 20, 2, 0, 1},
                                      {kFeed, 20, 2, 25, -35, 0.5, 2},
                                      {kFeed, 25, -35, 32.5, -35, 0.5, 3},
                                      {kRapid, 32.5, -35, 32.5, 2, 0, 4}});
}

TEST(AxialCycleProgram, NamingG90AgainKeepsTheRetainedValues) {
  const auto result = run("G00 X60 Z2\nG90 X50 Z-20 F0.2\nG90 X40\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  ASSERT_EQ(result.toolpath.moves.size(), 9u);
  expectMoves({result.toolpath.moves[6]}, {{kFeed, 20, 2, 20, -20, 0.2, 2}});
}

TEST(AxialCycleProgram, DwellKeepsTheRetainedValues) {
  const auto result = run("G00 X60 Z2\nG90 X50 Z-20 F0.2\nG04 X1.5\nX40\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  EXPECT_EQ(result.toolpath.moves.size(), 10u);  // 1 rapid, 4 legs, the dwell, 4 legs
}

TEST(AxialCycleProgram, RapidClearsTheRetainedValues) {
  const auto result = run("G00 X60 Z2\nG90 X50 Z-20 F0.2\nG00 X60 Z2\nG90 Z-30\n");
  expectError(result, 4, 1, "G90 needs X(U) and Z(W): the end point's X(U)");
}

TEST(AxialCycleProgram, G50ClearsTheRetainedValues) {
  const auto result = run("G00 X60 Z2\nG90 X50 Z-20 F0.2\nG50 X60 Z2\nX40\n");
  expectError(result, 4, 1, "G90 needs X(U) and Z(W): the end point's Z(W)");
}

TEST(AxialCycleProgram, SwitchingBetweenG90AndG94ClearsTheRetainedValues) {
  // G90 → G94: the G90 block's Z-20 is not kept for the face cycle.
  expectError(run("G00 X60 Z2\nG90 X50 Z-20 F0.2\nG94 X40\n"), 3, 1,
              "G94 needs X(U) and Z(W): the end point's Z(W) is neither in this block nor kept "
              "from an earlier G94 block");
  // G94 → G90: the G94 block's X50 is not kept for the axial cycle.
  expectError(run("G00 X60 Z2\nG94 X50 Z-5 F0.2\nG90 Z-20\n"), 3, 1,
              "G90 needs X(U) and Z(W): the end point's X(U)");
}

TEST(AxialCycleProgram, NeedsXAndZ) {
  expectError(run("G00 X100 Z2\nG90 X20 F0.1\n"), 2, 1,
              "G90 needs X(U) and Z(W): the end point's Z(W) is neither in this block nor "
              "kept from an earlier G90 block");
  expectError(run("G00 X100 Z2\nG90 W-20 F0.1\n"), 2, 1, "the end point's X(U)");
}

TEST(AxialCycleProgram, FeedMustBeSet) {
  expectError(run("G00 X100 Z5\nG90 X50 Z-5\n"), 2, 1,
              "feed rate F is not set: G90 cuts at feed");
}

TEST(AxialCycleProgram, G17OrG19SaysThereIsNoYAxis) {
  expectError(run("G00 X100 Z5\nG17 G90 X50 Z-5 F0.1\n"), 2, 5,
              "G90 under G17: this machine has no Y axis");
  expectError(run("G19\nG00 X100 Z5 F0.1\nG90 X50 Z-5\n"), 3, 1,
              "G90 under G19: this machine has no Y axis");
}

}  // namespace
}  // namespace lathesim::interp
