// Part-off: a cut that separates the bar is found, the piece that falls is taken out of the
// stock, and both are measured against volumes worked out by hand (cylinders and rings).
// Programs are read by the interpreter, so G75's pecks are its own; the blade is 3 mm wide,
// programmed at its +Z corner, so a cut at Z leaves the kerf Z−3 … Z.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "interp/interpreter.hpp"
#include "sim/simulate.hpp"

namespace lathesim::sim {
namespace {

constexpr double kBladeWidthMm = 3.0;

ToolOutlines tools() {
  ToolOutlines outlines;
  const std::vector<RZ> blade{{0, 0}, {15, 0}, {15, -kBladeWidthMm}, {0, -kBladeWidthMm}};
  outlines.emplace(1, *ConvexPolygon::fromOutline(blade).polygon);
  const std::vector<RZ> axialBlade{{0, 0}, {2, 0}, {2, 20}, {0, 20}};  // a face groove 2 mm wide
  outlines.emplace(2, *ConvexPolygon::fromOutline(axialBlade).polygon);
  const std::vector<RZ> innerBlade{{0, 0}, {6, 0}, {6, 3}, {0, 3}};  // an internal groove 3 mm wide
  outlines.emplace(3, *ConvexPolygon::fromOutline(innerBlade).polygon);
  const std::vector<RZ> turning{{0, 0}, {10, 1}, {12, 12}, {1, 10}};  // the default tool, flanks leaning 1 in 10
  outlines.emplace(4, *ConvexPolygon::fromOutline(turning).polygon);
  const std::vector<RZ> small{{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // a 1 mm finishing insert: r, Z tip … tip + 1
  outlines.emplace(5, *ConvexPolygon::fromOutline(small).polygon);
  return outlines;
}

interp::Toolpath toolpathOf(const std::string& program) {
  interp::InterpreterOptions options;
  options.startPosition = {50.0, 50.0};
  options.toolNumbers = {1, 2, 3, 4, 5};
  interp::InterpretResult result = interp::interpret(program, "part_off.nc", options);
  EXPECT_TRUE(result.ok()) << (result.diagnostics.empty() ? "" : interp::format(result.diagnostics[0]));
  return result.toolpath;
}

struct PartOffRun {
  SimulationResult result;
  double stubMm3 = 0;  // what is left in the stock
};

PartOffRun simulateProgram(const StockSpec& bar, double voxelMm, const std::string& program,
                           RevolvedWrites writes = RevolvedWrites::Table) {
  Stock stock(bar, voxelMm, writes);
  PartOffRun run;
  run.result = simulate(toolpathOf(program), tools(), stock);
  run.stubMm3 = stock.volumeMm3();
  return run;
}

// 5 % of a voxel layer over a solid's surface, as the README states for every volume.
double tolerance(double surfaceMm2, double voxelMm) { return 0.05 * voxelMm * surfaceMm2; }
// A cylinder's or a tube's surface, r the bore's radius.
double surface(double outer, double inner, double length) {
  return 2 * M_PI * (outer + inner) * length + 2 * M_PI * (outer * outer - inner * inner);
}

// A bar Φ40 × 50 (Z-50 … 0), parted by G01 to X0 or past the centre, at Z positions on and off
// the voxel grid: the piece Z … 0 falls (400π·|Z|), the stub Z-50 … Z−3 stays.
TEST(PartOff, G01ToTheCentreOrPastItPartsTheBar) {
  const StockSpec bar{40.0, 50.0, 0.0};
  for (const double voxel : {0.25, 0.4})
    for (const double z : {-20.0, -31.3})
      for (const char* endX : {"X0.", "X-2.", "X-6."}) {
        SCOPED_TRACE(testing::Message() << voxel << " mm voxels, Z" << z << ", G01 " << endX);
        const std::string program = "G99 M03 S500\nG00 X44. Z" + std::to_string(z) + "\nG01 " + endX +
                                    " F0.05\nG00 X60.\nM30\n";
        const PartOffRun run = simulateProgram(bar, voxel, program);
        ASSERT_EQ(run.result.partOffs.size(), 1u);
        const PartOff& off = run.result.partOffs[0];
        EXPECT_EQ(off.line, 3);
        EXPECT_EQ(off.column, 1);
        EXPECT_NEAR(off.zMm, z, 1e-9);
        const double pieceLength = -z, stubLength = 50.0 + z - kBladeWidthMm;
        EXPECT_NEAR(off.volumeMm3, 400 * M_PI * pieceLength, tolerance(surface(20, 0, pieceLength), voxel));
        EXPECT_NEAR(run.stubMm3, 400 * M_PI * stubLength, tolerance(surface(20, 0, stubLength), voxel));
        ASSERT_TRUE(run.result.part);
        EXPECT_NEAR(run.result.part->volumeMm3(), off.volumeMm3, 1e-6);
        EXPECT_FALSE(off.catcher);
        EXPECT_TRUE(run.result.warnings.empty()) << run.result.warnings[0].message;
      }
}

// With the spindle stopped the same G01 to X-2. cuts a straight slot (4 mm thick, the default
// insert's) in the plane y = 0 where the section is read: the section falls in two, yet the
// bar still holds together at every other angle, so nothing parts off. The slot takes 3 mm of
// Z times the bar's section within |y| ≤ 2, x ≥ −1: 4·1 + ∫₋₂² √(400 − y²) dy = 4 + 2(√396 +
// 200·asin 0.1) = 83.86646 mm², 251.5994 mm³; the rapid back out (G00 X60.) runs in the slot
// and takes nothing more. A rapid in (G00 X-2.) with the spindle stopped cuts the same slot,
// reported as a rapid into the stock of that volume: it is no ring, and parts nothing. A
// blade 50 mm thick (wider than the bar) cut past the whole bar (G01 X-44.) severs it in 3D
// too, and the piece Z-20 … 0 falls: 400π·20.
TEST(PartOff, ASlotCutWithTheSpindleStoppedPartsOnlyWhenItSevers) {
  const StockSpec bar{40.0, 50.0, 0.0};
  const double slotMm3 = 3.0 * (4.0 + 2.0 * (std::sqrt(396.0) + 200.0 * std::asin(0.1)));
  EXPECT_NEAR(slotMm3, 251.5994, 1e-4);
  const double slotSurface = 2 * 83.86646 + 3.0 * (2 * 40.0 + 4.0);
  // On and off the voxel grid, at two voxel sizes: the slot's volume is the same wherever it is.
  for (const double voxel : {0.25, 0.4})
    for (const std::string z : {"-20.", "-31.3"}) {
      SCOPED_TRACE(testing::Message() << voxel << " mm voxels, Z" << z);
      const double slotTolerance = tolerance(surface(20, 0, 50) + slotSurface, voxel);
      const PartOffRun slot = simulateProgram(bar, voxel, "G99\nG00 X44. Z" + z + "\nG01 X-2. F0.05\nG00 X60.\nM30\n");
      EXPECT_TRUE(slot.result.partOffs.empty());
      EXPECT_FALSE(slot.result.part);
      EXPECT_TRUE(slot.result.collisions.empty());
      EXPECT_NEAR(slot.stubMm3, 400 * M_PI * 50 - slotMm3, slotTolerance);

      const PartOffRun rapid = simulateProgram(bar, voxel, "G99\nG00 X44. Z" + z + "\nG00 X-2.\nG00 X60.\nM30\n");
      EXPECT_TRUE(rapid.result.partOffs.empty());
      EXPECT_FALSE(rapid.result.part);
      ASSERT_EQ(rapid.result.collisions.size(), 1u);
      EXPECT_EQ(rapid.result.collisions[0].line, 3);
      EXPECT_EQ(rapid.result.collisions[0].kind, "rapid_into_stock");
      EXPECT_NEAR(rapid.result.collisions[0].volumeMm3, slotMm3, slotTolerance);
      EXPECT_NEAR(rapid.stubMm3, 400 * M_PI * 50 - slotMm3, slotTolerance);
    }
  const double voxel = 0.25;
  Stock stock(bar, voxel);
  const SimulationResult through = simulate(toolpathOf("G99\nG00 X44. Z-20.\nG01 X-44. F0.05\nM30\n"),
                                            tools(), stock, {{}, nullptr, ToolThicknesses{{1, 50.0}}, {}});
  ASSERT_EQ(through.partOffs.size(), 1u);
  EXPECT_NEAR(through.partOffs[0].volumeMm3, 400 * M_PI * 20, tolerance(surface(20, 0, 20), voxel));
  EXPECT_NEAR(stock.volumeMm3(), 400 * M_PI * 27, tolerance(surface(20, 0, 27), voxel));
}

// G75 to X-1 in 3 mm pecks (P6000: Δi on the diameter): the piece falls on the cycle's line.
TEST(PartOff, G75PeckCyclePartsTheBarOnItsLine) {
  const PartOffRun run = simulateProgram({40.0, 50.0, 0.0}, 0.25,
                                  "G99 M03 S500\nG00 X42. Z-25.\nG75 R0.5\nG75 X-1. P6000 F0.05\nG00 X60.\nM30\n");
  ASSERT_EQ(run.result.partOffs.size(), 1u);
  EXPECT_EQ(run.result.partOffs[0].line, 4);
  EXPECT_NEAR(run.result.partOffs[0].zMm, -25.0, 1e-9);
  EXPECT_NEAR(run.result.partOffs[0].volumeMm3, 400 * M_PI * 25, tolerance(surface(20, 0, 25), 0.25));
  EXPECT_NEAR(run.stubMm3, 400 * M_PI * 22, tolerance(surface(20, 0, 22), 0.25));
}

// A tube Φ40 with a Φ20 bore parts when the blade passes the bore (r 10), not before.
TEST(PartOff, ATubePartsWhenTheCutReachesItsBore) {
  const StockSpec tube{40.0, 50.0, 0.0, 20.0};
  for (const double voxel : {0.25, 0.4}) {
    SCOPED_TRACE(testing::Message() << voxel << " mm voxels");
    const PartOffRun parted = simulateProgram(tube, voxel, "G99 M03 S500\nG00 X44. Z-18.7\nG01 X18. F0.05\nG00 X60.\nM30\n");
    ASSERT_EQ(parted.result.partOffs.size(), 1u);
    EXPECT_EQ(parted.result.partOffs[0].line, 3);
    EXPECT_NEAR(parted.result.partOffs[0].volumeMm3, 300 * M_PI * 18.7, tolerance(surface(20, 10, 18.7), voxel));
    EXPECT_NEAR(parted.stubMm3, 300 * M_PI * 28.3, tolerance(surface(20, 10, 28.3), voxel));

    // To X22 (r 11) the wall keeps a 1 mm ring: a groove, nothing falls.
    const PartOffRun grooved = simulateProgram(tube, voxel, "G99 M03 S500\nG00 X44. Z-18.7\nG01 X22. F0.05\nG00 X60.\nM30\n");
    EXPECT_TRUE(grooved.result.partOffs.empty());
    EXPECT_FALSE(grooved.result.part);
    EXPECT_NEAR(grooved.stubMm3, 300 * M_PI * 50 - (400 - 121) * M_PI * 3, tolerance(surface(20, 10, 50), voxel));
  }
}

// A groove that leaves a core of Φ2 (four voxels of radius at 0.25 mm) holds the bar together.
TEST(PartOff, AGrooveThatLeavesACoreDoesNotPartTheBar) {
  const PartOffRun run = simulateProgram({40.0, 50.0, 0.0}, 0.25, "G99 M03 S500\nG00 X44. Z-20.\nG01 X2. F0.05\nG00 X60.\nM30\n");
  EXPECT_TRUE(run.result.partOffs.empty());
  EXPECT_FALSE(run.result.part);
}

// Facing to X0 with a flank that leans 1 in 10 leaves a cone on the axis, its point on the face
// (r < z/10 over the 1 mm cut: 0.01 mm³): loose, but a crumb, not a part.
TEST(PartOff, ThePipAFaceCutToTheCentreLeavesIsNoPart) {
  for (const double voxel : {0.2, 0.25}) {
    const PartOffRun run = simulateProgram({40.0, 50.0, 1.0}, voxel, "G99 M03 S500\nT0404\nG00 X44. Z0.\nG01 X0. F0.2\nM30\n");
    EXPECT_TRUE(run.result.partOffs.empty()) << voxel << " mm voxels: " << run.result.partOffs[0].volumeMm3 << " mm³";
    EXPECT_NEAR(run.stubMm3, 400 * M_PI * 49, tolerance(surface(20, 0, 49), voxel));  // Z-49..0 left
  }
}

// The section falls in two with no Z free of material: a face groove (r 14…16, 10 deep) meets an
// internal groove from the bore (r 10…16, Z-12…-9), and the ring r 10…14, Z-9…0 comes loose
// while the outside (r 16…20) runs on to the face: 96π·9 = 864π mm³ falls. It holds less than
// half of the material from Z-9 on (the outside holds 144π·9 = 1296π): no part-off, a loose
// ring warned of on its line, and the stock (all but the ring) stays the part.
TEST(PartOff, ARingCutLooseInsideATubeFallsAndIsNoPart) {
  const double voxel = 0.25;
  const PartOffRun run = simulateProgram({40.0, 50.0, 0.0, 20.0}, voxel,
                                  "G99 M03 S500\nT0202\nG00 X28. Z2.\nG01 Z-10. F0.05\nG00 Z2.\n"
                                  "T0303\nG00 X8.\nZ-12.\nG01 X20.\nG00 X8.\nG00 Z5.\nM30\n");
  EXPECT_TRUE(run.result.partOffs.empty());
  EXPECT_FALSE(run.result.part);
  ASSERT_EQ(run.result.loosePieces.size(), 1u);
  const LoosePiece& ring = run.result.loosePieces[0];
  EXPECT_EQ(ring.line, 9);
  const double ringSurface = surface(14, 10, 9);
  EXPECT_NEAR(ring.volumeMm3, 864 * M_PI, tolerance(ringSurface, voxel));
  EXPECT_NEAR(ring.rInnerMm, 10.0, voxel);
  EXPECT_NEAR(ring.rOuterMm, 14.0, voxel);
  EXPECT_NEAR(ring.zLowMm, -9.0, voxel);
  EXPECT_NEAR(ring.beyondMm3, 1296 * M_PI, tolerance(surface(20, 16, 9), voxel));
  ASSERT_EQ(run.result.warnings.size(), 1u);
  EXPECT_EQ(run.result.warnings[0].line, 9);
  EXPECT_NE(run.result.warnings[0].message.find("a 4.0 mm ring (Φ20.0 to Φ28.0, Z-9.0 to Z0.0) of "),
            std::string::npos)
      << run.result.warnings[0].message;
  EXPECT_NE(run.result.warnings[0].message.find("comes loose at line 9"), std::string::npos);
  const double stubMm3 = 300 * M_PI * 50 - 60 * M_PI * 10 - 156 * M_PI * 3 - 864 * M_PI + 60 * M_PI * 1;
  EXPECT_NEAR(run.stubMm3, stubMm3, tolerance(surface(20, 10, 50) + ringSurface, voxel));
}

// A finishing pass run on a full bar Φ40 (Z-50…0) with a 1 mm insert (tip at r, Z; the insert
// r … r+1, Z … Z+1): G01 X36 from Z2 to Z-25 takes the band r 18…19, and G01 X42 Z-28 leaves
// it along a diagonal whose sweep's upper edge, the insert's corner (r+1, Z+1), runs from
// (19, -24) to (22, -27): z = −5 − r. The 1 mm skin r 19…20 above that edge hangs on nothing:
// ∫₁₉²⁰ 2πr (5 + r) dr = 2π (2.5·39 + 1141/3) = 955.667π mm³ falls at line 5. The core r < 18
// holds 324π·24 mm³ and more from the skin's lowest Z (-25) on: the skin is a tenth of it, no
// part-off. The shaft stays the part; the skin is warned of and kept out of it.
TEST(PartOff, AFinishingPassThatSetsASkinLooseOnAFullBarIsNoPartOff) {
  for (const double voxel : {0.1, 0.2, 0.25, 0.4}) {
    SCOPED_TRACE(testing::Message() << voxel << " mm voxels");
    const StockSpec bar{40.0, 50.0, 0.0};
    const PartOffRun run = simulateProgram(bar, voxel, "G99 M03 S500\nT0505\nG00 X36. Z2.\nG01 Z-25. F0.1\n"
                                                       "G01 X42. Z-28.\nG00 X60.\nM30\n");
    EXPECT_TRUE(run.result.partOffs.empty());
    EXPECT_FALSE(run.result.part);
    ASSERT_EQ(run.result.loosePieces.size(), 1u);
    const LoosePiece& skin = run.result.loosePieces[0];
    EXPECT_EQ(skin.line, 5);
    const double skinSurface = 2 * M_PI * (20 + 19) * 25 + 2 * M_PI * (400 - 361);
    EXPECT_NEAR(skin.volumeMm3, 955.667 * M_PI, tolerance(skinSurface, voxel));
    EXPECT_GT(skin.beyondMm3, 324 * M_PI * 24);
    ASSERT_EQ(run.result.warnings.size(), 1u);
    EXPECT_EQ(run.result.warnings[0].line, 5);
    EXPECT_NE(run.result.warnings[0].message.find("a 1.0 mm ring (Φ38.0 to Φ40.0"), std::string::npos)
        << run.result.warnings[0].message;
    // Nothing is lost: the stock, what the blocks cut and the skin that fell add up to the bar.
    double cut = 0;
    for (const BlockRemoval& block : run.result.blocks) cut += block.removedMm3;
    EXPECT_NEAR(run.stubMm3 + cut + skin.volumeMm3, 400 * M_PI * 50, tolerance(surface(20, 0, 50) + skinSurface, voxel));
  }
}

// The same around a bore: a tube Φ40 with a Φ20 bore, the 1 mm insert boring at X22 (r 11…12)
// from Z2 to Z-5 and leaving along the diagonal to X18 Z-7, whose sweep's upper edge (the
// insert's corner (r, Z+1)) runs from (11, -4) to (9, -6): z = r − 15. The 1 mm skin r 10…11
// on the bore above it falls at line 5: ∫₁₀¹¹ 2πr (15 − r) dr = 2π (7.5·21 − 331/3) = 94.333π
// mm³, against 256π·4 and more of the wall outside from its lowest Z on.
TEST(PartOff, ARingCutLooseAroundABoreIsNoPartOff) {
  for (const double voxel : {0.1, 0.2, 0.25}) {
    SCOPED_TRACE(testing::Message() << voxel << " mm voxels");
    const PartOffRun run = simulateProgram({40.0, 50.0, 0.0, 20.0}, voxel,
                                           "G99 M03 S500\nT0505\nG00 X22. Z2.\nG01 Z-5. F0.1\nG01 X18. Z-7.\n"
                                           "G00 X17.\nG00 Z5.\nM30\n");
    EXPECT_TRUE(run.result.partOffs.empty());
    EXPECT_FALSE(run.result.part);
    EXPECT_TRUE(run.result.collisions.empty());
    ASSERT_EQ(run.result.loosePieces.size(), 1u);
    EXPECT_EQ(run.result.loosePieces[0].line, 5);
    const double ringSurface = 2 * M_PI * (10 + 11) * 5 + 2 * M_PI * (121 - 100);
    EXPECT_NEAR(run.result.loosePieces[0].volumeMm3, 94.333 * M_PI, tolerance(ringSurface, voxel));
    EXPECT_NEAR(run.result.loosePieces[0].rInnerMm, 10.0, voxel);
    EXPECT_NEAR(run.result.loosePieces[0].rOuterMm, 11.0, voxel);
  }
}

// Only a part-off writes a piece as the part: a blade to X-1 at Z positions on and off the grid,
// at 0.2 and 0.1 mm voxels, parts Z … 0 of a Φ24 bar (144π·|Z|) and is no loose piece.
TEST(PartOff, OnlyAPartOffMakesThePartSweptOverPositionsAndVoxels) {
  for (const double voxel : {0.2, 0.1})
    for (const double z : {-6.0, -9.37, -14.05}) {
      SCOPED_TRACE(testing::Message() << voxel << " mm voxels, Z" << z);
      const PartOffRun run = simulateProgram({24.0, 30.0, 0.0}, voxel,
                                             "G99 M03 S500\nG00 X26. Z" + std::to_string(z) + "\nG01 X-1. F0.05\nG00 X30.\nM30\n");
      ASSERT_EQ(run.result.partOffs.size(), 1u);
      EXPECT_TRUE(run.result.loosePieces.empty());
      EXPECT_NEAR(run.result.partOffs[0].zMm, z, 1e-9);
      ASSERT_TRUE(run.result.part);
      EXPECT_NEAR(run.result.part->volumeMm3(), 144 * M_PI * -z, tolerance(surface(12, 0, -z), voxel));
      EXPECT_NEAR(run.stubMm3, 144 * M_PI * (30 + z - kBladeWidthMm), tolerance(surface(12, 0, 30 + z - kBladeWidthMm), voxel));
      EXPECT_TRUE(run.result.warnings.empty());
    }
}

// The part-off's Z is its cut's deepest point: of the block's moves, the one ending nearest the
// axis. A corner radius D1 (the GSK preset's corner word) at the blade's corner makes the block
// two moves: to X0 at Z-20, then the corner's arc (1 mm from the corner along both lines) to
// X-2 at Z-19, nearer the axis: the part falls at Z-19.
TEST(PartOff, ThePartOffsZIsTheBlocksMoveEndingNearestTheAxis) {
  const PartOffRun run = simulateProgram({40.0, 50.0, 0.0}, 0.25,
                                         "G99 M03 S500\nG00 X44. Z-20.\nG01 X-2. D1. F0.05\nG01 Z-10.\nG00 X60.\nM30\n");
  ASSERT_EQ(run.result.partOffs.size(), 1u);
  EXPECT_EQ(run.result.partOffs[0].line, 3);
  EXPECT_NEAR(run.result.partOffs[0].zMm, -19.0, 1e-9);
}

// A loose sliver no sample of which lies more than a quarter of a voxel inside is a crumb, not
// a piece: a bar Φ39.6 (r 19.8) bored from outside by the 1 mm insert at X37.4 (r 18.7…19.7)
// leaves the skin r 19.7…19.8, 0.1 mm thick, whose only sample (r 19.75 at 0.25 mm voxels)
// lies 0.05 inside: it holds 2π·19.75·0.1·20 = 79π mm³ (over 5000 voxels' worth), yet it is
// neither a part-off nor a loose piece, and stays in the stock (the mesh drops such crumbs).
TEST(PartOff, ASliverShallowerThanAQuarterVoxelIsACrumb) {
  const PartOffRun run = simulateProgram({39.6, 50.0, 0.0}, 0.25,
                                         "G99 M03 S500\nT0505\nG00 X37.4 Z2.\nG01 Z-20. F0.1\nG01 X42. Z-23.\n"
                                         "G00 X60.\nM30\n");
  EXPECT_TRUE(run.result.partOffs.empty());
  EXPECT_TRUE(run.result.loosePieces.empty());
  EXPECT_TRUE(run.result.warnings.empty()) << run.result.warnings[0].message;
}

// After the part-off, a cut where the part was finds nothing to cut (the part has fallen) and
// says so; a second part-off further down the stub is a second piece, warned of.
TEST(PartOff, CutsAfterThePartOffDoNotTouchThePartThatFell) {
  const double voxel = 0.25;
  const PartOffRun run = simulateProgram({40.0, 50.0, 0.0}, voxel,
                                  "G99 M03 S500\nG00 X44. Z-25.\nG01 X-1. F0.05\nG00 X44.\n"
                                  "G00 Z-5.\nG01 X10.\nG00 X44.\n"
                                  "G00 Z-40.\nG01 X-1.\nG00 X60.\nM30\n");
  ASSERT_EQ(run.result.partOffs.size(), 2u);
  ASSERT_TRUE(run.result.part);
  EXPECT_NEAR(run.result.part->volumeMm3(), 400 * M_PI * 25, tolerance(surface(20, 0, 25), voxel));
  ASSERT_EQ(run.result.warnings.size(), 2u);
  EXPECT_EQ(run.result.warnings[0].line, 6);
  EXPECT_NE(run.result.warnings[0].message.find("parted off at line 3"), std::string::npos)
      << run.result.warnings[0].message;
  EXPECT_EQ(run.result.warnings[1].line, 9);
  EXPECT_NE(run.result.warnings[1].message.find("a second piece"), std::string::npos) << run.result.warnings[1].message;
  EXPECT_EQ(run.result.partOffs[1].line, 9);
  EXPECT_NEAR(run.result.partOffs[1].volumeMm3, 400 * M_PI * 12, tolerance(surface(20, 0, 12), voxel));
  EXPECT_NEAR(run.stubMm3, 400 * M_PI * 7, tolerance(surface(20, 0, 7), voxel));
  ASSERT_EQ(run.result.blocks.size(), 9u);
  EXPECT_EQ(run.result.blocks[4].line, 6);
  EXPECT_NEAR(run.result.blocks[4].removedMm3, 0.0, tolerance(surface(20, 0, 3), voxel));
}

// Parting in short steps, as CAM posts it: each block turns a sliver of the section to air, and
// while the table holds the stock the part-off check looks for loose material around those
// samples only (RevolvedTable::takeMeridianFlips). The level set's writer, with no table, looks
// around the block's whole cut. Bars and tubes, steps on and off the voxel grid, two Z: the
// piece falls at the same block with the same volume both ways, and at the block that first
// reaches the axis or the bore (a voxel's rounding either way; X is a diameter) with the volume
// worked out by hand. A ring cut loose inside a tube in steps too (the section falls in two
// with no Z free of material, as in ARingCutLooseInsideATubeFallsAndIsNoPart).
TEST(PartOff, PartingInShortStepsFallsAtTheSameBlockAsLookingAroundTheWholeCut) {
  for (const double bore : {0.0, 10.0})
    for (const double voxel : {0.25, 0.4})
      for (const double step : {0.03, 0.13, 0.5})
        for (const double z : {-10.0, -13.37}) {
          SCOPED_TRACE(testing::Message() << "bore " << bore << ", " << voxel << " mm voxels, steps of " << step
                                          << " mm, Z" << z);
          const StockSpec bar{24.0, 30.0, 0.0, bore};
          std::string program = "G99 M03 S500\nG00 X26. Z" + std::to_string(z) + "\n";
          int firstThrough = 0;  // the line of the first step at or past the axis, or the bore
          int line = 3;
          for (double x = 26.0 - step; x > bore - 1.0 - step; x -= step, ++line) {
            program += "G01 X" + std::to_string(x) + " F0.05\n";
            if (!firstThrough && x <= bore) firstThrough = line;
          }
          program += "G00 X30.\nM30\n";
          const PartOffRun table = simulateProgram(bar, voxel, program);
          const PartOffRun voxels = simulateProgram(bar, voxel, program, RevolvedWrites::Voxels);
          ASSERT_EQ(table.result.partOffs.size(), 1u);
          ASSERT_EQ(voxels.result.partOffs.size(), 1u);
          const PartOff& off = table.result.partOffs[0];
          EXPECT_EQ(off.line, voxels.result.partOffs[0].line);
          EXPECT_NEAR(off.volumeMm3, voxels.result.partOffs[0].volumeMm3, 1e-9 * off.volumeMm3);
          EXPECT_NEAR(table.stubMm3, voxels.stubMm3, 1e-9 * table.stubMm3);
          // A voxel of radius is two of diameter (X): so many steps either way, and one more.
          EXPECT_LE(std::abs(off.line - firstThrough), static_cast<int>(std::ceil(2.0 * voxel / step)) + 1) << off.line;
          const double area = M_PI * (144.0 - bore * bore / 4.0);
          EXPECT_NEAR(off.volumeMm3, area * -z, tolerance(surface(12, bore / 2.0, -z), voxel));
        }
  for (const double step : {0.05, 0.31}) {
    SCOPED_TRACE(testing::Message() << "a ring in steps of " << step << " mm");
    std::string program = "G99 M03 S500\nT0202\nG00 X28. Z2.\n";
    for (double z = 2.0 - step; z > -10.0 - step; z -= step) program += "G01 Z" + std::to_string(std::max(z, -10.0)) + " F0.05\n";
    program += "G00 Z2.\nT0303\nG00 X8.\nZ-12.\n";
    for (double x = 8.0 + step; x < 20.0 + step; x += step) program += "G01 X" + std::to_string(std::min(x, 20.0)) + "\n";
    program += "G00 X8.\nG00 Z5.\nM30\n";
    const PartOffRun table = simulateProgram({40.0, 50.0, 0.0, 20.0}, 0.25, program);
    const PartOffRun voxels = simulateProgram({40.0, 50.0, 0.0, 20.0}, 0.25, program, RevolvedWrites::Voxels);
    // No part-off (ARingCutLooseInsideATubeFallsAndIsNoPart): a loose ring, the same both ways.
    EXPECT_TRUE(table.result.partOffs.empty());
    ASSERT_EQ(table.result.loosePieces.size(), 1u);
    ASSERT_EQ(voxels.result.loosePieces.size(), 1u);
    EXPECT_EQ(table.result.loosePieces[0].line, voxels.result.loosePieces[0].line);
    EXPECT_NEAR(table.result.loosePieces[0].volumeMm3, 864 * M_PI, tolerance(surface(14, 10, 9), 0.25));
  }
}

// The parts catcher command in force when the piece falls is reported with it.
TEST(PartOff, TheCatcherInForceIsReported) {
  const StockSpec bar{40.0, 50.0, 0.0};
  const std::string cut = "G00 X44. Z-20.\nG01 X-1. F0.05\nG00 X60.\nM30\n";
  const PartOffRun caught = simulateProgram(bar, 0.4, "G99 M03 S500\nM37\nM36\n" + cut);
  ASSERT_EQ(caught.result.partOffs.size(), 1u);
  ASSERT_TRUE(caught.result.partOffs[0].catcher);
  EXPECT_EQ(caught.result.partOffs[0].catcher->code, "M36");
  EXPECT_EQ(caught.result.partOffs[0].catcher->line, 3);
  EXPECT_TRUE(caught.result.partOffs[0].catcher->inPlace);
  const PartOffRun dropped = simulateProgram(bar, 0.4, "G99 M03 S500\nM36\nM37\n" + cut);
  ASSERT_EQ(dropped.result.partOffs.size(), 1u);
  ASSERT_TRUE(dropped.result.partOffs[0].catcher);
  EXPECT_EQ(dropped.result.partOffs[0].catcher->code, "M37");
  EXPECT_FALSE(dropped.result.partOffs[0].catcher->inPlace);
}

}  // namespace
}  // namespace lathesim::sim
