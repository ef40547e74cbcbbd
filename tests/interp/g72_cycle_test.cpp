// G72 stock removal in facing: G71 with the axes exchanged (lathe-cycles.md §4). Levels of
// constant Z, passes parallel to X, retract 45°, rapid back in X. Move lists expanded by hand;
// step numbers as in interp/stock_removal.cpp. Positions are (radius, Z) mm.

#include <gtest/gtest.h>

#include <vector>

#include "interp/roughing_cycle.hpp"
#include "roughing_test_support.hpp"

namespace lathesim::interp {
namespace {

using test::arcSegment;
using test::expectLegsNear;
using test::expectRoughingError;
using test::segment;

constexpr MoveKind kRapid = MoveKind::Rapid;
constexpr MoveKind kFeed = MoveKind::Feed;
constexpr MoveKind kCw = MoveKind::ArcCW;

RoughingParams params(double depthMm, double retractMm, double allowanceXMm,
                      double allowanceZMm) {
  RoughingParams p;
  p.depthMm = depthMm;
  p.retractMm = retractMm;
  p.allowanceXMm = allowanceXMm;
  p.allowanceZMm = allowanceZMm;
  return p;
}

// A = X104 Z2 (radius 52). N10 G00 Z-12; N20 G01 X80 (radius 40); N30 X40 Z-2 (radius 20);
// N40 Z0; N50 X0.
Contour faceContour() {
  return {segment(kRapid, 52, 2, 52, -12, 10), segment(kFeed, 52, -12, 40, -12, 20),
          segment(kFeed, 40, -12, 20, -2, 30), segment(kFeed, 20, -2, 20, 0, 40),
          segment(kFeed, 20, 0, 0, 0, 50)};
}

// G72 W3 R0.5; G72 P10 Q50 U0.4 W0.3: Δd 3 in Z, e 0.5, allowance (0.2 radius, 0.3).
// A′ = (52.2, 2.3), B′ = (52.2, -11.7); rough contour B′ → (40.2, -11.7) → taper →
// (20.2, -1.7) → (20.2, 0.3) → C′ (0.2, 0.3). Depth to cut 2.3 - (-11.7) = 14: levels
// Z = 2.3 - 3k for k = 1..4: -0.7, -3.7, -6.7, -9.7 (k = 5 would pass B′).
// Z-0.7 meets the wall X = 20.2 (Z -1.7 … 0.3). The taper X = 40.2 - 20t, Z = -11.7 + 10t
// meets -3.7 at t 0.8 (X 24.2), -6.7 at t 0.5 (X 30.2), -9.7 at t 0.2 (X 36.2).
// Retract 45° back toward A′: +0.5 in X, +0.5 in Z; then rapid in X back to 52.2.
TEST(FacingRoughing, FaceTypeIWithTaper) {
  const auto legs = facingRoughingLegs(RZ(52, 2), faceContour(), params(3, 0.5, 0.2, 0.3));
  ASSERT_TRUE(legs.ok()) << legs.error().message;
  expectLegsNear(legs.value(), {
      {kRapid, 52, 2, 52.2, 2.3, 1},
      {kRapid, 52.2, 2.3, 52.2, -0.7, 2},
      {kFeed, 52.2, -0.7, 20.2, -0.7, 3},
      {kFeed, 20.2, -0.7, 20.7, -0.2, 4},
      {kRapid, 20.7, -0.2, 52.2, -0.2, 5},
      {kRapid, 52.2, -0.2, 52.2, -3.7, 6},
      {kFeed, 52.2, -3.7, 24.2, -3.7, 3},
      {kFeed, 24.2, -3.7, 24.7, -3.2, 4},
      {kRapid, 24.7, -3.2, 52.2, -3.2, 5},
      {kRapid, 52.2, -3.2, 52.2, -6.7, 6},
      {kFeed, 52.2, -6.7, 30.2, -6.7, 3},
      {kFeed, 30.2, -6.7, 30.7, -6.2, 4},
      {kRapid, 30.7, -6.2, 52.2, -6.2, 5},
      {kRapid, 52.2, -6.2, 52.2, -9.7, 6},
      {kFeed, 52.2, -9.7, 36.2, -9.7, 3},
      {kFeed, 36.2, -9.7, 36.7, -9.2, 4},
      {kRapid, 36.7, -9.2, 52.2, -9.2, 5},
      {kRapid, 52.2, -9.2, 52.2, -11.7, 6},
      {kFeed, 52.2, -11.7, 40.2, -11.7, 7},
      {kFeed, 40.2, -11.7, 20.2, -1.7, 7},
      {kFeed, 20.2, -1.7, 20.2, 0.3, 7},
      {kFeed, 20.2, 0.3, 0.2, 0.3, 7},
      {kRapid, 0.2, 0.3, 52, 2, 8},
  });
}

// A = X64 Z2 (radius 32). N10 G00 Z-10; N20 G01 X40 (radius 20);
// N30 G02 X20 Z0 R10 (convex corner about (10, -10)); N40 X0.
// Δd 5, e 1, allowance (0.1, 0.2): A′ = (32.1, 2.2), B′ = (32.1, -9.8), arc centre
// (10.1, -9.8), radius 10. Depth 12: levels Z -2.8 and -7.8.
// On the arc X = 10.1 + 10 sin θ, Z = -9.8 + 10 cos θ (θ from 0 to π/2):
//   Z -2.8 → cos 0.7, X = 10.1 + 10·√0.51 = 17.24142842854285
//   Z -7.8 → cos 0.2, X = 10.1 + 10·√0.96 = 19.89795897113271
// The semi-finishing pass keeps the arc a G02 (exchanging the axes twice restores it).
TEST(FacingRoughing, PassesEndOnTheArcAndTheArcStaysClockwise) {
  const Contour contour = {segment(kRapid, 32, 2, 32, -10, 10),
                           segment(kFeed, 32, -10, 20, -10, 20),
                           arcSegment(kCw, 20, -10, 10, 0, 10, -10, 30),
                           segment(kFeed, 10, 0, 0, 0, 40)};
  const auto legs = facingRoughingLegs(RZ(32, 2), contour, params(5, 1, 0.1, 0.2));
  ASSERT_TRUE(legs.ok()) << legs.error().message;
  expectLegsNear(legs.value(), {
      {kRapid, 32, 2, 32.1, 2.2, 1},
      {kRapid, 32.1, 2.2, 32.1, -2.8, 2},
      {kFeed, 32.1, -2.8, 17.24142842854285, -2.8, 3},
      {kFeed, 17.24142842854285, -2.8, 18.24142842854285, -1.8, 4},
      {kRapid, 18.24142842854285, -1.8, 32.1, -1.8, 5},
      {kRapid, 32.1, -1.8, 32.1, -7.8, 6},
      {kFeed, 32.1, -7.8, 19.89795897113271, -7.8, 3},
      {kFeed, 19.89795897113271, -7.8, 20.89795897113271, -6.8, 4},
      {kRapid, 20.89795897113271, -6.8, 32.1, -6.8, 5},
      {kRapid, 32.1, -6.8, 32.1, -9.8, 6},
      {kFeed, 32.1, -9.8, 20.1, -9.8, 7},
      {kCw, 20.1, -9.8, 10.1, 0.2, 7, 10.1, -9.8},
      {kFeed, 10.1, 0.2, 0.1, 0.2, 7},
      {kRapid, 0.1, 0.2, 32, 2, 8},
  });
}

TEST(FacingRoughingErrors, NamesTheAxesOfG72) {
  // N30 moves Z back from -2 to -6: the type I contour must be monotonic in Z, G72's step
  // axis.
  Contour contour = faceContour();
  contour[3] = segment(kFeed, 20, -2, 20, -6, 40);
  contour[4] = segment(kFeed, 20, -6, 0, -6, 50);
  expectRoughingError(facingRoughingLegs(RZ(52, 2), contour, params(3, 0.5, 0, 0)), 40, 1,
                      "G72 type I contour must be monotonic in Z: this block moves Z back "
                      "toward B");
  // N40 goes back out in X: X is G72's cutting axis.
  contour = faceContour();
  contour[4] = segment(kFeed, 20, 0, 30, 0, 50);
  expectRoughingError(facingRoughingLegs(RZ(52, 2), contour, params(3, 0.5, 0, 0)), 50, 1,
                      "G72 contour must be monotonic in X: this block moves X against the "
                      "blocks before it");
  expectRoughingError(facingRoughingLegs(RZ(52, 2), faceContour(), params(0, 0.5, 0, 0)), 10,
                      1, "G72 depth of cut Δd is 0");
  const Contour noZ = {segment(kRapid, 52, 2, 40, 2, 10), segment(kFeed, 40, 2, 40, -5, 20)};
  expectRoughingError(facingRoughingLegs(RZ(52, 2), noZ, params(3, 0.5, 0, 0)), 10, 1,
                      "G72 ns block does not move Z");
}

}  // namespace
}  // namespace lathesim::interp
