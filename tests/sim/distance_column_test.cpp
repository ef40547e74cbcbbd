// The column distance kernel the stock is cut with (RevolvedRegion::signedDistanceColumn):
// its values against distances worked out by hand, on both sides of the boundary, past
// an edge's ends (nearest point a vertex) and beside them (nearest point on the edge); and the
// same kernel read through a plan of its place (RevolvedRegion::planColumn), to the last bit.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

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

// A turning tool as the simulation sweeps it: a 55° rhombic insert's nose, rounded by r in
// chords, and its two flanks running 12 mm back.
ConvexPolygon insertAt(const RZ& nose, double r) {
  std::vector<RZ> points;
  for (int k = 0; k <= 24; ++k) {
    const double a = std::numbers::pi * (0.9 + 0.9 * k / 24.0);
    points.push_back(nose + RZ(r * std::cos(a), r * std::sin(a)));
  }
  points.push_back(nose + RZ(12.0 * std::cos(0.9 * std::numbers::pi), 12.0 * std::sin(0.9 * std::numbers::pi)));
  points.push_back(nose + RZ(12.0, -1.0));
  return ConvexPolygon::hullOf(points);
}

TEST(DistanceColumn, PlannedPlaceGivesTheWholeSearchsValuesToTheLastBit) {
  // Sweeps of every direction (a CAM contour's short steps, a facing pass, a plunge), single
  // and in unions, a piece reaching across the axis and a bare segment (both searched whole),
  // read at the radii of a voxel-wide bin of classes and the Z of a leaf's column, at voxel
  // sizes 0.05–0.2 mm, with the band as cap and with none.
  std::mt19937 random(20261129);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int planned = 0, compared = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const double h = 0.05 + 0.15 * unit(random);
    const RZ from(2.0 + 30.0 * unit(random), -40.0 * unit(random));
    const double angle = 2.0 * std::numbers::pi * unit(random);
    const double length = trial % 3 == 0 ? 0.03 : 5.0 * unit(random);
    const RZ to = from + length * RZ(std::cos(angle), std::sin(angle));
    const ConvexPolygon tool = insertAt(RZ(0, 0), 0.2 + 1.4 * unit(random));
    std::vector<ConvexPolygon> pieces{tool.sweptAlong(from, to)};
    if (trial % 4 == 1) pieces.push_back(tool.sweptAlong(to, to + RZ(0.5, -0.7)));
    if (trial % 10 == 2) pieces.push_back(ConvexPolygon::hullOf(std::vector<RZ>{{-1.0, from.y()}, {1.5, from.y() + 0.3}, {1.0, from.y() - 2.0}}));
    if (trial % 10 == 3) pieces.push_back(ConvexPolygon::hullOf(std::vector<RZ>{from, from + RZ(0.4, 0.9)}));
    const RevolvedRegion region(pieces);
    for (int place = 0; place < 40; ++place) {
      // A bin of class radii [b·h, (b + 1)·h) and a leaf column's first Z index near the cut.
      const double rhoBin = std::floor((from.x() + 3.0 * (unit(random) - 0.5)) / h) * h;
      const double rhoLow = rhoBin + 0.5 * h * unit(random), rhoHigh = rhoBin + h * (0.5 + 0.5 * unit(random));
      const double z0 = std::floor((from.y() + 4.0 * (unit(random) - 0.5)) / h / 8.0) * 8.0 * h;
      RevolvedRegion::ColumnPlan plan;
      region.planColumn(rhoLow, rhoHigh, z0, h, plan);
      for (const double cap : {3.0 * h, 1e9})
        for (int c = 0; c <= 10; ++c) {
          const double rho = c == 10 ? rhoHigh : rhoLow + (rhoHigh - rhoLow) * c / 10.0;
          double whole[RevolvedRegion::kColumn], read[RevolvedRegion::kColumn];
          region.signedDistanceColumn(rho, z0, h, cap, whole);
          region.signedDistanceColumn(plan, rho, cap, read);
          for (int k = 0; k < RevolvedRegion::kColumn; ++k) {
            ASSERT_EQ(read[k], whole[k]) << "trial " << trial << ", ρ " << rho << ", z " << z0 + k * h << ", cap " << cap;
            ++compared;
          }
        }
      planned += plan.plannedPieces();
    }
  }
  // The plan must be taken for most pieces, or the comparison above proves little.
  EXPECT_GT(planned, 400 * 40 / 2) << compared << " values compared";
}

}  // namespace
}  // namespace lathesim
