#include "geometry/convex_polygon.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace lathesim {
namespace {

ConvexPolygon square(double size) {
  const std::vector<RZ> outline{{0, 0}, {size, 0}, {size, size}, {0, size}};
  return *ConvexPolygon::fromOutline(outline).polygon;
}

TEST(ConvexPolygon, SignedDistanceIsExactInsideAndOutside) {
  const ConvexPolygon p = square(10);
  EXPECT_DOUBLE_EQ(p.signedDistance({5, 5}), -5.0);
  EXPECT_DOUBLE_EQ(p.signedDistance({1, 5}), -1.0);
  EXPECT_DOUBLE_EQ(p.signedDistance({15, 5}), 5.0);
  EXPECT_DOUBLE_EQ(p.signedDistance({13, 14}), 5.0);  // nearest point is the corner (10,10)
  EXPECT_DOUBLE_EQ(p.signedDistance({10, 3}), 0.0);
}

TEST(ConvexPolygon, AcceptsClockwiseOutlineAndReordersIt) {
  const std::vector<RZ> clockwise{{0, 0}, {0, 4}, {4, 4}, {4, 0}};
  const auto checked = ConvexPolygon::fromOutline(clockwise);
  ASSERT_TRUE(checked.polygon);
  EXPECT_DOUBLE_EQ(checked.polygon->area(), 16.0);
}

TEST(ConvexPolygon, RejectsNonConvexOutline) {
  const std::vector<RZ> dart{{0, 0}, {10, 0}, {3, 3}, {0, 10}};
  const auto checked = ConvexPolygon::fromOutline(dart);
  EXPECT_FALSE(checked.polygon);
  EXPECT_NE(checked.problem.find("not convex"), std::string::npos) << checked.problem;
}

TEST(ConvexPolygon, RejectsSelfIntersectingOutline) {
  const std::vector<RZ> bowTie{{0, 0}, {10, 10}, {10, 0}, {0, 10}};
  const auto checked = ConvexPolygon::fromOutline(bowTie);
  EXPECT_FALSE(checked.polygon);
  EXPECT_NE(checked.problem.find("self-intersecting"), std::string::npos) << checked.problem;
}

TEST(ConvexPolygon, RejectsCollinearOutline) {
  const std::vector<RZ> line{{0, 0}, {1, 1}, {2, 2}};
  EXPECT_FALSE(ConvexPolygon::fromOutline(line).polygon);
}

TEST(ConvexPolygon, SweepOfSquareAlongDiagonalIsAHexagonOfKnownArea) {
  // A 2×2 square moved by (3, 4): area = 4 + |cross(move, diagonal)| = 4 + |3·2 − 4·2|... computed
  // as the Minkowski sum of the square and the segment: 4 + 2·|3| + 2·|4| = 18.
  const ConvexPolygon swept = square(2).sweptAlong({0, 0}, {3, 4});
  EXPECT_EQ(swept.vertices().size(), 6u);
  EXPECT_DOUBLE_EQ(swept.area(), 18.0);
}

TEST(ConvexPolygon, DegenerateHullsMeasurePlainDistance) {
  const std::vector<RZ> segment{{0, 0}, {4, 0}};
  const ConvexPolygon s = ConvexPolygon::hullOf(segment);
  EXPECT_DOUBLE_EQ(s.signedDistance({2, 3}), 3.0);
  EXPECT_DOUBLE_EQ(s.signedDistance({7, 4}), 5.0);
}

}  // namespace
}  // namespace lathesim
