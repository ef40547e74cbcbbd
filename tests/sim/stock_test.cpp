#include "sim/stock.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lathesim::sim {
namespace {

// Volume measured on a level set is exact up to the discretisation at the surface; a
// tolerance of a tenth of a voxel layer over the whole surface is generous yet tight enough
// to catch a wrong cut (which moves whole voxel layers).
double voxelTolerance(double surfaceMm2, double voxelMm) { return 0.1 * voxelMm * surfaceMm2; }

ConvexPolygon rectangle(double r0, double z0, double r1, double z1) {
  const std::vector<RZ> corners{{r0, z0}, {r1, z0}, {r1, z1}, {r0, z1}};
  return ConvexPolygon::hullOf(corners);
}

class StockAtVoxel : public ::testing::TestWithParam<double> {};

TEST_P(StockAtVoxel, BarVolumeIsTheCylinders) {
  const double h = GetParam();
  const StockSpec spec{50.0, 40.0, 2.0};
  Stock stock(spec, h);
  const double exact = M_PI * 25.0 * 25.0 * 40.0;
  const double surface = 2 * M_PI * 25 * 25 + 2 * M_PI * 25 * 40;
  EXPECT_NEAR(stock.volumeMm3(), exact, voxelTolerance(surface, h));
}

TEST_P(StockAtVoxel, TurningAShoulderRemovesTheRingExactly) {
  const double h = GetParam();
  Stock stock({50.0, 40.0, 2.0}, h);
  // Turn Φ50 → Φ30 from the face down to Z-20: a ring r 15..25, 22 mm long, removed.
  const double removed = stock.remove(RevolvedRegion({rectangle(15.0, -20.0, 40.0, 10.0)}));
  const double ring = M_PI * (25.0 * 25.0 - 15.0 * 15.0) * 22.0;
  const double surface = 2 * M_PI * 15 * 22 + M_PI * (25 * 25 - 15 * 15);
  EXPECT_NEAR(removed, ring, voxelTolerance(surface, h));
  const double remaining = M_PI * 25.0 * 25.0 * 40.0 - ring;
  EXPECT_NEAR(stock.volumeMm3(), remaining, voxelTolerance(surface + 2 * M_PI * 25 * 40, h));
}

TEST_P(StockAtVoxel, TaperLeavesAFrustum) {
  const double h = GetParam();
  Stock stock({50.0, 30.0, 0.0}, h);
  // Everything above the line from (r10, z0) to (r25, z-30) goes: a frustum stays.
  const std::vector<RZ> above{{10.0, 0.0}, {25.0, -30.0}, {40.0, -30.0}, {40.0, 5.0}, {10.0, 5.0}};
  stock.remove(RevolvedRegion({ConvexPolygon::hullOf(above)}));
  const double frustum = M_PI * 30.0 / 3.0 * (25.0 * 25.0 + 25.0 * 10.0 + 10.0 * 10.0);
  const double slant = std::hypot(15.0, 30.0);
  const double surface = M_PI * (25 + 10) * slant + M_PI * (25 * 25 + 10 * 10);
  EXPECT_NEAR(stock.volumeMm3(), frustum, voxelTolerance(surface, h));
}

TEST_P(StockAtVoxel, FacesSharedByTwoCutsLeaveNoGhostSheet) {
  // Two cuts meet at one face (a face pass repeated from both sides). `max` leaves a sheet
  // of voxels at φ ≈ 0 there with air on both sides; uncleaned, it counts about half a
  // voxel layer over the face (942 mm² × h/2: 118 mm³ at 0.25 mm). Both a face through
  // voxel centres (Z-10) and one between them (Z-10.03) are checked, against an eighth of
  // that sheet: a ghost left anywhere on the face exceeds it several times (90–240 mm³
  // measured without the cleaning), the discretisation error (3.6 mm³ at 0.25) does not.
  const double h = GetParam();
  for (const double faceZ : {-10.0, -10.03}) {
    SCOPED_TRACE(faceZ);
    Stock stock({40.0, 30.0, 0.0}, h);
    stock.remove(RevolvedRegion({rectangle(10.0, faceZ, 30.0, 5.0)}));
    stock.remove(RevolvedRegion({rectangle(10.0, -20.0, 30.0, faceZ)}));
    const double exact = M_PI * 20 * 20 * 10 + M_PI * 10 * 10 * 20;
    const double sheet = M_PI * (20 * 20 - 10 * 10) * h / 2;
    EXPECT_NEAR(stock.volumeMm3(), exact, sheet / 8);
    const TriangleMesh mesh = stock.mesh(0.0);
    EXPECT_TRUE(isClosedAndOriented(mesh));
    const double surface = 2 * M_PI * 20 * 10 + 2 * M_PI * 10 * 20 + 2 * M_PI * 20 * 20;
    EXPECT_NEAR(enclosedVolumeMm3(mesh), exact, voxelTolerance(surface, h));
  }
}

TEST_P(StockAtVoxel, MeshIsClosedWithOutwardNormalsAndMatchesTheVolume) {
  const double h = GetParam();
  // Written through the table, the mesh is the revolved profile's; voxel by voxel, the level
  // set's (adaptive or not).
  for (const RevolvedWrites writes : {RevolvedWrites::Table, RevolvedWrites::Voxels}) {
    Stock stock({50.0, 40.0, 2.0}, h, writes);
    stock.remove(RevolvedRegion({rectangle(15.0, -20.0, 40.0, 10.0)}));
    const double exact = M_PI * 25.0 * 25.0 * 18.0 + M_PI * 15.0 * 15.0 * 22.0;
    const double surface = 2 * M_PI * 25 * 18 + 2 * M_PI * 15 * 22 + 2 * M_PI * 25 * 25;
    for (double adaptivity : {0.0, 0.1}) {
      const TriangleMesh mesh = stock.mesh(adaptivity);
      EXPECT_TRUE(isClosedAndOriented(mesh)) << "adaptivity " << adaptivity;
      EXPECT_NEAR(enclosedVolumeMm3(mesh), exact, voxelTolerance(surface, h)) << "adaptivity " << adaptivity;
    }
  }
}

TEST_P(StockAtVoxel, MeshOfABoxIsTheMaterialInItClosedByItsFaces) {
  // A close-up's mesh, at the voxels and finer: Φ20 to Z-10, Φ12 above; the box x ≥ 0,
  // Z-15…-5 holds half of each step, 5 mm long. The box's faces are placed by whole voxels,
  // so each cap may stand up to a voxel off: the tolerance adds a voxel layer over the caps.
  const double h = GetParam();
  Stock stock({20.0, 30.0, 0.0}, h);
  stock.remove(RevolvedRegion({rectangle(6.0, -10.0, 20.0, 5.0)}));
  const Eigen::Vector3d low(0.0, -20.0, -15.0), high(20.0, 20.0, -5.0);
  const double exact = 0.5 * M_PI * (10.0 * 10.0 + 6.0 * 6.0) * 5.0;
  const double curved = M_PI * (10 + 6) * 5.0 + 0.5 * M_PI * (10 * 10 - 6 * 6);
  const double caps = 0.5 * M_PI * (10 * 10 + 6 * 6) + 2 * 10 * 5 + 2 * 6 * 5;
  for (const int subdivisions : {1, 2, 3}) {
    SCOPED_TRACE(subdivisions);
    const TriangleMesh mesh = stock.mesh(low, high, subdivisions);
    EXPECT_TRUE(isClosedAndOriented(mesh));
    EXPECT_NEAR(enclosedVolumeMm3(mesh), exact, voxelTolerance(curved, h) + h * caps);
    for (const Eigen::Vector3f& v : mesh.vertices)
      for (int axis = 0; axis < 3; ++axis) {
        ASSERT_GE(v[axis], low[axis] - h);
        ASSERT_LE(v[axis], high[axis] + h);
      }
  }
}

INSTANTIATE_TEST_SUITE_P(TwoVoxelSizes, StockAtVoxel, ::testing::Values(0.5, 0.25));

TEST(Stock, CutThroughTheAxisRemovesTheWholeSlice) {
  // A tool reaching across the axis (r < 0) must not leave a core.
  Stock stock({40.0, 20.0, 0.0}, 0.25);
  stock.remove(RevolvedRegion({rectangle(-5.0, -5.0, 30.0, 5.0)}));
  EXPECT_NEAR(stock.volumeMm3(), M_PI * 20 * 20 * 15, voxelTolerance(2 * M_PI * 20 * 20 + 2 * M_PI * 20 * 15, 0.25));
}

TEST(Stock, RefusesAGridTooLargeForMemoryAndSaysHowMuch) {
  const auto problem = gridProblem({125.0, 112.0, 2.0}, 0.002);
  ASSERT_TRUE(problem.has_value());
  EXPECT_NE(problem->find("GiB"), std::string::npos) << *problem;
  EXPECT_FALSE(gridProblem({125.0, 112.0, 2.0}, 0.1).has_value());
  EXPECT_TRUE(gridProblem({125.0, 112.0, 2.0}, 0.0).has_value());
  EXPECT_TRUE(gridProblem({125.0, 112.0, 2.0}, -0.1).has_value());
  EXPECT_TRUE(gridProblem({125.0, 112.0, 2.0}, std::nan("")).has_value());
}

TEST(Stock, RefusesAVoxelTooCoarseForTheStock) {
  // 20 voxels across the bar's smaller dimension at least: Φ50×30 allows 1.5 mm, not 2.
  EXPECT_FALSE(gridProblem({50.0, 30.0, 0.0}, 1.5).has_value());
  const auto problem = gridProblem({50.0, 30.0, 0.0}, 2.0);
  ASSERT_TRUE(problem.has_value());
  EXPECT_NE(problem->find("too coarse"), std::string::npos) << *problem;
}

}  // namespace
}  // namespace lathesim::sim
