// The level set built whole from the revolved table (sim/table_grid.hpp) against the level set
// written voxel by voxel: the bar, then the same cuts (what the table itself must agree with,
// revolved_table_test.cpp). Every voxel's value and active state must agree over the bar and a margin, and so
// must the volume and the active voxel count; the tree must be no larger. Bars and tubes, three
// voxel sizes, faces and radii on and off voxel centres and on 128-voxel block boundaries, with
// and without cuts (turning, a taper, an arc, a groove, facing to the axis).

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "sim/move_sweep.hpp"
#include "sim/stock_grid.hpp"
#include "sim/table_grid.hpp"
#include "test_moves.hpp"

namespace lathesim::sim {
namespace {

// A bar or tube and its cuts, every length in voxels (so that a case means the same voxels at
// any voxel size), shifted by `shift` voxels off the voxel centres.
struct GridCase {
  double voxelMm;
  double radius, length, faceZ, boreRadius;  // voxels; boreRadius 0: a bar
  double shift;
  bool cuts;
};

RevolvedRegion rectangle(double rhoLow, double zLow, double rhoHigh, double zHigh) {
  const std::vector<RZ> corners{{rhoLow, zLow}, {rhoHigh, zLow}, {rhoHigh, zHigh}, {rhoLow, zHigh}};
  return RevolvedRegion({ConvexPolygon::hullOf(corners)});
}

StockSpec specOf(const GridCase& c) {
  const double h = c.voxelMm, s = c.shift;
  return {2.0 * (c.radius + s) * h, c.length * h, (c.faceZ + s) * h, c.boreRadius > 0.0 ? 2.0 * (c.boreRadius + s) * h : 0.0};
}

// The bar as Stock's constructor writes it: a solid bar's section mirrored across the axis, a
// tube's from its bore out.
RevolvedRegion barOf(const StockSpec& spec) {
  const double r = spec.diameterMm / 2.0, inner = spec.boreMm > 0.0 ? spec.boreMm / 2.0 : -r;
  return rectangle(inner, spec.faceZMm - spec.lengthMm, r, spec.faceZMm);
}

// Cuts on a bar whose face is at `faceZ` and whose radius is `radius` (voxels): a face cut to the
// axis, a turning pass, a taper, an arc swept by a sharp tool, and a groove, each `s` voxels off.
std::vector<RevolvedRegion> cutsOf(const GridCase& c) {
  const double h = c.voxelMm, s = c.shift, top = c.faceZ + 10.0, out = c.radius + 10.0;
  const auto mm = [h](double voxels) { return voxels * h; };
  std::vector<RevolvedRegion> cuts;
  // Faced to the axis down to the block boundary below the face (whole blocks turn to air).
  const double newFace = std::floor((c.faceZ - 20.0) / 128.0) * 128.0 + s;
  cuts.push_back(rectangle(mm(-out), mm(newFace), mm(out), mm(top)));
  cuts.push_back(rectangle(mm(c.radius - 13.0 + s), mm(newFace - 150.0 + s), mm(out), mm(top)));  // turned
  const std::vector<RZ> cone{{mm(c.radius - 25.0 + s), mm(newFace - 150.0)}, {mm(out), mm(newFace - 150.0)},
                             {mm(out), mm(newFace - 210.0)}};
  cuts.push_back(RevolvedRegion({ConvexPolygon::hullOf(cone)}));
  // An arc: a sharp tool's sweep along a quarter circle into the turned diameter.
  const std::vector<RZ> sharp{{0, 0}, {mm(40), mm(4)}, {mm(48), mm(48)}, {mm(4), mm(40)}};
  const RZ from(mm(c.radius - 13.0 + s), mm(newFace - 40.0)), to(mm(c.radius - 33.0 + s), mm(newFace - 60.0));
  const interp::Move arc = test::turningMove(interp::MoveKind::ArcCW, from, to, 0, 1, RZ(from.x() - mm(20.0), from.y()));
  cuts.push_back(RevolvedRegion(sweptPieces(arc, *ConvexPolygon::fromOutline(sharp).polygon, h)));
  cuts.push_back(rectangle(mm(c.radius - 40.0 + s), mm(newFace - 120.0 + s), mm(out), mm(newFace - 100.0)));  // a groove
  return cuts;
}

struct BothWays {
  std::unique_ptr<StockGrid> settled;  // the bar and the cuts written into the level set voxel by voxel
  std::unique_ptr<StockGrid> built;    // the bar and the cuts through the table, the level set built from it
};

BothWays bothWays(const StockSpec& spec, double voxelMm, const std::vector<RevolvedRegion>& cuts) {
  BothWays both{std::make_unique<StockGrid>(spec, voxelMm), std::make_unique<StockGrid>(spec, voxelMm)};
  const RevolvedRegion bar = barOf(spec);
  writeRegion(*both.settled, bar, RegionWrite::Add);
  for (const RevolvedRegion& cut : cuts) writeRegion(*both.settled, cut, RegionWrite::Remove);
  if (!both.built->startTable(bar)) {
    ADD_FAILURE() << "the stock got no table";
    return both;
  }
  for (const RevolvedRegion& cut : cuts) both.built->writeThroughTable(cut, nullptr);
  both.built->settle();  // the level set was never built: writeGridFromTable
  return both;
}

// How the two grids differ over `box`. The bar's and the cuts' writer takes each column's radius as √(x² + y²) of its own x and
// y, the table its class's widest column's: equal sums of squares (3² + 4² = 5² + 0²) can round
// an ulp apart, so a voxel on a surface through voxel centres can hold 0 in one and 1e-15 mm in
// the other. Such a difference is rounding only where the built grid holds the table's value and
// the two lie within a millionth of a voxel; every other difference counts as a fault.
struct Differences {
  std::uint64_t voxels = 0, states = 0, rounding = 0, values = 0;  // values: beyond rounding
  Coord first;  // the first fault
};

Differences differences(const StockGrid& settled, const StockGrid& built, const openvdb::CoordBBox& box) {
  Differences found;
  auto readA = settled.grid->getConstAccessor();
  auto readB = built.grid->getConstAccessor();
  const RevolvedTable& table = *built.table;
  const auto alignDown = [](int i) { return i & ~(kLeafDim - 1); };
  for (int x = alignDown(box.min().x()); x <= box.max().x(); x += kLeafDim)
    for (int y = alignDown(box.min().y()); y <= box.max().y(); y += kLeafDim)
      for (int z = alignDown(box.min().z()); z <= box.max().z(); z += kLeafDim) {
        const Coord origin(x, y, z);
        const Leaf* leafA = readA.probeConstLeaf(origin);
        const Leaf* leafB = readB.probeConstLeaf(origin);
        const float tileA = leafA ? 0.0f : readA.getValue(origin), tileB = leafB ? 0.0f : readB.getValue(origin);
        const bool onA = leafA ? false : readA.isValueOn(origin), onB = leafB ? false : readB.isValueOn(origin);
        for (openvdb::Index n = 0; n < Leaf::NUM_VALUES; ++n) {
          ++found.voxels;
          const float valueA = leafA ? leafA->getValue(n) : tileA, valueB = leafB ? leafB->getValue(n) : tileB;
          const bool activeA = leafA ? leafA->isValueOn(n) : onA, activeB = leafB ? leafB->isValueOn(n) : onB;
          if (valueA == valueB && activeA == activeB) continue;
          const Coord voxel = origin + Leaf::offsetToLocalCoord(n);
          const bool rounding = activeA == activeB && valueB == table.value(voxel.x(), voxel.y(), voxel.z()) &&
                                std::abs(valueA - valueB) <= 1e-6 * settled.voxel;
          if (rounding) {
            ++found.rounding;
            continue;
          }
          if (found.values + found.states == 0) found.first = voxel;
          found.states += activeA != activeB;
          found.values += valueA != valueB;
        }
      }
  return found;
}

// Stock::volumeMm3 over a grid: each voxel clamp(½ − φ/h, 0, 1) of itself, tiles whole.
double volumeMm3(const StockGrid& stock) {
  const Tree& tree = stock.grid->tree();
  double voxels = 0.0;
  for (auto leaf = tree.cbeginLeaf(); leaf; ++leaf) voxels += stock.leafInsideVoxels(*leaf);
  auto tile = tree.cbeginValueOff();
  tile.setMaxDepth(decltype(tile)::LEAF_DEPTH - 1);
  for (; tile; ++tile)
    if (*tile < 0.0f) voxels += static_cast<double>(tile.getVoxelCount());
  return voxels * stock.voxel * stock.voxel * stock.voxel;
}

void expectTheSameGrid(const GridCase& c) {
  const StockSpec spec = specOf(c);
  const BothWays both = bothWays(spec, c.voxelMm, c.cuts ? cutsOf(c) : std::vector<RevolvedRegion>{});
  if (!both.built->table) return;
  const Grid& settled = *both.settled->grid;
  const Grid& built = *both.built->grid;
  // Over the bar and two leaves beyond it on every side (beyond that both are background).
  openvdb::CoordBBox box = both.settled->materialBounds;
  box.expand(2 * kLeafDim);
  const Differences found = differences(*both.settled, *both.built, box);
  EXPECT_GT(found.voxels, 0u);
  EXPECT_EQ(found.values, 0u) << "first at " << found.first;
  EXPECT_EQ(found.states, 0u) << "first at " << found.first;
  EXPECT_EQ(settled.activeVoxelCount(), built.activeVoxelCount());
  const double volume = volumeMm3(*both.settled);  // apart by the rounding above at most: 1e-15 mm a voxel
  EXPECT_NEAR(volumeMm3(*both.built), volume, 1e-12 * volume);
  // Nothing outside the box, and the tree no larger.
  openvdb::CoordBBox used;
  built.tree().evalLeafBoundingBox(used);
  EXPECT_TRUE(box.isInside(used)) << used;
  EXPECT_LE(built.tree().leafCount(), settled.tree().leafCount());
  EXPECT_LE(built.tree().memUsage(), settled.tree().memUsage());
  // The grid is up to date with the table: nothing is left to settle.
  EXPECT_TRUE(both.built->table->changedLeaves().empty());
}

TEST(TableGrid, BuildsWhatTheVoxelWritesBuild) {
  // A bar of radius 128 voxels (its surface on the block boundary at ±128), face at Z = 0 and
  // back at −384 (block boundaries), then shifted off voxel centres by half a voxel and less.
  for (const double voxelMm : {0.1, 0.13, 0.2})
    for (const double boreRadius : {0.0, 60.0})
      for (const double shift : {0.0, 0.5, 0.37})
        for (const bool cuts : {false, true}) {
          const GridCase c{voxelMm, 128.0, 384.0, 0.0, boreRadius, shift, cuts};
          SCOPED_TRACE(testing::Message() << "voxel " << voxelMm << " mm, bore radius " << boreRadius << " voxels, shift "
                                          << shift << (cuts ? ", cut" : ", uncut"));
          expectTheSameGrid(c);
        }
}

// A bar spanning six 128³ blocks across and five along Z, its faces and radius off the block
// boundaries and off voxel centres.
TEST(TableGrid, BuildsWhatTheVoxelWritesBuildOverManyBlocks) {
  for (const bool cuts : {false, true}) {
    const GridCase c{0.1, 300.0, 470.0, 37.0, 0.0, 0.29, cuts};
    SCOPED_TRACE(cuts ? "cut" : "uncut");
    expectTheSameGrid(c);
  }
}

// Over a grid already built, what the table now holds as air would keep the old values.
TEST(TableGrid, RefusesAGridAlreadyBuilt) {
  const StockSpec spec{20.0, 16.0, 0.0, 0.0};
  StockGrid stock(spec, 0.2);
  const RevolvedRegion bar = barOf(spec);
  writeRegion(stock, bar, RegionWrite::Add);
  ASSERT_TRUE(stock.startTable(bar));
  EXPECT_THROW(writeGridFromTable(stock), std::logic_error);
  StockGrid withoutTable(spec, 0.2);
  EXPECT_THROW(writeGridFromTable(withoutTable), std::logic_error);
}

}  // namespace
}  // namespace lathesim::sim
