// The revolved table (sim/revolved_table.hpp) against the level set written voxel by voxel, on
// the same moves: every block's volume, the warnings and collisions, and the final values at
// voxel centres must agree to rounding, over bars and tubes, voxel sizes, positions on and off
// voxel centres, coincident faces (ghost sheets), arcs, grooves, runs of short moves, and a cut
// made with the spindle stopped midway (the table then hands over to the level set).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "sim/simulate.hpp"
#include "test_moves.hpp"

namespace lathesim::sim {
namespace {

constexpr int kSharpTool = 1;
constexpr int kGroovingTool = 2;

ToolOutlines tools() {
  ToolOutlines outlines;
  // A sharp turning tool, tip at the programmed point, body above and outside it.
  const std::vector<RZ> sharp{{0, 0}, {10, 1}, {12, 12}, {1, 10}};
  outlines.emplace(kSharpTool, *ConvexPolygon::fromOutline(sharp).polygon);
  // A 2 mm grooving blade, the programmed point at its lower corner.
  const std::vector<RZ> blade{{0, 0}, {8, 0}, {8, 2}, {0, 2}};
  outlines.emplace(kGroovingTool, *ConvexPolygon::fromOutline(blade).polygon);
  return outlines;
}

struct Path {
  interp::Toolpath toolpath;
  int block = 0;

