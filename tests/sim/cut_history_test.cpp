// Writing only near what a cut changes (CutHistory) gives the stock a whole write gives.
// Random CAM-like chains — hundredths-of-a-millimetre steps, plunges, moves retraced, arcs,
// groups of several moves written at once, face cuts across the axis — are written into two
// stocks, one whole region at a time and one through the history; every write must remove the
// same volume and the two level sets must agree voxel for voxel at the end.

#include "sim/cut_history.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "geometry/arc.hpp"
#include "geometry/convex_overlap.hpp"
#include "sim/stock.hpp"

namespace lathesim::sim {
namespace {

ConvexPolygon polygon(const std::vector<RZ>& points) { return ConvexPolygon::hullOf(points); }

// A sharp tool with flanks 1 in 10 off the axes, and a round-nosed one (an octagon nose of
// radius 0.4 on a body).
const std::vector<ConvexPolygon> kTools{
    polygon({{0, 0}, {5, 0.5}, {6, 6}, {0.5, 5}}),
    polygon({{0, 0}, {0.12, -0.28}, {0.4, -0.4}, {0.68, -0.28}, {4, 0.5}, {4, 5}, {-0.28, 0.68}, {-0.4, 0.4}, {-0.28, 0.12}})};

struct Step {
  RZ from, to;
  std::vector<ConvexPolygon> pieces;
};

TEST(CutHistory, WritesOnlyWhatChangesWithTheSameResult) {
  std::mt19937 random(1413);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double voxel = 0.25;
  for (int trial = 0; trial < 6; ++trial) {
    const StockSpec bar{20.0 + 4.0 * unit(random), 16.0, 0.0, trial % 3 == 2 ? 6.0 : 0.0};
    const ConvexPolygon& tool = kTools[trial % 2];
    Stock whole(bar, voxel), culled(bar, voxel);
    CutHistory history;
    RZ at(bar.diameterMm / 2.0 - 1.0, 0.5);
    std::vector<ConvexPolygon> group;
    for (int move = 0; move < 90; ++move) {
      const double kind = unit(random);
      RZ to = at;
      std::vector<ConvexPolygon> pieces;
      if (kind < 0.55) {  // a CAM step along the profile
        to += RZ(0.3 * (unit(random) - 0.5), -0.01 - 0.4 * unit(random) * unit(random));
      } else if (kind < 0.65) {  // a plunge, or a face cut across the axis now and then
        to.x() = trial == 1 && unit(random) < 0.3 ? -0.5 : to.x() - 2.0 * unit(random);
      } else if (kind < 0.75) {  // back along the way it came: faces it cut before
        to.y() += 0.5 * unit(random);
      } else if (kind < 0.85) {  // a quarter arc of a fillet
        const double radius = 0.2 + unit(random);
        to += RZ(-radius, -radius);
        const Arc arc(at, to, at + RZ(0.0, -radius), false);
        for (const Arc& piece : arc.split(0.05 * voxel)) pieces.push_back(tool.sweptAlong(piece.start(), piece.end()));
      } else {  // up and over to another place
        to = RZ(bar.diameterMm / 2.0 - 3.0 * unit(random), 0.5 - 10.0 * unit(random));
      }
      to.x() = std::min(to.x(), bar.diameterMm / 2.0 + 0.5);
      to.y() = std::clamp(to.y(), -14.0, 1.0);
      if (to.x() < 1.0 && to.x() != -0.5) to.x() = 1.0;
      if (pieces.empty()) pieces.push_back(tool.sweptAlong(at, to));
      at = to;
      group.insert(group.end(), pieces.begin(), pieces.end());
      if (unit(random) < 0.4) continue;  // the next move joins this write, as moves of one block do
      const RevolvedRegion region(group);
      const double expected = whole.remove(region);
      const auto changes = history.changesOf(group);
      const double removed = changes ? culled.remove(region, *changes) : culled.remove(region);
      ASSERT_NEAR(removed, expected, 1e-9 * std::max(1.0, std::abs(expected))) << "trial " << trial << " move " << move;
      group.clear();
    }
    EXPECT_NEAR(culled.volumeMm3(), whole.volumeMm3(), 1e-9 * whole.volumeMm3()) << "trial " << trial;
    // Voxel for voxel: the trilinear samples at voxel centres are the voxels' values.
    for (double z = -15.0; z <= 1.0; z += voxel)
      for (double x = 0.0; x <= bar.diameterMm / 2.0 + 1.0; x += voxel)
        ASSERT_EQ(culled.signedDistanceAt(x, 0.0, z), whole.signedDistanceAt(x, 0.0, z))
            << "trial " << trial << " at x " << x << " z " << z;
  }
}

}  // namespace
}  // namespace lathesim::sim
