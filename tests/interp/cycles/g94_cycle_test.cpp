// G94 face cycle: the four sign cases of GSK980TDi 3.21.2, expanded by hand.
// A is the start, C the end, R the taper; B = (X_A, Z_C + R), D = (X_C, Z_A).

#include "interp/cycles/g94_cycle.hpp"

#include <gtest/gtest.h>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::Expected;
using test::expectLegs;
using test::kFeed;
using test::kRapid;

// Case 1: U>0 W<0 R<0. A = X20 Z0 (radius 10), C = X60 Z-10 (radius 30), R-5: B = (10, -15).
TEST(FaceCycleLegs, OutwardWithNegativeTaper) {
  expectLegs(faceCycleLegs(RZ(10, 0), RZ(30, -10), -5),
             {{kRapid, 10, 0, 10, -15, 0, 1},
              {kFeed, 10, -15, 30, -10, 0, 2},
              {kFeed, 30, -10, 30, 0, 0, 3},
              {kRapid, 30, 0, 10, 0, 0, 4}});
}

// Case 2: U<0 W<0 R<0. A = X60 Z0, C = X20 Z-10, R-5: B = (30, -15), D = (10, 0).
TEST(FaceCycleLegs, InwardWithNegativeTaper) {
  expectLegs(faceCycleLegs(RZ(30, 0), RZ(10, -10), -5),
             {{kRapid, 30, 0, 30, -15, 0, 1},
              {kFeed, 30, -15, 10, -10, 0, 2},
              {kFeed, 10, -10, 10, 0, 0, 3},
              {kRapid, 10, 0, 30, 0, 0, 4}});
}

// Case 3: U>0 W<0 R>0, |R| ≤ |W|. A = X20 Z0, C = X60 Z-10, R4: B = (10, -6).
TEST(FaceCycleLegs, OutwardWithPositiveTaper) {
  expectLegs(faceCycleLegs(RZ(10, 0), RZ(30, -10), 4),
             {{kRapid, 10, 0, 10, -6, 0, 1},
              {kFeed, 10, -6, 30, -10, 0, 2},
              {kFeed, 30, -10, 30, 0, 0, 3},
              {kRapid, 30, 0, 10, 0, 0, 4}});
  EXPECT_FALSE(faceCycleTaperProblem(-10, 4));
}

// Case 4: U<0 W<0 R>0, |R| ≤ |W|. A = X60 Z0, C = X20 Z-10, R4: B = (30, -6).
TEST(FaceCycleLegs, InwardWithPositiveTaper) {
  expectLegs(faceCycleLegs(RZ(30, 0), RZ(10, -10), 4),
             {{kRapid, 30, 0, 30, -6, 0, 1},
              {kFeed, 30, -6, 10, -10, 0, 2},
              {kFeed, 10, -10, 10, 0, 0, 3},
              {kRapid, 10, 0, 30, 0, 0, 4}});
}

// R = -W puts B at A's Z: step 1 has no length and is left out.
TEST(FaceCycleLegs, ZeroLengthLegIsLeftOut) {
  expectLegs(faceCycleLegs(RZ(30, 0), RZ(10, -10), 10),
             {{kFeed, 30, 0, 10, -10, 0, 2},
              {kFeed, 10, -10, 10, 0, 0, 3},
              {kRapid, 10, 0, 30, 0, 0, 4}});
}

TEST(FaceCycleTaper, OppositeSignsNeedRNoLongerThanW) {
  EXPECT_FALSE(faceCycleTaperProblem(-10, 10));
  EXPECT_FALSE(faceCycleTaperProblem(-10, -30));  // same signs: any length
  EXPECT_FALSE(faceCycleTaperProblem(10, 30));
  EXPECT_FALSE(faceCycleTaperProblem(-10, 0));
  const auto problem = faceCycleTaperProblem(-10, 12);
  ASSERT_TRUE(problem);
  EXPECT_EQ(*problem,
            "R12 and W-10 have opposite signs and |R| > |W|; G94 needs |R| ≤ |W| (W is the end "
            "Z minus the start Z)");
  EXPECT_TRUE(faceCycleTaperProblem(5, -5.5));
}

// The same cases through the interpreter, written with U and W.
TEST(FaceCycleProgram, IncrementalEndPointCase2) {
  const auto result = test::run("G00 X60 Z0\nG94 U-40 W-10 R-5 F0.1\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  test::expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 30, 0, 0, 0},
                                            {kRapid, 30, 0, 30, -15, 0, 1},
                                            {kFeed, 30, -15, 10, -10, 0.1, 2},
                                            {kFeed, 10, -10, 10, 0, 0.1, 3},
                                            {kRapid, 10, 0, 30, 0, 0, 4}});
}

TEST(FaceCycleProgram, IncrementalEndPointCase3) {
  const auto result = test::run("G00 X20 Z0\nG94 U40 W-10 R4 F0.1\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  test::expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 10, 0, 0, 0},
                                            {kRapid, 10, 0, 10, -6, 0, 1},
                                            {kFeed, 10, -6, 30, -10, 0.1, 2},
                                            {kFeed, 30, -10, 30, 0, 0.1, 3},
                                            {kRapid, 30, 0, 10, 0, 0, 4}});
}

TEST(FaceCycleProgram, TaperAlarmPointsAtR) {
  const auto result = test::run("G00 X60 Z0\nG94 X20 Z-10 R12 F0.1\n");
  test::expectError(result, 2, 14, "R12 and W-10 have opposite signs and |R| > |W|");
  EXPECT_EQ(result.toolpath.moves.size(), 1u);  // the failing block made no move
}

}  // namespace
}  // namespace lathesim::interp