  interp::Move& add(interp::MoveKind kind, RZ from, RZ to, int tool = kSharpTool, RZ centre = RZ(0, 0)) {
    interp::Move m = test::turningMove(kind, from, to, block, block + 1, centre);
    m.tool = tool;
    toolpath.moves.push_back(m);
    toolpath.blockCount = ++block;
    return toolpath.moves.back();
  }
  void feed(RZ from, RZ to, int tool = kSharpTool) { add(interp::MoveKind::Feed, from, to, tool); }
};

struct Case {
  double voxelMm;
  double boreMm;   // 0: a bar
  double shiftMm;  // moves every cut's radius and Z by this much (on and off voxel centres)
  bool slotMidway; // a cut with the spindle stopped after the turning cuts
};

// A program's worth of revolved cuts on a Φ20 × 16 bar (face at Z0), shifted by `s`.
interp::Toolpath program(const Case& c) {
  const double s = c.shiftMm;
  Path p;
  p.feed({12.0, 0.0}, {-0.5, 0.0});         // a face pass exactly on the bar's face: ghost sheets
  p.feed({12.0, -0.3 + s}, {c.boreMm / 2.0 + 0.5, -0.3 + s});  // a face cut
  p.feed({9.03 + s, 1.0}, {9.03 + s, -9.0});  // a turning pass...
  p.feed({9.03 + s, 1.0}, {9.03 + s, -9.0});  // ...and the same again: nothing to cut
  p.feed({8.5 + s, 1.0}, {8.5 + s, -0.3 + s});
  // A run of short moves on a wavy radius, as CAM posts a contour, and an arc.
  RZ at(8.5 + s, -0.3 + s);
  for (int k = 1; k <= 40; ++k) {
    const RZ next(8.3 + s + 0.15 * std::sin(0.4 * k), -0.3 + s - 0.03 * k);
    p.feed(at, next);
    at = next;
  }
  const RZ arcEnd(at.x() - 0.6, at.y() - 0.6);
  p.add(interp::MoveKind::ArcCW, at, arcEnd, kSharpTool, RZ(at.x() - 0.6, at.y()));
  // A groove, plunged and withdrawn.
  p.feed({11.0, -6.0 + s}, {7.2 + s, -6.0 + s}, kGroovingTool);
  p.feed({7.2 + s, -6.0 + s}, {11.0, -6.0 + s}, kGroovingTool);
  if (c.slotMidway) {
    interp::Move& slot = p.add(interp::MoveKind::Feed, {11.0, -10.0}, {8.0 + s, -10.0}, kGroovingTool);
    slot.spindleOn = false;
    slot.spindleS = 0;
    p.feed({8.8 + s, -8.0}, {8.8 + s, -12.0});  // turning again, through the slot
  }
  return p.toolpath;
}

// φ at every voxel centre of every third Z layer over the bar (mm).
std::vector<double> valuesAtVoxelCentres(const Stock& stock, double voxelMm) {
  const int r = static_cast<int>(std::ceil(10.0 / voxelMm)) + 4;
  const int zLow = static_cast<int>(std::floor(-16.0 / voxelMm)) - 4, zHigh = static_cast<int>(std::ceil(0.0 / voxelMm)) + 4;
  std::vector<Eigen::Vector3d> points;
  for (int k = zLow; k <= zHigh; k += 3)
    for (int i = -r; i <= r; ++i)
      for (int j = -r; j <= r; ++j) points.emplace_back(i * voxelMm, j * voxelMm, k * voxelMm);
  std::vector<double> values(points.size());
  stock.signedDistancesAt(points, values);
  return values;
}

TEST(RevolvedTable, GivesWhatTheLevelSetWrittenVoxelByVoxelGives) {
  const std::vector<Case> cases{{0.1, 0.0, 0.0, false},   {0.1, 0.0, 0.037, true},  {0.13, 0.0, 0.011, false},
                                {0.13, 8.0, 0.0, true},   {0.2, 8.0, 0.071, false}, {0.2, 0.0, 0.1, true}};
  for (const Case& c : cases) {
    SCOPED_TRACE(testing::Message() << "voxel " << c.voxelMm << " mm, bore " << c.boreMm << ", shift " << c.shiftMm
                                    << (c.slotMidway ? ", a slot midway" : ""));
    const StockSpec spec{20.0, 16.0, 0.0, c.boreMm};
    const interp::Toolpath toolpath = program(c);
    Stock byTable(spec, c.voxelMm, RevolvedWrites::Table);
    Stock byVoxels(spec, c.voxelMm, RevolvedWrites::Voxels);
    const SimulationResult table = simulate(toolpath, tools(), byTable);
    const SimulationResult voxels = simulate(toolpath, tools(), byVoxels);

    // Rounding: the table sums a class's columns as one product, the level set voxel by voxel;
    // and the columns of a class compute ρ = √(x² + y²) to within an ulp of each other, so a
    // stored float can round one step apart (1.2e-7 of the band: 3.6e-7 of a voxel's share).
    const double voxelVolume = c.voxelMm * c.voxelMm * c.voxelMm;
    ASSERT_EQ(table.blocks.size(), voxels.blocks.size());
    double removed = 0.0;
    for (std::size_t b = 0; b < table.blocks.size(); ++b) {
      EXPECT_NEAR(table.blocks[b].removedMm3, voxels.blocks[b].removedMm3,
                  1e-8 * std::abs(voxels.blocks[b].removedMm3) + 1e-5 * voxelVolume)
          << "block " << b;
      removed += voxels.blocks[b].removedMm3;
    }
    EXPECT_GT(removed, 100.0);  // the program cuts
    EXPECT_EQ(table.warnings.size(), voxels.warnings.size());
    EXPECT_EQ(table.collisions.size(), voxels.collisions.size());
    EXPECT_NEAR(byTable.volumeMm3(), byVoxels.volumeMm3(), 1e-8 * byVoxels.volumeMm3());
    EXPECT_EQ(byTable.activeVoxelCount(), byVoxels.activeVoxelCount());

    const std::vector<double> fromTable = valuesAtVoxelCentres(byTable, c.voxelMm);
    const std::vector<double> fromVoxels = valuesAtVoxelCentres(byVoxels, c.voxelMm);
    // Every value lies in the band, on both routes: a block split from a tile once took a
    // heap address's bits as its value (region_writer.cpp, restructure), a leaf of garbage
    // deep inside the material in about one run in five.
    const double band = kHalfBandVoxels * c.voxelMm * (1.0 + 1e-6);
    double largest = 0.0;
    std::size_t outOfBand = 0;
    for (std::size_t n = 0; n < fromTable.size(); ++n) {
      outOfBand += !(std::abs(fromVoxels[n]) <= band) + !(std::abs(fromTable[n]) <= band);
      largest = std::max(largest, std::abs(fromTable[n] - fromVoxels[n]));
    }
    EXPECT_EQ(outOfBand, 0u);
    EXPECT_LE(largest, 1e-5 * c.voxelMm);
  }
}

}  // namespace
}  // namespace lathesim::sim
