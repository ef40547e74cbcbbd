// Per-block volumes of a long program of short moves, against Pappus worked out by hand: a
// finishing cut posted as many one-move blocks (as CAM posts a contour), over a sweep of move
// lengths, cut depths and voxel sizes. Whatever route a write takes (one write per block,
// writes limited to what a block changes, or several blocks written at once), each block must
// still get its own volume.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "sim/simulate.hpp"
#include "test_moves.hpp"

namespace lathesim::sim {
namespace {

constexpr double kBarRadiusMm = 25.0;

// The default sharp tool (parts/README.md): tip at the programmed point, the body above and
// outside it, its lower flank rising 1 mm in Z per 10 mm of radius.
ToolOutlines defaultTool() {
  const std::vector<RZ> outline{{0, 0}, {10, 1}, {12, 12}, {1, 10}};
  ToolOutlines tools;
  tools.emplace(1, *ConvexPolygon::fromOutline(outline).polygon);
  return tools;
}

interp::Move feed(RZ from, RZ to, int block) {
  return test::turningMove(interp::MoveKind::Feed, from, to, block, block + 1);
}

// The tip runs at radius `tipMm` from Z1 to the face (block 0, cuts nothing), then leftwards
// along −Z in `blocks` blocks of one `stepMm` move each.
interp::Toolpath turningInSteps(double tipMm, double stepMm, int blocks) {
  interp::Toolpath path;
  path.blockCount = blocks + 1;
  path.moves.push_back(feed({tipMm, 1.0}, {tipMm, 0.0}, 0));
  for (int k = 1; k <= blocks; ++k) path.moves.push_back(feed({tipMm, -(k - 1) * stepMm}, {tipMm, -k * stepMm}, k));
  return path;
}

// Block k's volume by hand. With the tip at Z−(k−1)s the lower flank lies at
// z = −(k−1)s + (r − tip)/10, and the material left of the face Z0 below it (earlier blocks
// took the rest). Block k moves the flank down by s: at radius r it takes the Z length
// min(s, k·s − (r − tip)/10) (none where that is negative), from tip to the bar's radius.
// Pappus: V = 2π ∫ r·length(r) dr, integrated here by Simpson's rule (the integrand is
// piecewise quadratic; 20,000 intervals leave an error far below a voxel's rounding).
double blockVolumeByHand(double tipMm, double stepMm, int k) {
  const auto length = [&](double r) { return std::max(0.0, std::min(stepMm, k * stepMm - (r - tipMm) / 10.0)); };
  constexpr int kIntervals = 20000;
  const double dr = (kBarRadiusMm - tipMm) / kIntervals;
  double sum = 0.0;
  for (int i = 0; i <= kIntervals; ++i) {
    const double r = tipMm + i * dr;
    const double weight = i == 0 || i == kIntervals ? 1.0 : i % 2 ? 4.0 : 2.0;
    sum += weight * r * length(r);
  }
  return 2.0 * std::numbers::pi * sum * dr / 3.0;
}

struct LongProgramCase {
  double voxelMm;
  double tipMm;   // the tip's radius: the cut is kBarRadiusMm − tipMm deep
  double stepMm;  // each block's move
};

TEST(LongProgramVolume, EveryShortBlockRemovesItsPappusVolume) {
  // Moves from a third of a voxel (a CAM contour at 0.1 mm) to several voxels, depths from
  // 0.7 to 3.3 mm, tips on and off voxel centres.
  const std::vector<LongProgramCase> cases{{0.1, 21.73, 0.03}, {0.1, 23.05, 0.1},  {0.1, 24.31, 0.37},
                                {0.2, 22.0, 0.03},  {0.2, 21.87, 0.13}, {0.2, 23.4, 0.5},
                                {0.25, 22.63, 0.07}, {0.25, 21.7, 1.1}};
  for (const LongProgramCase& c : cases) {
    SCOPED_TRACE(testing::Message() << "voxel " << c.voxelMm << " mm, tip r " << c.tipMm << ", move " << c.stepMm);
    const int blocks = static_cast<int>(std::ceil(2.0 / c.stepMm));  // about 2 mm of Z
    Stock stock({2.0 * kBarRadiusMm, 12.0, 0.0}, c.voxelMm);
    const double before = stock.volumeMm3();
    const SimulationResult result = simulate(turningInSteps(c.tipMm, c.stepMm, blocks), defaultTool(), stock);
    ASSERT_EQ(result.blocks.size(), static_cast<std::size_t>(blocks + 1));

    // A block moves the flank (a ring tip…R, 1-in-10 steep) and turns a strip of the Φ: its
    // volume may stray by the project's voxel-layer tolerance (stock.hpp) over that surface.
    // One flank, not two: the flank before and after is the same shape shifted by a fraction
    // of a voxel, rounded alike, so that its rounding mostly cancels in the difference
    // (measured: at most a third of this tolerance over these cases).
    const double flankMm2 = std::numbers::pi * (kBarRadiusMm * kBarRadiusMm - c.tipMm * c.tipMm) * std::hypot(1.0, 0.1);
    const double blockSurfaceMm2 = flankMm2 + 2.0 * std::numbers::pi * c.tipMm * c.stepMm;
    double byHand = 0.0, measured = 0.0;
    EXPECT_NEAR(result.blocks[0].removedMm3, 0.0, volumeToleranceMm3(flankMm2, c.voxelMm));
    for (int k = 1; k <= blocks; ++k) {
      const double expected = blockVolumeByHand(c.tipMm, c.stepMm, k);
      EXPECT_EQ(result.blocks[k].line, k + 1);
      EXPECT_NEAR(result.blocks[k].removedMm3, expected, volumeToleranceMm3(blockSurfaceMm2, c.voxelMm))
          << "block " << k;
      byHand += expected;
      measured += result.blocks[k].removedMm3;
    }
    // The blocks add up to what the stock lost, and to the whole cut by hand within the
    // tolerance of the cut's own surface (the last flank and the turned strip).
    EXPECT_NEAR(measured + result.blocks[0].removedMm3, before - stock.volumeMm3(), 1e-6 * before);
    const double cutSurfaceMm2 = flankMm2 + 2.0 * std::numbers::pi * c.tipMm * blocks * c.stepMm;
    EXPECT_NEAR(measured, byHand, volumeToleranceMm3(cutSurfaceMm2, c.voxelMm));
  }
}

}  // namespace
}  // namespace lathesim::sim
