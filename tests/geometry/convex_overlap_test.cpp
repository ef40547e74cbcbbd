#include "geometry/convex_overlap.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

namespace lathesim {
namespace {

ConvexPolygon box(double r0, double z0, double r1, double z1) {
  const std::vector<RZ> corners{{r0, z0}, {r1, z0}, {r1, z1}, {r0, z1}};
  return ConvexPolygon::hullOf(corners);
}

TEST(ConvexOverlap, OverlappingSquares) {
  // [0,2]² ∩ [1,3]² = [1,2]²: area 1, centroid (1.5, 1.5); revolved: 1·2π·1.5 = 3π.
  const Overlap o = overlapOf(box(0, 0, 2, 2), box(1, 1, 3, 3));
  EXPECT_NEAR(o.areaMm2, 1.0, 1e-12);
  EXPECT_TRUE(o.centroid.isApprox(RZ(1.5, 1.5)));
  EXPECT_NEAR(revolvedVolumeMm3(o), 3.0 * std::numbers::pi, 1e-12);
}

TEST(ConvexOverlap, TriangleClippedByASquare) {
  // The triangle (0,0) (4,0) (0,4) inside [0,2]²: the square minus nothing but its corner
  // beyond r + z = 4, which only touches at (2,2): area 4.
  const std::vector<RZ> t{{0, 0}, {4, 0}, {0, 4}};
  EXPECT_NEAR(overlapOf(ConvexPolygon::hullOf(t), box(0, 0, 2, 2)).areaMm2, 4.0, 1e-12);
  // Against [1,3]²: the part with r + z ≤ 4 is the triangle (1,1) (3,1) (1,3): area 2.
  EXPECT_NEAR(overlapOf(ConvexPolygon::hullOf(t), box(1, 1, 3, 3)).areaMm2, 2.0, 1e-12);
}

TEST(ConvexOverlap, DisjointOrTouchingIsEmpty) {
  EXPECT_EQ(overlapOf(box(0, 0, 1, 1), box(2, 2, 3, 3)).areaMm2, 0.0);
  EXPECT_EQ(overlapOf(box(0, 0, 1, 1), box(1, 0, 2, 1)).areaMm2, 0.0);
}

}  // namespace
}  // namespace lathesim
