// The nose radius through interpreter and simulation (issue 4's acceptance): a 0.8 mm nose
// cutting a taper and an arc leaves the deviation the geometry predicts when the program is
// not compensated, and the drawn contour under G42.
//
// Tool: a convex polygon approximating a nose circle R = 0.8 about (0.8, 0.8) (radial, axial)
// from the programmed point, which is therefore the imaginary tip 3 (the nose's −X, −Z
// corner of its bounding square). The nose is inscribed in 3° steps: the chords are at most
// R(1 − cos 1.5°) = 0.00027 mm inside the circle. The body lies up and to the right
// (r, z ≥ 0) and leans off the nose at slopes that clear the part.
// Bar Φ20 (r 10), Z -12 … 0. Volumes of revolution by Pappus: V = 2π · area · centroid r.
// Tolerance: a tenth of a voxel layer over the surfaces the cut changes (as arc_sweep_test).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string_view>
#include <vector>

#include "interp/interpreter.hpp"
#include "sim/simulate.hpp"

namespace lathesim::sim {
namespace {

constexpr double kNoseVoxelMm = 0.1;
constexpr double kNoseMm = 0.8;

ConvexPolygon roundedTool() {
  std::vector<RZ> outline;
  for (int degrees = 174; degrees <= 276; degrees += 3) {
    const double a = degrees * std::numbers::pi / 180.0;
    outline.emplace_back(kNoseMm + kNoseMm * std::cos(a), kNoseMm + kNoseMm * std::sin(a));
  }
  outline.emplace_back(10.0, 1.5);
  outline.emplace_back(12.0, 12.0);
  outline.emplace_back(1.5, 10.0);
  return *ConvexPolygon::fromOutline(outline).polygon;
}

/// The volume the program removes from the Φ20 × 12 bar, offset 1 being R0.8 tip 3.
double removedMm3(std::string_view program) {
  interp::InterpreterOptions options;
  options.startPosition = RZ(20.0, 10.0);
  options.toolNumbers = {1};
  options.offsets[1] = interp::ToolOffset{0, 0, kNoseMm, 3, 0, 0};
  const auto result = interp::interpret(program, "test.nc", options);
  EXPECT_TRUE(result.ok()) << result.diagnostics.front().message;
  Stock stock({20.0, 12.0, 0.0}, kNoseVoxelMm);
  const double before = stock.volumeMm3();
  simulate(result.toolpath, {{1, roundedTool()}}, stock);
  return before - stock.volumeMm3();
}

// The taper r + z = 6, drawn from (5, 1) to (11, -5): both ends clear of the bar, so what is
// cut is the bar's corner beyond a straight line r + z = c: the triangle (c, 0), (10, 0),
// (10, c − 10) with legs L = 10 − c, area L²/2, centroid r (c + 20)/3:
//   removed(c) = 2π · L²/2 · (c + 20)/3 = π L² (c + 20)/3.
double taperRemovedMm3(double c) {
  const double legs = 10.0 - c;
  return std::numbers::pi * legs * legs * (c + 20.0) / 3.0;
}

// Changed surfaces (largest case, c = 6): face ring π(10² − 6²) = 201.1, cylinder band
// 2π·10·4 = 251.3, cone 2π · 8 · 4√2 = 284.3: 736.7 mm².
constexpr double kTaperToleranceMm3 = 0.1 * kNoseVoxelMm * 736.7;

TEST(NoseRadius, UncompensatedTaperLeavesTheBandTheGeometryPredicts) {
  // The tip (the programmed point) runs on the drawn line r + z = 6, so the nose centre runs
  // on r + z = 6 + 2R; the taper makes θ = 45° with the Z axis, and its outward normal is
  // (cos θ, sin θ), so the centre stands R(cos θ + sin θ) = R√2 off the drawn line and the
  // nose cuts R(cos θ + sin θ − 1) = R(√2 − 1) = 0.331 mm short of it, perpendicular to the
  // line: the cut surface is r + z = 6 + √2 · R(√2 − 1) = 6 + R(2 − √2) = 6.4686.
  //   removed = taperRemoved(6.4686) = π · 3.5314² · 26.4686/3 = 345.66 mm³
  // (the drawn cut is 416π/3 = 435.63 mm³: 90 mm³ more, twelve tolerances).
  const double removed = removedMm3(
      "G99 M03 S800 T0101\n"
      "G00 X10 Z3\n"
      "G01 Z1 F0.1\n"
      "X22 Z-5\n"
      "G00 X30\n"
      "M30\n");
  EXPECT_NEAR(removed, taperRemovedMm3(6.0 + kNoseMm * (2.0 - std::sqrt(2.0))),
              kTaperToleranceMm3);
}

TEST(NoseRadius, G42TaperLandsOnTheDrawnLine) {
  // The same taper under G42: the centre runs on r + z = 6 + R√2 and the nose cuts r + z = 6.
  // Start-up from (5, 3): the centre ends at (5, 1) + R(1, 1)/√2 = (5.566, 1.566), the nose's
  // lowest point at z 0.766, above the face; the taper's centre ends at (11.566, -4.434), the
  // nose's lowest r 10.766, outside the bar: the ends stay clear of it.
  //   removed = taperRemoved(6) = 416π/3 = 435.63 mm³
  const double removed = removedMm3(
      "G99 M03 S800 T0101\n"
      "G00 X10 Z3\n"
      "G42 G01 Z1 F0.1\n"
      "X22 Z-5\n"
      "G40 G00 X30\n"
      "M30\n");
  EXPECT_NEAR(removed, taperRemovedMm3(6.0), kTaperToleranceMm3);
}

TEST(NoseRadius, G90TaperUnderG42LandsOnTheDrawnLine) {
  // G90 from A = (12, 1) to C = (11, -5) with R-6: B = (5, 1), the same cut line r + z = 6,
  // started above the face and ended outside the bar. Under G42 the cycle is offset by the
  // tip number: the tip's line is r + z = 6 − R(2 − √2), so the nose cuts r + z = 6.
  //   removed = taperRemoved(6) = 416π/3 = 435.63 mm³ (uncompensated it would be 345.66)
  const double removed = removedMm3(
      "G99 M03 S800 T0101\n"
      "G00 X24 Z1\n"
      "G42 G90 X22 Z-5 R-6 F0.1\n"
      "G40 G00 X30\n"
      "M30\n");
  EXPECT_NEAR(removed, taperRemovedMm3(6.0), kTaperToleranceMm3);
}

// The corner of the bar rounded by a quarter circle of radius ρ tangent to the face Z0 and
// the diameter r 10, centred at (a, -ρ) with a = 10 − ρ: removed is the square [a, 10] ×
// [-ρ, 0] less the quarter disc (area πρ²/4, centroid r a + 4ρ/(3π)):
//   removed(ρ) = π(10² − a²)ρ − 2π · πρ²/4 · (a + 4ρ/(3π)) = π(100 − a²)ρ − π²ρ²a/2 − 2πρ³/3
double roundRemovedMm3(double rho) {
  const double a = 10.0 - rho;
  return std::numbers::pi * (100.0 - a * a) * rho - std::numbers::pi * std::numbers::pi * rho * rho * a / 2.0 -
         2.0 * std::numbers::pi * rho * rho * rho / 3.0;
}

// Changed surfaces (largest case, ρ = 4): face ring π(100 − 36) = 201.1, cylinder band
// 2π·10·4 = 251.3, round 2π · 2π · (6 + 8/π) = 337.4: 789.8 mm².
constexpr double kRoundToleranceMm3 = 0.1 * kNoseVoxelMm * 789.8;

TEST(NoseRadius, UncompensatedArcLeavesTheSmallerRoundTheGeometryPredicts) {
  // Drawn: G03 R4 from (6, 0) on the face to (10, -4) on the diameter, about (6, -4); the
  // face and diameter before and after it are cut with the tip on them, which leaves them
  // where drawn (tip 3 touches off on its −X and −Z edges). The nose centre runs on the arc
  // moved by (R, R): radius 4 about (6.8, -3.2), so the nose cuts a round of radius
  // 4 − R = 3.2 about (6.8, -3.2), still tangent to the face and the diameter: the corner is
  // left R(√2 − 1) = 0.331 mm proud at 45°.
  //   removed = roundRemoved(3.2) = 172.032π − 34.816π² − 21.845π = 128.20 mm³
  // (the drawn round removes roundRemoved(4) = 196.47 mm³: 68 mm³ more, eight tolerances).
  const double removed = removedMm3(
      "G99 M03 S800 T0101\n"
      "G00 X4 Z1\n"
      "G01 Z0 F0.1\n"
      "X12\n"
      "G03 X20 Z-4 R4\n"
      "G01 Z-6\n"
      "G00 X30\n"
      "M30\n");
  EXPECT_NEAR(removed, roundRemovedMm3(4.0 - kNoseMm), kRoundToleranceMm3);
}

TEST(NoseRadius, G42ArcLandsOnTheDrawnRound) {
  // Under G42 the centre runs on radius 4 + R about (6, -4) (the arc turns left, away from
  // the tool), the face at z 0.8 and the diameter at r 10.8: the nose cuts the drawn round.
  //   removed = roundRemoved(4) = 256π − 48π² − 128π/3 = 196.47 mm³
  const double removed = removedMm3(
      "G99 M03 S800 T0101\n"
      "G00 X4 Z1\n"
      "G42 G01 Z0 F0.1\n"
      "X12\n"
      "G03 X20 Z-4 R4\n"
      "G01 Z-6\n"
      "G40 G00 X30\n"
      "M30\n");
  EXPECT_NEAR(removed, roundRemovedMm3(4.0), kRoundToleranceMm3);
}

}  // namespace
}  // namespace lathesim::sim
