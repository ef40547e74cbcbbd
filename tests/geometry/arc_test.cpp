// Arcs of the (r, z) plane. Angles are read in the drawing view (Z to the right, r up).

#include "geometry/arc.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lathesim {
namespace {

void expectPoint(const RZ& actual, double r, double z, double tolerance = 1e-12) {
  EXPECT_NEAR(actual.x(), r, tolerance);
  EXPECT_NEAR(actual.y(), z, tolerance);
}

// A convex corner round: centre (r15, z-5), radius 5, from straight above the centre
// (20, -5) to straight right of it (15, 0) — a quarter turn clockwise in the drawing view.
const Arc kCornerRound({20, -5}, {15, 0}, {15, -5}, true);

TEST(Arc, QuarterTurnClockwise) {
  EXPECT_NEAR(kCornerRound.sweepRad(), M_PI / 2, 1e-12);
  EXPECT_NEAR(kCornerRound.lengthMm(), 5 * M_PI / 2, 1e-12);  // 7.853982
  // Halfway: 45° from both ends, (15 + 5·cos45°, -5 + 5·sin45°) = (18.535534, -1.464466).
  expectPoint(kCornerRound.pointAt(0.5), 15 + 5 * M_SQRT1_2, -5 + 5 * M_SQRT1_2);
  expectPoint(kCornerRound.pointAt(0), 20, -5);
  expectPoint(kCornerRound.pointAt(1), 15, 0);
  // Sagitta of a 90° arc: 5·(1 − cos45°) = 1.464466.
  EXPECT_NEAR(kCornerRound.sagittaMm(), 5 * (1 - M_SQRT1_2), 1e-12);
}

TEST(Arc, SameEndsCounterClockwiseGoTheLongWayRound) {
  // From above the centre counter-clockwise: left, down, right, then up to the end: 270°.
  const Arc major({20, -5}, {15, 0}, {15, -5}, false);
  EXPECT_NEAR(major.sweepRad(), 3 * M_PI / 2, 1e-12);
  EXPECT_NEAR(major.lengthMm(), 15 * M_PI / 2, 1e-12);
  // A third of 270° is 90°: straight left of the centre, (15, -10).
  expectPoint(major.pointAt(1.0 / 3), 15, -10);
}

TEST(Arc, StartEqualToEndIsAFullCircle) {
  const Arc circle({10, 0}, {10, 0}, {10, -4}, false);
  EXPECT_DOUBLE_EQ(circle.sweepRad(), 2 * M_PI);
  EXPECT_NEAR(circle.lengthMm(), 8 * M_PI, 1e-12);  // 2π·4
  // The start lies right of the centre (Z to the right); counter-clockwise a quarter turn
  // reaches the top, (14, -4), half a turn the left, (10, -8).
  expectPoint(circle.pointAt(0.25), 14, -4);
  expectPoint(circle.pointAt(0.5), 10, -8);
}

TEST(Arc, EndSlightlyOffTheCircleIsReachedExactly) {
  // Start radius 5, end radius 5.01: the radius grows linearly with the angle.
  const Arc arc({5, 0}, {0, 5.01}, {0, 0}, true);
  EXPECT_NEAR(arc.sweepRad(), M_PI / 2, 1e-12);
  EXPECT_NEAR(arc.lengthMm(), M_PI / 2 * 5.005, 1e-12);
  // Halfway: angle 45°, radius 5.005.
  expectPoint(arc.pointAt(0.5), 5.005 * M_SQRT1_2, 5.005 * M_SQRT1_2);
  expectPoint(arc.pointAt(1), 0, 5.01);
}

TEST(Arc, SplitKeepsEverySagittaWithinTheTolerance) {
  // Tolerance 0.01 mm on radius 5: each piece may sweep 2·acos(1 − 0.01/5) = 0.12654 rad,
  // and 90° = 1.570796 rad needs ceil(12.41) = 13 pieces of π/26 = 0.120831 rad, each with a
  // sagitta of 5·(1 − cos(π/52)) = 0.009122 mm.
  const std::vector<Arc> pieces = kCornerRound.split(0.01);
  ASSERT_EQ(pieces.size(), 13u);
  expectPoint(pieces.front().start(), 20, -5);
  expectPoint(pieces.back().end(), 15, 0);
  double totalSweep = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    SCOPED_TRACE(k);
    if (k > 0) {
      EXPECT_EQ(pieces[k].start(), pieces[k - 1].end());
    }
    EXPECT_TRUE(pieces[k].clockwise());
    EXPECT_EQ(pieces[k].center(), kCornerRound.center());
    EXPECT_NEAR(pieces[k].sweepRad(), M_PI / 26, 1e-12);
    EXPECT_NEAR(pieces[k].sagittaMm(), 0.009122, 1e-6);
    // The chord's midpoint lies the sagitta inside the circle.
    const RZ mid = 0.5 * (pieces[k].start() + pieces[k].end());
    EXPECT_NEAR((mid - kCornerRound.center()).norm(), 5 - 0.009122, 1e-6);
    totalSweep += pieces[k].sweepRad();
  }
  EXPECT_NEAR(totalSweep, M_PI / 2, 1e-12);
}

TEST(Arc, SplitOfAFullCircleAndOfACoarseTolerance) {
  // A tolerance beyond the radius still cuts a full circle in two half circles.
  const Arc circle({10, 0}, {10, 0}, {10, -4}, true);
  const std::vector<Arc> halves = circle.split(100);
  ASSERT_EQ(halves.size(), 2u);
  expectPoint(halves[0].end(), 10, -8);  // from right of the centre, half a turn: the left
  EXPECT_NEAR(halves[0].sweepRad(), M_PI, 1e-12);
  // Radius 4, tolerance 0.04: 2·acos(0.99) = 0.28379 rad per piece, 2π / 0.28379 = 22.14 → 23.
  EXPECT_EQ(circle.split(0.04).size(), 23u);
}

}  // namespace
}  // namespace lathesim
