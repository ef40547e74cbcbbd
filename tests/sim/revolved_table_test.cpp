// The revolved table (sim/revolved_table.hpp) against the level set written voxel by voxel, on
// the same moves: every block's volume, the warnings and collisions, and the final values at
// voxel centres must agree to rounding, over bars and tubes, voxel sizes, positions on and off
// voxel centres, coincident faces (ghost sheets), arcs, grooves, runs of short moves, and a cut
// made with the spindle stopped midway (the table then hands over to the level set).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "geometry/convex_polygon.hpp"
#include "interp/control/control_preset.hpp"
#include "interp/interpreter.hpp"
#include "sim/cut_history.hpp"
#include "sim/move_sweep.hpp"
#include "sim/cut_rules.hpp"
#include "sim/revolved_table.hpp"
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

struct TableCase {
  double voxelMm;
  double boreMm;   // 0: a bar
  double shiftMm;  // moves every cut's radius and Z by this much (on and off voxel centres)
  bool slotMidway; // a cut with the spindle stopped after the turning cuts
};

// A program's worth of revolved cuts on a Φ20 × 16 bar (face at Z0), shifted by `s`.
interp::Toolpath program(const TableCase& c) {
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

// φ at every voxel centre of every `step`-th Z layer over the bar, and of the layers next to
// its end faces (where a cut along a face leaves ghost sheets), in mm.
std::vector<double> valuesAtVoxelCentres(const Stock& stock, const StockSpec& spec, double voxelMm, int step) {
  const int r = static_cast<int>(std::ceil(spec.diameterMm / 2.0 / voxelMm)) + 4;
  const int zLow = static_cast<int>(std::floor((spec.faceZMm - spec.lengthMm) / voxelMm)) - 4;
  const int zHigh = static_cast<int>(std::ceil(spec.faceZMm / voxelMm)) + 4;
  const auto nextToAFace = [&](int k) { return std::min(std::abs(k - zLow - 4), std::abs(zHigh - 4 - k)) <= 1; };
  std::vector<Eigen::Vector3d> points;
  for (int k = zLow; k <= zHigh; ++k)
    if ((k - zLow) % step == 0 || nextToAFace(k))
      for (int i = -r; i <= r; ++i)
      for (int j = -r; j <= r; ++j) points.emplace_back(i * voxelMm, j * voxelMm, k * voxelMm);
  std::vector<double> values(points.size());
  stock.signedDistancesAt(points, values);
  return values;
}

// Simulates `toolpath` on `spec` through the table and voxel by voxel and compares every
// block's volume, the warnings and collisions, and φ at voxel centres.
void expectTheSameStock(const StockSpec& spec, double voxelMm, const interp::Toolpath& toolpath, int layerStep) {
  Stock byTable(spec, voxelMm, RevolvedWrites::Table);
  Stock byVoxels(spec, voxelMm, RevolvedWrites::Voxels);
  const SimulationResult table = simulate(toolpath, tools(), byTable);
  const SimulationResult voxels = simulate(toolpath, tools(), byVoxels);

  // Rounding: the table sums a class's columns as one product, the level set voxel by voxel;
  // and the columns of a class compute ρ = √(x² + y²) to within an ulp of each other, so a
  // stored float can round one step apart (1.2e-7 of the band: 3.6e-7 of a voxel's share).
  const double voxelVolume = voxelMm * voxelMm * voxelMm;
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

  const std::vector<double> fromTable = valuesAtVoxelCentres(byTable, spec, voxelMm, layerStep);
  const std::vector<double> fromVoxels = valuesAtVoxelCentres(byVoxels, spec, voxelMm, layerStep);
  // Every value lies in the band, on both routes: a block split from a tile once took a
  // heap address's bits as its value (region_writer.cpp, restructure), a leaf of garbage
  // deep inside the material in about one run in five.
  const double band = kHalfBandVoxels * voxelMm * (1.0 + 1e-6);
  double largest = 0.0;
  std::size_t outOfBand = 0;
  for (std::size_t n = 0; n < fromTable.size(); ++n) {
    outOfBand += !(std::abs(fromVoxels[n]) <= band) + !(std::abs(fromTable[n]) <= band);
    largest = std::max(largest, std::abs(fromTable[n] - fromVoxels[n]));
  }
  EXPECT_EQ(outOfBand, 0u);
  EXPECT_LE(largest, 1e-5 * voxelMm);
  // A cut with the spindle stopped and a part-off hand the stock to the level set; nothing
  // else in these programs may (ghosts a class's columns disagree on are kept apart as air
  // voxels).
  const bool slot = std::any_of(toolpath.moves.begin(), toolpath.moves.end(),
                                [](const interp::Move& m) { return !spindleTurns(m); });
  EXPECT_EQ(table.partOffs.size(), voxels.partOffs.size());
  EXPECT_EQ(byTable.isRevolved(), !slot && table.partOffs.empty());
}

TEST(RevolvedTable, GivesWhatTheLevelSetWrittenVoxelByVoxelGives) {
  const std::vector<TableCase> cases{{0.1, 0.0, 0.0, false},   {0.1, 0.0, 0.037, true},  {0.13, 0.0, 0.011, false},
                                {0.13, 8.0, 0.0, true},   {0.2, 8.0, 0.071, false}, {0.2, 0.0, 0.1, true}};
  for (const TableCase& c : cases) {
    SCOPED_TRACE(testing::Message() << "voxel " << c.voxelMm << " mm, bore " << c.boreMm << ", shift " << c.shiftMm
                                    << (c.slotMidway ? ", a slot midway" : ""));
    expectTheSameStock(StockSpec{20.0, 16.0, 0.0, c.boreMm}, c.voxelMm, program(c), 3);
  }
}

// A longer bar, Φ44 × 90 with 1 mm to face: faced to X0 twice (whole solid chunks turn to air,
// chunks near the old face from mixed back to uniform), turned in steps down to Φ12 (the
// steps' faces and shoulders), a long taper and a face cut through a step. Its table holds
// cells only near the profile: most of its chunks are uniform, and they change.
interp::Toolpath steppedBar(double s) {
  Path p;
  p.feed({23.0, 0.4 + s}, {-0.5, 0.4 + s});  // G94 to X0: the first face
  p.feed({23.0, 0.0}, {-0.5, 0.0});          // the finish face, on Z0 exactly
  for (const auto& [radius, zEnd] : {std::pair{19.0, -70.0}, {15.5 + s, -45.0}, {11.0 + s, -20.0}, {6.0 + s, -8.0}}) {
    p.feed({radius, 1.0}, {radius, zEnd + s});
    p.feed({radius, zEnd + s}, {23.0, zEnd + s});  // up the shoulder
  }
  p.feed({19.0, -72.0 + s}, {16.0 + s, -85.0});   // a taper into the bar
  p.feed({23.0, -30.0 + s}, {-0.5, -30.0 + s}, kGroovingTool);  // a face cut through a step, to X0
  return p.toolpath;
}

TEST(RevolvedTable, GivesWhatTheLevelSetGivesOnALongerBarFacedAndStepped) {
  for (const auto& [voxelMm, shiftMm] : {std::pair{0.25, 0.0}, {0.17, 0.043}, {0.31, 0.11}}) {
    SCOPED_TRACE(testing::Message() << "voxel " << voxelMm << " mm, shift " << shiftMm);
    expectTheSameStock(StockSpec{44.0, 91.0, 1.0, 0.0}, voxelMm, steppedBar(shiftMm), 7);
  }
}

// Seed 000's face and taper passes (GSK G94 with R, parts/seed000-face-taper) scaled to a Φ50
// bar, its back face at Z-44.2. Its second face pass ends on that face at the pass's diameter:
// a ghost sheet lies along the back face, and near the step at the pass's radius some of a
// class's columns see a material neighbour and others do not (parts/'s program makes 168 such
// voxels at 0.2 mm and 324 at 0.1; these, 56–172). The table keeps them apart as air voxels
// and stays the stock, voxel for voxel as the level set's writer leaves it.
interp::Toolpath faceAndTaperPasses(double facedDiameterMm, double shiftMm) {
  std::string text = "G00 X52 Z5 M3 S500\nG94 X0 Z0 F200\nX" + std::to_string(facedDiameterMm) +
                     " Z-44.2 F300\nG00 X48 Z0\n";
  const double z = -12.0 + shiftMm;
  for (int pass = 1; pass <= 5; ++pass)
    text += (pass == 1 ? "G94 X" : "X") + std::to_string(48.0 - 4.8 * pass) + (pass == 1 ? " Z" + std::to_string(z) : "") +
            " R" + std::to_string(-4.0 * pass) + "\n";
  text += "M30\n";
  interp::InterpreterOptions options;
  options.control = interp::controlPreset("gsk980tdi")->parameters;
  options.startPosition = RZ(60.0, 20.0);
  interp::Toolpath toolpath = interp::interpret(text, "face-taper.nc", options).toolpath;
  for (interp::Move& move : toolpath.moves) move.tool = kSharpTool;
  return toolpath;
}

TEST(RevolvedTable, KeepsGhostsItsColumnsDisagreeOnApartAndStaysTheStock) {
  struct FaceCase {
    double voxelMm, facedDiameterMm, shiftMm;
  };
  for (const FaceCase& c : {FaceCase{0.2, 48.0, 0.0}, {0.13, 46.0, 0.037}, {0.1, 44.4, 0.0}}) {
    SCOPED_TRACE(testing::Message() << "voxel " << c.voxelMm << " mm, faced to X" << c.facedDiameterMm << ", shift " << c.shiftMm);
    const interp::Toolpath toolpath = faceAndTaperPasses(c.facedDiameterMm, c.shiftMm);
    ASSERT_GT(toolpath.moves.size(), 20u);
    expectTheSameStock(StockSpec{50.0, 45.0, 0.8, 0.0}, c.voxelMm, toolpath, 11);
  }
}

// A write's work is shared among threads only past a size (RevolvedTable::ParallelThresholds),
// so each write of the tests above takes one route. Forced one way and then the other over the
// same moves, on and off voxel centres, with ghost sheets and air voxels, the tables must agree
// to the last bit: every write's lost voxels, the leaves it changed, every voxel's value and
// active bit.
TEST(RevolvedTable, GivesTheSameTableOnOneThreadAsSharedAmongThreads) {
  struct RouteCase {
    StockSpec spec;
    double voxelMm;
    interp::Toolpath toolpath;
  };
  const std::vector<RouteCase> cases{{StockSpec{20.0, 16.0, 0.0, 0.0}, 0.1, program({0.1, 0.0, 0.0, false})},
                                     {StockSpec{20.0, 16.0, 0.0, 0.0}, 0.13, program({0.13, 0.0, 0.037, false})},
                                     {StockSpec{50.0, 45.0, 0.8, 0.0}, 0.2, faceAndTaperPasses(48.0, 0.0)}};
  std::size_t airVoxels = 0;
  for (const RouteCase& c : cases) {
    SCOPED_TRACE(testing::Message() << "Φ" << c.spec.diameterMm << ", voxel " << c.voxelMm << " mm");
    const double h = c.voxelMm, radius = c.spec.diameterMm / 2.0, back = c.spec.faceZMm - c.spec.lengthMm;
    const float band = static_cast<float>(kHalfBandVoxels * h);
    const int halfWidth = static_cast<int>(std::ceil(radius / h)) + 5;
    const int kFirst = static_cast<int>(std::floor(back / h)) - 5, kLast = static_cast<int>(std::ceil(c.spec.faceZMm / h)) + 5;
    RevolvedTable alone(halfWidth, kFirst, kLast, h, band, radius + band + 2.0 * h);
    RevolvedTable shared = alone;
    alone.setParallelThresholds(RevolvedTable::ParallelThresholds::never());
    shared.setParallelThresholds(RevolvedTable::ParallelThresholds::always());
    const std::vector<RZ> section{{-radius, back}, {radius, back}, {radius, c.spec.faceZMm}, {-radius, c.spec.faceZMm}};
    const RevolvedRegion bar({ConvexPolygon::hullOf(section)});
    ASSERT_EQ(alone.write(bar, true), shared.write(bar, true));
    alone.takeMeridianFlips();
    shared.takeMeridianFlips();
    CutHistory history;
    const ToolOutlines outlines = tools();
    // The meridian plane's voxels (i, 0, k), i ≥ 0, before and after each write: the box of
    // those that turned from material to air is what takeMeridianFlips gives, on either route.
    std::vector<float> plane, planeBefore;
    const auto readPlane = [&] {
      plane.clear();
      for (int i = 0; i <= halfWidth; ++i)
        for (int k = kFirst; k <= kLast; ++k) plane.push_back(alone.value(i, 0, k));
    };
    int movesWithFlips = 0;
    readPlane();
    for (std::size_t m = 0; m < c.toolpath.moves.size(); ++m) {
      const std::vector<ConvexPolygon> pieces = sweptPieces(c.toolpath.moves[m], outlines.at(c.toolpath.moves[m].tool), h);
      if (pieces.empty()) continue;
      const RevolvedRegion region(pieces);
      const std::optional<RevolvedRegion> changes = history.changesOf(pieces);
      const RevolvedRegion* bound = changes ? &*changes : nullptr;
      ASSERT_EQ(alone.write(region, false, bound), shared.write(region, false, bound)) << "move " << m;
      planeBefore.swap(plane);
      readPlane();
      MeridianBox flips;
      for (int i = 0, n = 0; i <= halfWidth; ++i)
        for (int k = kFirst; k <= kLast; ++k, ++n)
          if (planeBefore[n] < 0.0f && plane[n] >= 0.0f) flips.add(i, k);
      movesWithFlips += !flips.empty();
      ASSERT_TRUE(alone.takeMeridianFlips() == flips) << "move " << m;
      ASSERT_TRUE(shared.takeMeridianFlips() == flips) << "move " << m;
      const std::vector<VoxelIndex> aloneLeaves = alone.changedLeaves(), sharedLeaves = shared.changedLeaves();
      ASSERT_EQ(aloneLeaves.size(), sharedLeaves.size()) << "move " << m;
      for (std::size_t n = 0; n < aloneLeaves.size(); ++n)
        ASSERT_TRUE(aloneLeaves[n].i == sharedLeaves[n].i && aloneLeaves[n].j == sharedLeaves[n].j && aloneLeaves[n].k == sharedLeaves[n].k)
            << "move " << m << ", leaf " << n;
    }
    ASSERT_EQ(alone.airVoxelCount(), shared.airVoxelCount());
    airVoxels += alone.airVoxelCount();
    std::size_t differing = 0, material = 0, columnReadDiffering = 0;
    std::vector<float> column(kLast - kFirst + 3);
    for (int i = -halfWidth; i <= halfWidth; ++i)
      for (int j = -halfWidth; j <= halfWidth; ++j) {
        // A column read whole (a voxel beyond each end of the table too) gives what value() gives.
        alone.columnValues(i, j, kFirst - 1, static_cast<int>(column.size()), column.data(), 1);
        for (int k = kFirst - 1; k <= kLast + 1; ++k) columnReadDiffering += column[k - kFirst + 1] != alone.value(i, j, k);
        for (int k = kFirst; k <= kLast; ++k) {
          differing += alone.value(i, j, k) != shared.value(i, j, k) || alone.active(i, j, k) != shared.active(i, j, k);
          material += alone.value(i, j, k) < 0.0f;
        }
      }
    EXPECT_EQ(differing, 0u);
    EXPECT_EQ(columnReadDiffering, 0u);
    EXPECT_GT(material, 0u);
    EXPECT_GT(movesWithFlips, 5);
  }
  EXPECT_GT(airVoxels, 0u);  // the route of ghosts a class's columns disagree on was taken
}

// A write's volume is the material its voxels held before less what they hold after, each
// voxel's share counted as the level set counts it (½ − φ/h, clamped to 0…1) with its air
// voxels read as air. The face and taper passes leave air voxels (ghosts some of a class's
// columns disagree on) beside cells still partly material; then the bar is faced to X0 well
// past its back face and everything goes. Counted here voxel by voxel through value(), the
// lost volume must match the write's own sum, which takes back what the air voxels (already
// air) did not lose: without that term it counts them twice.
double materialVoxels(const RevolvedTable& table, int halfWidth, int kFirst, int kLast, double h) {
  std::vector<float> column(kLast - kFirst + 1);
  double sum = 0.0;
  for (int i = -halfWidth; i <= halfWidth; ++i)
    for (int j = -halfWidth; j <= halfWidth; ++j) {
      table.columnValues(i, j, kFirst, static_cast<int>(column.size()), column.data(), 1);
      for (const float v : column) sum += std::clamp(0.5 - v / h, 0.0, 1.0);
    }
  return sum;
}

TEST(RevolvedTable, AWriteLosesWhatItsVoxelsHeldCountingAirVoxelsAsAir) {
  struct FaceCase {
    double voxelMm, facedDiameterMm, shiftMm;
  };
  for (const FaceCase& c : {FaceCase{0.2, 48.0, 0.0}, {0.13, 46.0, 0.037}, {0.1, 44.4, 0.0}}) {
    SCOPED_TRACE(testing::Message() << "voxel " << c.voxelMm << " mm, faced to X" << c.facedDiameterMm << ", shift " << c.shiftMm);
    const StockSpec spec{50.0, 45.0, 0.8, 0.0};
    const double h = c.voxelMm, radius = spec.diameterMm / 2.0, back = spec.faceZMm - spec.lengthMm;
    const int halfWidth = static_cast<int>(std::ceil(radius / h)) + 5;
    const int kFirst = static_cast<int>(std::floor(back / h)) - 5, kLast = static_cast<int>(std::ceil(spec.faceZMm / h)) + 5;
    RevolvedTable table(halfWidth, kFirst, kLast, h, static_cast<float>(kHalfBandVoxels * h), radius + kHalfBandVoxels * h + 2.0 * h);
    const std::vector<RZ> section{{-radius, back}, {radius, back}, {radius, spec.faceZMm}, {-radius, spec.faceZMm}};
    table.write(RevolvedRegion({ConvexPolygon::hullOf(section)}), true);
    const ToolOutlines outlines = tools();
    const interp::Toolpath toolpath = faceAndTaperPasses(c.facedDiameterMm, c.shiftMm);
    for (const interp::Move& move : toolpath.moves) {
      const std::vector<ConvexPolygon> pieces = sweptPieces(move, outlines.at(move.tool), h);
      if (!pieces.empty()) table.write(RevolvedRegion(pieces), false);
    }
    ASSERT_GT(table.airVoxelCount(), 0u);
    const double before = materialVoxels(table, halfWidth, kFirst, kLast, h);
    // A block wider and longer than the bar: every voxel turns to air.
    const std::vector<RZ> everything{{-radius - 1.0, back - 1.0}, {radius + 1.0, back - 1.0},
                                      {radius + 1.0, spec.faceZMm + 1.0}, {-radius - 1.0, spec.faceZMm + 1.0}};
    const double lost = table.write(RevolvedRegion({ConvexPolygon::hullOf(everything)}), false);
    EXPECT_NEAR(materialVoxels(table, halfWidth, kFirst, kLast, h), 0.0, 1e-9);
    EXPECT_NEAR(lost, before, 1e-7 * before);
  }
}

// The table's cells follow the band of the profile: on a Φ40 × 120 bar at 0.1 mm a chunk of 8
// cells holds cells exactly where some cell lies nearer the surface than the band (worked out
// here from the rectangle's own distance), and the table weighs a small part of what one float
// per class and Z cell would.
TEST(RevolvedTable, HoldsCellsOnlyWhereTheBandIs) {
  constexpr double kVoxel = 0.1, kRadius = 20.0, kFaceZ = 0.0, kBackZ = -120.0;
  const float band = static_cast<float>(kHalfBandVoxels * kVoxel);
  const int halfWidth = static_cast<int>(std::ceil(kRadius / kVoxel)) + 5;
  const int kFirst = static_cast<int>(std::floor(kBackZ / kVoxel)) - 5, kLast = static_cast<int>(std::ceil(kFaceZ / kVoxel)) + 5;
  RevolvedTable table(halfWidth, kFirst, kLast, kVoxel, band, kRadius + band + 2.0 * kVoxel);
  const std::vector<RZ> section{{-kRadius, kBackZ}, {kRadius, kBackZ}, {kRadius, kFaceZ}, {-kRadius, kFaceZ}};
  table.write(RevolvedRegion({ConvexPolygon::hullOf(section)}), true);

  // The bar's signed distance in the meridian plane at (ρ, z).
  const auto distance = [&](double rho, double z) {
    const double outRho = rho - kRadius, outZ = std::max(z - kFaceZ, kBackZ - z);
    if (outRho <= 0.0 && outZ <= 0.0) return std::max(outRho, outZ);
    return std::hypot(std::max(outRho, 0.0), std::max(outZ, 0.0));
  };
  const int kBase = kFirst & ~7;
  std::size_t mixed = 0, chunks = 0, surelyMixed = 0, wronglyMixed = 0, wronglyUniform = 0, wronglyValued = 0;
  // The classes in ascending i² + j² up to the air radius, as the table numbers them; each
  // read through one of its columns.
  const double airCells = (kRadius + band + 2.0 * kVoxel) / kVoxel;
  const int largestSum = static_cast<int>(std::floor(airCells * airCells));
  std::vector<int> columnOfSum(largestSum + 1, -1);
  for (int i = 0; i <= halfWidth; ++i)
    for (int j = 0; j <= i && i * i + j * j <= largestSum; ++j) columnOfSum[i * i + j * j] = i * (halfWidth + 1) + j;
  int classes = 0;
  for (int n = 0; n <= largestSum; ++n) {
    if (columnOfSum[n] < 0) continue;
    ++classes;
    const int i = columnOfSum[n] / (halfWidth + 1), j = columnOfSum[n] % (halfWidth + 1);
    const double rho = std::hypot(i * kVoxel, j * kVoxel);
      for (int k0 = kBase; k0 <= kLast; k0 += 8) {
        ++chunks;
        double nearest = 1e9;
        for (int k = k0; k < k0 + 8; ++k) nearest = std::min(nearest, std::abs(distance(rho, k * kVoxel)));
        std::uint8_t bits = 0;
        const float* cells = table.column(i, j, k0, bits);
        bool isMixed = bits != 0;
        for (int k = 0; k < 8 && cells; ++k) isMixed |= cells[k] != cells[0] || std::abs(cells[k]) < band;
        mixed += isMixed;
        // Rounding at the band's edge aside, a cell nearer than the band is active.
        if (nearest < band - 1e-4) {
          ++surelyMixed;
          wronglyUniform += !isMixed;
        } else if (nearest > band + 1e-4) {
          wronglyMixed += isMixed;
          // Uniform: air outside the bar, solid inside it.
          const float expected = distance(rho, (k0 + 4) * kVoxel) > 0.0 ? band : -band;
          wronglyValued += (cells ? cells[0] : band) != expected;
        }
      }
  }
  std::size_t stored = 0;
  for (int c = 0; c < classes; ++c) table.forEachMixedChunk(c, [&](int, const float*, std::uint8_t) { ++stored; });
  EXPECT_EQ(stored, mixed);  // exactly the chunks not uniform hold cells
  EXPECT_GT(classes, 1000);
  EXPECT_GT(surelyMixed, 10000u);
  EXPECT_EQ(wronglyUniform, 0u);
  EXPECT_EQ(wronglyMixed, 0u);
  EXPECT_EQ(wronglyValued, 0u);
  // A tenth of the chunks at most are mixed here (the band is 0.6 mm of a 20 mm radius).
  EXPECT_LT(mixed, chunks / 10);
  const double dense = static_cast<double>(chunks) * (8 * sizeof(float) + 2);
  EXPECT_LT(static_cast<double>(table.bytes()), dense / 4);
}

}  // namespace
}  // namespace lathesim::sim
