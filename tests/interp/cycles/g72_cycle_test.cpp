// G72 stock removal in facing: G71 with the axes exchanged (lathe-cycles.md §4). Levels of
// constant Z, passes parallel to X, retract 45°, rapid back in X. Move lists expanded by hand;
// step numbers as in interp/cycles/stock_removal.cpp. Positions are (radius, Z) mm.

#include <gtest/gtest.h>

#include <vector>

#include "interp/cycles/roughing_cycle.hpp"
#include "roughing_test_support.hpp"

namespace lathesim::interp {
namespace {

using test::arcSegment;
using test::expectLegsNear;
using test::expectRoughingError;
using test::params;
using test::segment;

using test::kRapid;
using test::kFeed;
using test::kCw;

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

// Type II, a ring groove in the face. A = X68 Z0 (radius 34). N10 G00 U0 Z-10 (type II);
// N20 G01 X44 (radius 22); N30 Z-5; N40 X34 (radius 17); N50 X24 Z-13 (radius 12: into the
// groove); N60 X14 (radius 7); N70 X4 Z-1 (radius 2); N80 Z0. G72 W4 R1; G72 P10 Q80 U0 W0.
// X falls all along (G72's cutting axis); Z dips into the groove and comes back.
Contour ringGrooveContour() {
  return {segment(kRapid, 34, 0, 34, -10, 10), segment(kFeed, 34, -10, 22, -10, 20),
          segment(kFeed, 22, -10, 22, -5, 30),  segment(kFeed, 22, -5, 17, -5, 40),
          segment(kFeed, 17, -5, 12, -13, 50),  segment(kFeed, 12, -13, 7, -13, 60),
          segment(kFeed, 7, -13, 2, -1, 70),    segment(kFeed, 2, -1, 2, 0, 80)};
}

// This is the G71 pocket of g71_cycle_test.cpp (TurningRoughingTypeII) mirrored: a point
// (X, Z) there is (radius Z + 32, Z X − 25) here, so its hand expansion carries over leg by
// leg, with X and Z exchanged. Re-derived in G72's terms: deepest point Z-13, levels Z -4,
// -8, -12. Wall N50: radius 17 − 5t, Z −5 − 8t (Z-8 → t 3/8, radius 15.125; Z-12 → 12.625).
// Wall N70: radius 7 − 5t, Z −13 + 12t (Z-4 → t 0.75, radius 3.25; Z-8 → radius
// 7 − 25/12 = 4.916666…; Z-12 → 7 − 5/12 = 6.583333…). Back off e = 1 in +Z.
TEST(FacingRoughing, TypeIIRingGrooveInTheFace) {
  RoughingParams p = params(4, 1, 0, 0);
  p.typeII = true;
  const auto legs = facingRoughingLegs(RZ(34, 0), ringGrooveContour(), p);
  ASSERT_TRUE(legs.ok()) << legs.error().message;
  constexpr double r17 = 7 - 25.0 / 12;  // 4.916666…
  constexpr double r13 = 7 - 5.0 / 12;   // 6.583333…
  expectLegsNear(legs.value(), {
      {kRapid, 34, 0, 34, -4, 2},
      {kFeed, 34, -4, 3.25, -4, 3},
      {kFeed, 3.25, -4, 2, -1, 4},
      {kFeed, 2, -1, 2, 0, 4},
      {kFeed, 2, 0, 2, 1, 4},
      {kRapid, 2, 1, 34, 1, 5},
      {kRapid, 34, 1, 34, -8, 6},
      {kFeed, 34, -8, 22, -8, 3},
      {kFeed, 22, -8, 22, -5, 4},
      {kFeed, 22, -5, 17, -5, 4},
      {kFeed, 17, -5, 17, -4, 4},
      {kFeed, 17, -4, 17, -5, 6},
      {kFeed, 17, -5, 15.125, -8, 6},
      {kFeed, 15.125, -8, r17, -8, 3},
      {kFeed, r17, -8, 3.25, -4, 4},
      {kFeed, 3.25, -4, 3.25, -3, 4},
      {kRapid, 3.25, -3, 3.25, 0, 5},
      {kRapid, 3.25, 0, 15.125, 0, 5},
      {kRapid, 15.125, 0, 15.125, -7, 5},
      {kFeed, 15.125, -7, 15.125, -8, 6},
      {kFeed, 15.125, -8, 12.625, -12, 6},
      {kFeed, 12.625, -12, r13, -12, 3},
      {kFeed, r13, -12, r17, -8, 4},
      {kFeed, r17, -8, r17, -7, 4},
      {kRapid, r17, -7, r17, 0, 5},
      {kRapid, r17, 0, 34, 0, 5},
      {kRapid, 34, 0, 34, -10, 6},
      {kFeed, 34, -10, 22, -10, 7},
      {kFeed, 22, -10, 22, -5, 7},
      {kFeed, 22, -5, 17, -5, 7},
      {kFeed, 17, -5, 12, -13, 7},
      {kFeed, 12, -13, 7, -13, 7},
      {kFeed, 7, -13, 2, -1, 7},
      {kFeed, 2, -1, 2, 0, 7},
      {kRapid, 2, 0, 34, 0, 8},
  });
}

/// The legs and the contour with the axes exchanged (arcs change sense), so that G71's
/// no-gouge check applies: G72's levels step in Z as G71's step in X.
CycleLeg exchanged(CycleLeg leg) {
  leg.from = RZ(leg.from.y(), leg.from.x());
  leg.to = RZ(leg.to.y(), leg.to.x());
  leg.center = RZ(leg.center.y(), leg.center.x());
  if (leg.kind == MoveKind::ArcCW) {
    leg.kind = MoveKind::ArcCCW;
  } else if (leg.kind == MoveKind::ArcCCW) {
    leg.kind = MoveKind::ArcCW;
  }
  return leg;
}

// Type I (the taper, the arc corner) and type II (the ring groove), several depths and
// retracts, with an allowance: no roughing cut crosses the rough contour.
TEST(FacingRoughingProperty, NeverGougesTheRoughContour) {
  const Contour arcCorner = {segment(kRapid, 32, 2, 32, -10, 10),
                             segment(kFeed, 32, -10, 20, -10, 20),
                             arcSegment(kCw, 20, -10, 10, 0, 10, -10, 30),
                             segment(kFeed, 10, 0, 0, 0, 40)};
  struct Case {
    Contour contour;
    RZ start;
    bool typeII;
  };
  const std::vector<Case> cases = {{faceContour(), RZ(52, 2), false},
                                   {arcCorner, RZ(32, 2), false},
                                   {ringGrooveContour(), RZ(34, 0), true}};
  const RZ allowance(0.2, 0.3);
  for (const Case& c : cases) {
    for (const double depthMm : {0.7, 1.9, 3.3}) {
      for (const double retractMm : {0.0, 0.6}) {
        RoughingParams p = params(depthMm, retractMm, allowance.x(), allowance.y());
        p.typeII = c.typeII;
        const auto legs = facingRoughingLegs(c.start, c.contour, p);
        ASSERT_TRUE(legs.ok()) << legs.error().message;
        std::vector<CycleLeg> inG71Axes;
        for (const CycleLeg& leg : legs.value()) inG71Axes.push_back(exchanged(leg));
        Contour rough;
        for (ContourSegment s : c.contour) {
          s.from += allowance;
          s.to += allowance;
          s.center += allowance;
          const CycleLeg e = exchanged({s.kind, s.from, s.to, 0, s.center});
          rough.push_back({e.kind, e.from, e.to, e.center, s.line, s.column});
        }
        SCOPED_TRACE(testing::Message() << "depth " << depthMm << " retract " << retractMm);
        test::expectNoGouge(inG71Axes, rough, -1.0);
      }
    }
  }
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

// A contour of the ns block alone (the fuzzer's: N10 moves Z and X, the blocks to Q move
// nothing more) is type II with no blocks after the ns block: it ran past the end of an empty
// list. Now each level is cut to B′, as type I cuts it. By hand, G72 W4 R0.5, U0.4 W0.2 from
// A = (31, 2) to B = (20, -10): A′ = (31.2, 2.2), B′ = (20.2, -9.8), 12 mm to cut, levels
// k·4 < 12 at Z -1.8 and -5.8, each cut along X to B′'s radius 20.2.
TEST(FacingRoughing, TypeIIContourOfTheNsBlockAloneCutsEachLevelToB) {
  const Contour nsAlone{segment(kRapid, 31, 2, 20, -10, 10)};
  const auto legs = facingRoughingLegs(RZ(31, 2), nsAlone, params(4, 0.5, 0.2, 0.2));
  ASSERT_TRUE(legs.ok()) << legs.error().message;
  std::vector<CycleLeg> cuts;
  for (const CycleLeg& leg : legs.value())
    if (leg.step == 3) cuts.push_back(leg);
  ASSERT_EQ(cuts.size(), 2u);
  EXPECT_NEAR(cuts[0].from.x(), 31.2, 1e-9);
  EXPECT_NEAR(cuts[0].from.y(), -1.8, 1e-9);
  EXPECT_NEAR(cuts[0].to.x(), 20.2, 1e-9);
  EXPECT_NEAR(cuts[0].to.y(), -1.8, 1e-9);
  EXPECT_NEAR(cuts[1].to.x(), 20.2, 1e-9);
  EXPECT_NEAR(cuts[1].to.y(), -5.8, 1e-9);
}

}  // namespace
}  // namespace lathesim::interp
