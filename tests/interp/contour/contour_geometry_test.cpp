// Contour geometry shared by the compound cycles: translation by the allowance, exchanging the
// axes, and where segments meet a level X = const. Values worked out by hand.

#include "interp/contour/contour_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../cycles/roughing_test_support.hpp"

namespace lathesim::interp {
namespace {

using test::arcSegment;
using test::segment;

using test::kFeed;
using test::kCw;
using test::kCcw;

void expectPoint(const RZ& actual, double r, double z) {
  EXPECT_NEAR(actual.x(), r, 1e-9);
  EXPECT_NEAR(actual.y(), z, 1e-9);
}

// Translating by (0.25, 0.1) moves ends and centre alike; the radius stays 10.
TEST(TranslatedContour, MovesEndsAndCentresAlike) {
  const Contour contour = {segment(kFeed, 10, 2, 10, -10, 10),
                           arcSegment(kCw, 10, -10, 20, -20, 20, -10, 20)};
  const Contour moved = translatedContour(contour, RZ(0.25, 0.1));
  ASSERT_EQ(moved.size(), 2u);
  expectPoint(moved[0].from, 10.25, 2.1);
  expectPoint(moved[0].to, 10.25, -9.9);
  expectPoint(moved[1].from, 10.25, -9.9);
  expectPoint(moved[1].to, 20.25, -19.9);
  expectPoint(moved[1].center, 20.25, -9.9);
  EXPECT_EQ(moved[1].kind, kCw);
  EXPECT_EQ(moved[1].line, 20);
  EXPECT_NEAR((moved[1].from - moved[1].center).norm(), 10, 1e-9);
}

TEST(SwappedAxes, ExchangesCoordinatesAndTheSenseOfArcs) {
  const Contour contour = {arcSegment(kCw, 10, -10, 20, -20, 20, -10, 30)};
  const Contour swapped = swappedAxes(contour);
  expectPoint(swapped[0].from, -10, 10);
  expectPoint(swapped[0].to, -20, 20);
  expectPoint(swapped[0].center, -10, 20);
  EXPECT_EQ(swapped[0].kind, kCcw);
  const Contour back = swappedAxes(swapped);
  expectPoint(back[0].center, 20, -10);
  EXPECT_EQ(back[0].kind, kCw);
}

// From (10, -10) about (20, -10): the start lies at angle atan2(-10, 0) = -π/2; G02 to
// (20, -20) at angle atan2(0, -10) = π turns a quarter (clockwise, -π/2 → -π).
TEST(ArcSweep, QuarterTurnAndItsInsideDirections) {
  const ContourSegment arc = arcSegment(kCw, 10, -10, 20, -20, 20, -10, 30);
  EXPECT_NEAR(arcSweepRad(arc), std::numbers::pi / 2, 1e-12);
  EXPECT_TRUE(arcPassesAngleInside(arc, -3 * std::numbers::pi / 4));
  EXPECT_FALSE(arcPassesAngleInside(arc, -std::numbers::pi / 2));  // its start: not inside
  EXPECT_FALSE(arcPassesAngleInside(arc, 0));
  // The same ends counter-clockwise go the long way round: three quarters.
  ContourSegment ccw = arc;
  ccw.kind = kCcw;
  EXPECT_NEAR(arcSweepRad(ccw), 3 * std::numbers::pi / 2, 1e-12);
  EXPECT_TRUE(arcPassesAngleInside(ccw, 0));
}

TEST(LevelCrossings, StraightSegments) {
  // (20, -30) → (30, -40) meets X = 28 at t = 0.8: Z = -38.
  const auto taper = levelCrossings(segment(kFeed, 20, -30, 30, -40, 1), 28);
  ASSERT_EQ(taper.size(), 1u);
  expectPoint(taper[0], 28, -38);
  EXPECT_TRUE(levelCrossings(segment(kFeed, 20, -30, 30, -40, 1), 31).empty());
  // A segment lying on the level gives both its ends.
  const auto onLevel = levelCrossings(segment(kFeed, 30, -40, 30, -60, 1), 30);
  ASSERT_EQ(onLevel.size(), 2u);
  expectPoint(onLevel[0], 30, -40);
  expectPoint(onLevel[1], 30, -60);
}

// The half circle G02 (20, -10) → (20, -20) about (20, -15), radius 5, dips to X 15:
// X = 17 at Z = -15 ± 4, met first at -11 then at -19 along the arc.
TEST(LevelCrossings, ArcInOrderAlongIt) {
  const ContourSegment groove = arcSegment(kCw, 20, -10, 20, -20, 20, -15, 1);
  const auto both = levelCrossings(groove, 17);
  ASSERT_EQ(both.size(), 2u);
  expectPoint(both[0], 17, -11);
  expectPoint(both[1], 17, -19);
  // At its bottom the level touches once; above the circle's top half it misses (the top
  // half is not on this arc).
  const auto bottom = levelCrossings(groove, 15);
  ASSERT_EQ(bottom.size(), 1u);
  expectPoint(bottom[0], 15, -15);
  EXPECT_TRUE(levelCrossings(groove, 23).empty());
  // Its ends lie on X = 20.
  const auto ends = levelCrossings(groove, 20);
  ASSERT_EQ(ends.size(), 2u);
  expectPoint(ends[0], 20, -10);
  expectPoint(ends[1], 20, -20);
}

}  // namespace
}  // namespace lathesim::interp
