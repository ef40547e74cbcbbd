// The column distance kernel the stock is cut with (RevolvedRegion::signedDistanceColumn):
// its values against distances worked out by hand, on both sides of the boundary, past
// an edge's ends (nearest point a vertex) and beside them (nearest point on the edge).

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/revolved_region.hpp"

namespace lathesim {
namespace {

constexpr double kCap = 100.0;  // far beyond every point here: all values exact

RevolvedRegion squareRegion() {
  // The square r 10..20, z 0..10.
  const std::vector<RZ> corners{{10, 0}, {20, 0}, {20, 10}, {10, 10}};
  return RevolvedRegion({ConvexPolygon::hullOf(corners)});
}

TEST(DistanceColumn, BesideAndPastTheSquaresOuterEdge) {
  double d[RevolvedRegion::kColumn];
  // ρ = 25, z = −3, −1, 1, …, 11: 5 mm out from the edge r = 20 while 0 ≤ z ≤ 10; below
  // and above it the nearest point is the corner (20, 0) or (20, 10):
  // z = −3: √(5² + 3²) = √34; z = −1: √26; z = 1…9: 5; z = 11: √26.
  squareRegion().signedDistanceColumn(25.0, -3.0, 2.0, kCap, d);
  const double expected[] = {std::sqrt(34.0), std::sqrt(26.0), 5, 5, 5, 5, 5, std::sqrt(26.0)};
  for (int k = 0; k < RevolvedRegion::kColumn; ++k) EXPECT_NEAR(d[k], expected[k], 1e-12) << "k = " << k;
}

TEST(DistanceColumn, InsideTheSquareIsMinusTheDepth) {
  double d[RevolvedRegion::kColumn];
  // ρ = 12, z = 0.5, 1.5, …, 7.5: depth min(ρ − 10, 20 − ρ, z, 10 − z) = min(2, z):
  // 0.5, 1.5, 2, 2, 2, 2, 2, 2.
  squareRegion().signedDistanceColumn(12.0, 0.5, 1.0, kCap, d);
  const double expected[] = {-0.5, -1.5, -2, -2, -2, -2, -2, -2};
  for (int k = 0; k < RevolvedRegion::kColumn; ++k) EXPECT_NEAR(d[k], expected[k], 1e-12) << "k = " << k;
}

TEST(DistanceColumn, ObliqueEdgeAndItsVertices) {
  // Triangle (0, 0), (4, 0), (0, 3): hypotenuse from (4, 0) to (0, 3), length 5, outward
  // normal (3, 4)/5. Column at ρ = 4, z = −2, 0, 2, …, 12:
  // z = −2: nearest is the vertex (4, 0): 2.
  // z = 0: on the vertex: 0.
  // z = 2: (4, 2) − (4, 0) = (0, 2) lies along the hypotenuse's normal side: the foot of
  //   the perpendicular is at t = ((0,2)·(−4,3))/25 = 6/25 ∈ [0, 1], distance n·(p − a)
  //   = (3·0 + 4·2)/5 = 1.6.
  // z = 4: t = 12/25, distance (4·4)/5 = 3.2.
  // z = 6: t = 18/25, distance 24/5 = 4.8.
  // z = 8: t = 24/25, distance 32/5 = 6.4.
  // z = 10: t = 30/25 > 1: the vertex (0, 3): √(4² + 7²) = √65.
  // z = 12: the vertex (0, 3): √(16 + 81) = √97.
  const std::vector<RZ> corners{{0, 0}, {4, 0}, {0, 3}};
  const RevolvedRegion triangle({ConvexPolygon::hullOf(corners)});
  double d[RevolvedRegion::kColumn];
  triangle.signedDistanceColumn(4.0, -2.0, 2.0, kCap, d);
  const double expected[] = {2, 0, 1.6, 3.2, 4.8, 6.4, std::sqrt(65.0), std::sqrt(97.0)};
  for (int k = 0; k < RevolvedRegion::kColumn; ++k) EXPECT_NEAR(d[k], expected[k], 1e-12) << "k = " << k;
}

TEST(DistanceColumn, AgreesWithThePointwiseDistanceOfAUnion) {
  // Two overlapping tool sweeps; the column and the point-by-point distance are two
  // separate implementations of the same definition.
  const std::vector<RZ> a{{30, -5}, {42, -4}, {43, 8}, {31, 6}};
  const std::vector<RZ> b{{20, -30}, {32, -29}, {33, -17}, {35, -4}, {22, -5}};
  const RevolvedRegion region({ConvexPolygon::hullOf(a), ConvexPolygon::hullOf(b)});
  for (double rho = 15.0; rho <= 50.0; rho += 0.7)
    for (double z0 = -40.0; z0 <= 15.0; z0 += 3.3) {
      double d[RevolvedRegion::kColumn];
      region.signedDistanceColumn(rho, z0, 0.45, kCap, d);
      for (int k = 0; k < RevolvedRegion::kColumn; ++k)
        EXPECT_NEAR(d[k], region.signedDistance(rho, z0 + 0.45 * k, kCap), 1e-9) << rho << " " << z0 << " " << k;
    }
}

}  // namespace
}  // namespace lathesim
