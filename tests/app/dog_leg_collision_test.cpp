// A rapid swept along the path the machine makes: under non-linear positioning (the default on
// both presets) a retract from a groove is a dog-leg whose diagonal catches the groove's wall,
// where the straight line would have cleared it. Through interp and sim as `lathesim run`
// drives them; the volume is worked out by hand below.

#include <gtest/gtest.h>

#include <cmath>

#include "interp/interpreter.hpp"
#include "sim/simulate.hpp"

namespace lathesim::app {
namespace {

// Φ40 × 50 bar, face Z0 (Z-50..0). A grooving blade 3 wide (Z) and 10 deep (radial), its
// programmed point the −X −Z corner. The tool starts at X200 Z10 (r 100).
constexpr double kDogLegVoxelMm = 0.2;

// Line 2 rapids over the bar to X44 Z-23; lines 3–6 plunge twice to Φ30, cutting the groove
// r 15..20, Z-24..-20 (4 wide, the blade at Z-23 then Z-24). The blade ends at (r 15, Z-24),
// covering Z-24..-21. Line 7 retracts to X200 Z-22.
constexpr std::string_view kDogLegProgram =
    "G99 M03 S500\n"
    "G00 X44 Z-23\n"
    "G01 X30 F0.1\n"
    "G00 X44\n"
    "G00 Z-24\n"
    "G01 X30\n"
    "G00 X200 Z-22\n";

sim::SimulationResult simulate(interp::RapidPath rapidPath) {
  interp::InterpreterOptions options;
  options.startPosition = RZ(100, 10);
  options.toolNumbers = {1};
  options.control.rapidPath = rapidPath;
  const interp::InterpretResult result = interp::interpret(kDogLegProgram, "groove.nc", options);
  EXPECT_TRUE(result.ok()) << interp::format(result.diagnostics.at(0));
  sim::ToolOutlines tools;
  const std::vector<RZ> blade{{0, 0}, {10, 0}, {10, 3}, {0, 3}};
  tools.emplace(1, *ConvexPolygon::fromOutline(blade).polygon);
  sim::Stock stock(sim::StockSpec{40, 50, 0}, kDogLegVoxelMm);
  return sim::simulate(result.toolpath, tools, stock);
}

TEST(DogLegCollision, ARetractThatClearsTheGrooveStraightCatchesItsWallAsADogLeg) {
  // Straight (linear positioning): from (r 15, Z-24) to (r 100, Z-22) the blade's top edge,
  // at Z-21 + 2·(r − 15)/85, reaches the wall Z-20 only once r > 57.5, long past the bar's r 20.
  EXPECT_TRUE(simulate(interp::RapidPath::Linear).collisions.empty());

  // Dog-leg: Z needs 2/8000 min, X 85/6000: Z arrives first, X having moved 6000·2/8000 = 1.5:
  // the diagonal runs (15, -24) → (16.5, -22), 3 of radius per 4 of Z, then X alone at Z-22.
  // The blade's top edge passes Z-20 at (15.75, -23) and reaches Z-19. It takes from the wall
  // (r ≤ 20, Z > -20) the strip Z-20..-19, from r0(Z) = 15 + 0.75·(Z + 21), the diagonal's
  // point whose edge is at Z, out to r 20; the straight leg at Z-22 (edge at Z-19, r ≥ 16.5)
  // adds nothing. Revolved, with u = Z + 21 from 1 to 2:
  //   V = π ∫ (20² − (15 + 0.75u)²) du = π (400 − [225 + 22.5·1.5 + 0.5625·7/3]) = 139.9375π.
  const sim::SimulationResult dogLeg = simulate(interp::RapidPath::NonLinear);
  ASSERT_EQ(dogLeg.collisions.size(), 1u);
  const sim::Collision& collision = dogLeg.collisions[0];
  EXPECT_EQ(collision.line, 7);
  EXPECT_EQ(collision.kind, "rapid_into_stock");
  // The level set places the surface to a small fraction of a voxel: 5 % of a voxel layer over
  // the removed ring's surface (section perimeter ≈ 1 + 3.5 + 1 + 4.25 mm at r ≈ 18).
  const double surfaceMm2 = 2 * M_PI * 18 * (1 + 3.5 + 1 + 4.25);
  EXPECT_NEAR(collision.volumeMm3, 139.9375 * M_PI, 0.05 * kDogLegVoxelMm * surfaceMm2);
}

}  // namespace
}  // namespace lathesim::app
