// A Haas one-block G71 with a trough through interpreter and simulation: whatever order the
// levels take (the Haas manual's "Troughs"), the cycle must leave the bar's material below its
// contour plus the finishing allowance, no less (a level through the part) and no more (a
// trough left uncut). The closing pass of G71 runs along the contour shifted by U/2, so after
// the cycle the part is the bar under that contour: by Pappus, each straight block from
// (r1, z1) to (r2, z2) revolves into a frustum of volume π·h·(r1² + r1·r2 + r2²)/3, h = |z1 − z2|.
//
// Tool: a 30° V pointing at the axis, its tip the programmed point (the contour's walls lean at
// least 26.6° from the radial, so the V follows them without touching the far side).
// Bar Φ50 (r 25), Z −40 … 0. Tolerance: a tenth of a voxel layer over the surfaces cut.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "interp/control/control_preset.hpp"
#include "interp/interpreter.hpp"
#include "sim/simulate.hpp"

namespace lathesim::sim {
namespace {

constexpr double kTroughVoxelMm = 0.2;

ConvexPolygon vTool() {
  const double halfWidth = 12.0 * std::tan(15.0 * std::numbers::pi / 180.0);
  const std::vector<RZ> outline = {RZ(0, 0), RZ(12, halfWidth), RZ(12, -halfWidth)};
  return *ConvexPolygon::fromOutline(outline).polygon;
}

/// The volume left of the Φ50 × 40 bar after `program` under the haas preset and dialect.
double leftMm3(const std::string& program) {
  interp::InterpreterOptions options;
  options.control = interp::controlPreset("haas")->parameters;
  options.dialect = interp::Dialect::Haas;
  options.startPosition = RZ(40.0, 20.0);
  options.toolNumbers = {1};
  const auto result = interp::interpret(program, "test.nc", options);
  EXPECT_TRUE(result.ok()) << (result.diagnostics.empty() ? "" : result.diagnostics.front().message);
  Stock stock({50.0, 40.0, 0.0}, kTroughVoxelMm);
  simulate(result.toolpath, {{1, vTool()}}, stock);
  return stock.volumeMm3();
}

/// π·h·(r1² + r1·r2 + r2²)/3 summed over the profile's straight pieces, (r, z) in order.
double revolvedMm3(const std::vector<RZ>& profile) {
  double volume = 0;
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    const double r1 = profile[i].x(), r2 = profile[i + 1].x();
    volume += std::numbers::pi * std::abs(profile[i].y() - profile[i + 1].y()) * (r1 * r1 + r1 * r2 + r2 * r2) / 3.0;
  }
  return volume;
}

// The contour (diameters): X20. from Z2 to Z-10., up to X40. Z-15. (the crest), down to X26.
// Z-22., the floor to Z-25., up to X46. Z-30., X50. Z-32. (the bar's rim). Type I (the P block
// moves X only) with one trough under the crest. D2., Setting 73's retract.
const std::string kContour =
    "N10 G00 X20.\nG01 Z-10.\nX40. Z-15.\nX26. Z-22.\nZ-25.\nX46. Z-30.\nN20 X50. Z-32.\n";

TEST(HaasTroughVolume, TypeIWithATroughLeavesTheContour) {
  // Left: the bar under the contour from Z0 (the bar's face) to Z−32, and the untouched bar
  // from Z−32 to Z−40:
  //   π·[100·10 + 5·(100 + 200 + 400)/3 + 7·(400 + 260 + 169)/3 + 169·3 + 5·(169 + 299 + 529)/3
  //      + 2·(529 + 575 + 625)/3] + π·625·8 = π·(7422.333 + 5000) = 39025.9 mm³.
  const double expected = std::numbers::pi * (1000.0 + 3500.0 / 3 + 5803.0 / 3 + 507.0 + 4985.0 / 3 + 3458.0 / 3 + 5000.0);
  EXPECT_NEAR(revolvedMm3({RZ(10, 0), RZ(10, -10), RZ(20, -15), RZ(13, -22), RZ(13, -25), RZ(23, -30), RZ(25, -32),
                           RZ(25, -40)}),
              expected, 1e-6);
  // Surfaces cut: the faces and walls of the profile, about 2π·17·(32 + 2·15) ≈ 6600 mm².
  EXPECT_NEAR(leftMm3("G99 M03 S800 T101\nG00 X52. Z2.\nG71 P10 Q20 D2. F0.2\n" + kContour), expected,
              0.1 * kTroughVoxelMm * 6600);
}

TEST(HaasTroughVolume, TypeIIWithAFinishingAllowanceLeavesItOnTheContour) {
  // U1. leaves 0.5 on the radius: the closing pass runs on the contour 0.5 further out, B″ =
  // (10.5, 2) as the P block Z2. (type II) makes B = (10, 2).
  const double expected = revolvedMm3({RZ(10.5, 0), RZ(10.5, -10), RZ(20.5, -15), RZ(13.5, -22), RZ(13.5, -25),
                                       RZ(23.5, -30), RZ(25, -31.5)}) +
                          std::numbers::pi * 625 * 8.5;
  const std::string contour = "N10 G00 X20. Z2.\n" + kContour.substr(kContour.find('\n') + 1);
  EXPECT_NEAR(leftMm3("G99 M03 S800 T101\nG00 X52. Z2.\nG71 P10 Q20 U1. D2. F0.2\n" + contour), expected,
              0.1 * kTroughVoxelMm * 6600);
}

}  // namespace
}  // namespace lathesim::sim
