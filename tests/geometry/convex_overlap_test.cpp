#include "geometry/convex_overlap.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <random>
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

double areaOf(const std::vector<ConvexPolygon>& pieces) {
  double area = 0.0;
  for (const ConvexPolygon& piece : pieces) area += piece.area();
  return area;
}

TEST(ConvexDifference, SquareMinusAnOverlappingSquare) {
  // [0,2]² \ [1,3]²: an L of area 3, the two pieces not overlapping.
  const auto pieces = differenceOf(box(0, 0, 2, 2), box(1, 1, 3, 3));
  EXPECT_NEAR(areaOf(pieces), 3.0, 1e-12);
}

TEST(ConvexDifference, CoveredOrSharingOnlyABoundaryIsEmpty) {
  EXPECT_TRUE(differenceOf(box(1, 1, 2, 2), box(0, 0, 3, 3)).empty());
  EXPECT_TRUE(differenceOf(box(0, 0, 1, 1), box(0, 0, 1, 1)).empty());
  // Disjoint: all of a is left.
  EXPECT_NEAR(areaOf(differenceOf(box(0, 0, 1, 1), box(2, 2, 3, 3))), 1.0, 1e-12);
}

TEST(ConvexDifference, RandomPolygonsSplitIntoTheOverlapAndTheDifference) {
  // Random hulls: the pieces and the overlap tile a (areas add up), every sample of a lies in
  // b or in a piece, and no sample outside a lies in a piece.
  std::mt19937 random(14);
  std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<RZ> pa, pb;
    for (int i = 0; i < 7; ++i) pa.emplace_back(coordinate(random), coordinate(random));
    for (int i = 0; i < 5; ++i) pb.emplace_back(coordinate(random) + 0.5, coordinate(random));
    const ConvexPolygon a = ConvexPolygon::hullOf(pa), b = ConvexPolygon::hullOf(pb);
    const auto pieces = differenceOf(a, b);
    EXPECT_NEAR(areaOf(pieces) + overlapOf(a, b).areaMm2, a.area(), 1e-9) << trial;
    for (int s = 0; s < 200; ++s) {
      const RZ p(coordinate(random), coordinate(random));
      bool inPiece = false;
      for (const ConvexPolygon& piece : pieces) inPiece |= piece.signedDistance(p) < -1e-9;
      if (a.signedDistance(p) < -1e-9 && b.signedDistance(p) > 1e-9) {
        EXPECT_TRUE(inPiece) << trial;
      }
      if (a.signedDistance(p) > 1e-9 || b.signedDistance(p) < -1e-9) {
        EXPECT_FALSE(inPiece) << trial;
      }
    }
  }
}

}  // namespace
}  // namespace lathesim
