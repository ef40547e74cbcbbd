// Arcs through the simulation: the tool swept along G02/G03 removes the exact region of
// revolution, checked by Pappus (V = 2π · area · centroid radius), to the same tolerance
// as the other sim tests: a tenth of a voxel layer over the surfaces the cut changes.

#include <gtest/gtest.h>

#include <cmath>

#include "sim/move_sweep.hpp"
#include "sim/simulate.hpp"
#include "test_moves.hpp"

namespace lathesim::sim {
namespace {

constexpr double kArcVoxelMm = 0.25;

interp::Move move(interp::MoveKind kind, RZ from, RZ to, RZ center = RZ(0, 0)) {
  return test::turningMove(kind, from, to, 0, 1, center);
}

// A sharp tool: a 12 mm square whose corner at the programmed point points at -r, -z.
// Along both arcs below it stays on the air side (every point it covers has r and z at
// least those of a point on the arc), so it removes exactly the region above the arc.
ConvexPolygon squareOutline() {
  const std::vector<RZ> square{{0, 0}, {12, 0}, {12, 12}, {0, 12}};
  return *ConvexPolygon::fromOutline(square).polygon;
}

ToolOutlines arcSquareTool() { return {{1, squareOutline()}}; }

double tolerance(double changedSurfaceMm2) { return 0.1 * kArcVoxelMm * changedSurfaceMm2; }

TEST(ArcSweep, ConvexCornerRoundByPappus) {
  // Bar Φ40 (r 20), Z -30 … 0. G02 from (20, -5) to (15, 0) about (15, -5), radius 5:
  // from straight above the centre to straight right of it, clockwise in the drawing view.
  // It rounds the corner: removed = the square [15,20]×[-5,0] minus the quarter disc of
  // radius 5 about (15, -5).
  //   square, revolved:  π(20² − 15²)·5 = 875π
  //   quarter disc: area 25π/4, centroid r = 15 + 4·5/(3π) = 15 + 20/(3π);
  //     2π · 25π/4 · (15 + 20/(3π)) = 187.5π² + 250π/3
  //   removed = 875π − 250π/3 − 187.5π² = 2375π/3 − 187.5π² = 2487.09 − 1850.55 = 636.54 mm³
  // Changed surfaces: the cylinder band 2π·20·5 = 628.3, the face ring π(400 − 225) = 549.8,
  // the round 2π · (5π/2) · (15 + 10/π) = 75π² + 50π = 897.3 (arc length × its centroid
  // radius 15 + 5·2/π); 2075.4 mm² in all, tolerance 51.9 mm³. One straight chord instead
  // of the arc would also take the circular segment (25π/4 − 12.5 = 7.13 mm² at r ≈ 18):
  // about 800 mm³ more.
  Stock stock({40.0, 30.0, 0.0}, kArcVoxelMm);
  const double before = stock.volumeMm3();
  interp::Toolpath path;
  path.blockCount = 1;
  path.moves.push_back(move(interp::MoveKind::ArcCW, {20, -5}, {15, 0}, {15, -5}));
  const SimulationResult result = simulate(path, arcSquareTool(), stock);
  const double exact = 2375.0 * M_PI / 3.0 - 187.5 * M_PI * M_PI;
  EXPECT_NEAR(before - stock.volumeMm3(), exact, tolerance(2075.4));
  ASSERT_EQ(result.blocks.size(), 1u);
  EXPECT_NEAR(result.blocks[0].removedMm3, exact, tolerance(2075.4));
}

TEST(ArcSweep, ConcaveFilletInOneBlockByPappus) {
  // One block: turn r 15 from Z2 to Z-5, G02 from (15, -5) to (20, -10) about (20, -5)
  // (from straight below the centre to straight left of it, clockwise), then out to r 22.
  // Removed: the shell r 15…20, Z -5…0, and the quarter disc of radius 5 about (20, -5)
  // with r ≤ 20, Z ≤ -5 (the air side of the fillet).
  //   shell: π(20² − 15²)·5 = 875π
  //   quarter disc: area 25π/4, centroid r = 20 − 20/(3π); 2π · 25π/4 · (20 − 20/(3π))
  //     = 250π² − 250π/3
  //   removed = 875π − 250π/3 + 250π² = 2375π/3 + 250π² = 2487.09 + 2467.40 = 4954.49 mm³
  // Changed surfaces: old cylinder r 20 over Z -10…0, 2π·20·10 = 1256.6; face ring 549.8;
  // new cylinder r 15, 2π·15·5 = 471.2; fillet 2π · (5π/2) · (20 − 10/π) = 100π² − 50π
  // = 829.9; 3107.5 mm² in all, tolerance 77.7 mm³.
  Stock stock({40.0, 30.0, 0.0}, kArcVoxelMm);
  const double before = stock.volumeMm3();
  interp::Toolpath path;
  path.blockCount = 1;
  path.moves.push_back(move(interp::MoveKind::Feed, {15, 2}, {15, -5}));
  path.moves.push_back(move(interp::MoveKind::ArcCW, {15, -5}, {20, -10}, {20, -5}));
  path.moves.push_back(move(interp::MoveKind::Feed, {20, -10}, {22, -10}));
  const SimulationResult result = simulate(path, arcSquareTool(), stock);
  const double exact = 2375.0 * M_PI / 3.0 + 250.0 * M_PI * M_PI;
  EXPECT_NEAR(before - stock.volumeMm3(), exact, tolerance(3107.5));
  ASSERT_EQ(result.blocks.size(), 1u);
  EXPECT_NEAR(result.blocks[0].removedMm3, exact, tolerance(3107.5));
}

TEST(ArcSweep, BallEndIsAHemisphere) {
  // Bar Φ20 (r 10), Z -30 … 0. G03 X20 Z-10 R10 from X0 Z0: from (0, 0) to (10, -10) about
  // (0, -10), a quarter turn counter-clockwise from straight right of the centre to straight
  // above it. It leaves a hemisphere of radius 10 on the end of the bar:
  //   removed = cylinder r 10, Z -10…0, minus the hemisphere = 1000π − (2/3)π·1000
  //           = 1000π/3 = 1047.20 mm³
  // Changed surfaces: the face π·100 = 314.2, the cylinder band 2π·10·10 = 628.3, the
  // hemisphere 2π·100 = 628.3; 1570.8 mm² in all, tolerance 39.3 mm³.
  Stock stock({20.0, 30.0, 0.0}, kArcVoxelMm);
  const double before = stock.volumeMm3();
  interp::Toolpath path;
  path.blockCount = 1;
  path.moves.push_back(move(interp::MoveKind::ArcCCW, {0, 0}, {10, -10}, {0, -10}));
  simulate(path, arcSquareTool(), stock);
  EXPECT_NEAR(before - stock.volumeMm3(), 1000.0 * M_PI / 3.0, tolerance(1570.8));
}

TEST(ArcSweep, ArcsAreFollowedByChordsOfBoundedSagittaAndDwellsSweepNothing) {
  // Radius 5 at 0.2 mm voxels: sagitta ≤ 0.01 mm, 13 chords per quarter turn (worked out
  // in tests/geometry/arc_test.cpp).
  const ConvexPolygon tool = squareOutline();
  EXPECT_EQ(sweptPieces(move(interp::MoveKind::ArcCCW, {15, 0}, {20, -5}, {15, -5}), tool, 0.2).size(), 13u);
  EXPECT_EQ(sweptPieces(move(interp::MoveKind::Feed, {15, 0}, {20, -5}), tool, 0.2).size(), 1u);
  interp::Move dwell = move(interp::MoveKind::Dwell, {15, 0}, {15, 0});
  dwell.dwellS = 2;
  EXPECT_TRUE(sweptPieces(dwell, tool, 0.2).empty());
}

TEST(ArcSweep, DwellRemovesNothing) {
  // The tool standing inside the bar (as no real program would) for a dwell removes nothing.
  Stock stock({40.0, 30.0, 0.0}, kArcVoxelMm);
  const double before = stock.volumeMm3();
  interp::Toolpath path;
  path.blockCount = 1;
  path.moves.push_back(move(interp::MoveKind::Dwell, {10, -10}, {10, -10}));
  const SimulationResult result = simulate(path, arcSquareTool(), stock);
  EXPECT_DOUBLE_EQ(stock.volumeMm3(), before);
  ASSERT_EQ(result.blocks.size(), 1u);
  EXPECT_EQ(result.blocks[0].removedMm3, 0.0);
}

}  // namespace
}  // namespace lathesim::sim
