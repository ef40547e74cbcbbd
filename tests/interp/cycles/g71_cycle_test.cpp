// G71 stock removal: move lists expanded by hand from lathe-cycles.md §3 (see the step
// numbers in interp/cycles/stock_removal.cpp), the contour rules' errors, and a no-gouge property.
// Positions are (radius, Z) mm; the programs' X words are diameters, halved in the comments.

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "interp/cycles/roughing_cycle.hpp"
#include "roughing_test_support.hpp"

namespace lathesim::interp {
namespace {

using test::arcSegment;
using test::expectLegsNear;
using test::expectRoughingError;
using test::params;
using test::HandLeg;
using test::segment;

using test::kRapid;
using test::kFeed;
using test::kCw;
using test::kCcw;

// A = X100 Z2 (radius 50); N10 G00 X40; N20 G01 Z-30; N30 X60 Z-40; N40 Z-60; N50 X100.
Contour odTaperContour() {
  return {segment(kRapid, 50, 2, 20, 2, 10), segment(kFeed, 20, 2, 20, -30, 20),
          segment(kFeed, 20, -30, 30, -40, 30), segment(kFeed, 30, -40, 30, -60, 40),
          segment(kFeed, 30, -60, 50, -60, 50)};
}

// G71 U2 R0.5; G71 P10 Q50 U0.5 W0.1: Δd 2, e 0.5, allowance (0.25 radius, 0.1).
// A′ = (50.25, 2.1), B′ = (20.25, 2.1); rough contour B′ → (20.25, -29.9) → taper →
// (30.25, -39.9) → (30.25, -59.9) → C′ (50.25, -59.9).
// Depth to cut 50.25 - 20.25 = 30: levels X_k = 50.25 - 2k for k = 1..14 (k = 15 reaches B′).
// Levels 48.25 … 30.25 meet the contour last on the face Z-59.9 (for 30.25: the end of the
// floor (30.25, -39.9)–(30.25, -59.9), where the face starts). Levels below 30.25 meet the
// taper X = 20.25 + t·10, Z = -29.9 - t·10: 28.25 → t 0.8, Z -37.9; 26.25 → -35.9;
// 24.25 → -33.9; 22.25 → -31.9. Retract: +0.5 in X and +0.5 in Z (back toward A′), at feed.
TEST(TurningRoughing, OdTypeIWithTaper) {
  const auto legs = turningRoughingLegs(RZ(50, 2), odTaperContour(), params(2, 0.5, 0.25, 0.1));
  ASSERT_TRUE(legs.ok()) << legs.error().message;
  expectLegsNear(legs.value(), {
      {kRapid, 50, 2, 50.25, 2.1, 1},
      {kRapid, 50.25, 2.1, 48.25, 2.1, 2},
      {kFeed, 48.25, 2.1, 48.25, -59.9, 3},
      {kFeed, 48.25, -59.9, 48.75, -59.4, 4},
      {kRapid, 48.75, -59.4, 48.75, 2.1, 5},
      {kRapid, 48.75, 2.1, 46.25, 2.1, 6},
      {kFeed, 46.25, 2.1, 46.25, -59.9, 3},
      {kFeed, 46.25, -59.9, 46.75, -59.4, 4},
      {kRapid, 46.75, -59.4, 46.75, 2.1, 5},
      {kRapid, 46.75, 2.1, 44.25, 2.1, 6},
      {kFeed, 44.25, 2.1, 44.25, -59.9, 3},
      {kFeed, 44.25, -59.9, 44.75, -59.4, 4},
      {kRapid, 44.75, -59.4, 44.75, 2.1, 5},
      {kRapid, 44.75, 2.1, 42.25, 2.1, 6},
      {kFeed, 42.25, 2.1, 42.25, -59.9, 3},
      {kFeed, 42.25, -59.9, 42.75, -59.4, 4},
      {kRapid, 42.75, -59.4, 42.75, 2.1, 5},
      {kRapid, 42.75, 2.1, 40.25, 2.1, 6},
      {kFeed, 40.25, 2.1, 40.25, -59.9, 3},
      {kFeed, 40.25, -59.9, 40.75, -59.4, 4},
      {kRapid, 40.75, -59.4, 40.75, 2.1, 5},
      {kRapid, 40.75, 2.1, 38.25, 2.1, 6},
      {kFeed, 38.25, 2.1, 38.25, -59.9, 3},
      {kFeed, 38.25, -59.9, 38.75, -59.4, 4},
      {kRapid, 38.75, -59.4, 38.75, 2.1, 5},
      {kRapid, 38.75, 2.1, 36.25, 2.1, 6},
      {kFeed, 36.25, 2.1, 36.25, -59.9, 3},
      {kFeed, 36.25, -59.9, 36.75, -59.4, 4},
      {kRapid, 36.75, -59.4, 36.75, 2.1, 5},
      {kRapid, 36.75, 2.1, 34.25, 2.1, 6},
      {kFeed, 34.25, 2.1, 34.25, -59.9, 3},
      {kFeed, 34.25, -59.9, 34.75, -59.4, 4},
      {kRapid, 34.75, -59.4, 34.75, 2.1, 5},
      {kRapid, 34.75, 2.1, 32.25, 2.1, 6},
      {kFeed, 32.25, 2.1, 32.25, -59.9, 3},
      {kFeed, 32.25, -59.9, 32.75, -59.4, 4},
      {kRapid, 32.75, -59.4, 32.75, 2.1, 5},
      {kRapid, 32.75, 2.1, 30.25, 2.1, 6},
      {kFeed, 30.25, 2.1, 30.25, -59.9, 3},
      {kFeed, 30.25, -59.9, 30.75, -59.4, 4},
      {kRapid, 30.75, -59.4, 30.75, 2.1, 5},
      {kRapid, 30.75, 2.1, 28.25, 2.1, 6},
      {kFeed, 28.25, 2.1, 28.25, -37.9, 3},
      {kFeed, 28.25, -37.9, 28.75, -37.4, 4},
      {kRapid, 28.75, -37.4, 28.75, 2.1, 5},
      {kRapid, 28.75, 2.1, 26.25, 2.1, 6},
      {kFeed, 26.25, 2.1, 26.25, -35.9, 3},
      {kFeed, 26.25, -35.9, 26.75, -35.4, 4},
      {kRapid, 26.75, -35.4, 26.75, 2.1, 5},
      {kRapid, 26.75, 2.1, 24.25, 2.1, 6},
      {kFeed, 24.25, 2.1, 24.25, -33.9, 3},
      {kFeed, 24.25, -33.9, 24.75, -33.4, 4},
      {kRapid, 24.75, -33.4, 24.75, 2.1, 5},
      {kRapid, 24.75, 2.1, 22.25, 2.1, 6},
      {kFeed, 22.25, 2.1, 22.25, -31.9, 3},
      {kFeed, 22.25, -31.9, 22.75, -31.4, 4},
      {kRapid, 22.75, -31.4, 22.75, 2.1, 5},
      // The next level would reach B′: infeed to B′ (rapid: the ns block is G00), then the
      // semi-finishing pass along the rough contour and the rapid back to A.
      {kRapid, 22.75, 2.1, 20.25, 2.1, 6},
      {kFeed, 20.25, 2.1, 20.25, -29.9, 7},
      {kFeed, 20.25, -29.9, 30.25, -39.9, 7},
      {kFeed, 30.25, -39.9, 30.25, -59.9, 7},
      {kFeed, 30.25, -59.9, 50.25, -59.9, 7},
      {kRapid, 50.25, -59.9, 50, 2, 8},
  });
}

// The same with the Fanuc-style rapid retract: only the kind of the step-4 legs changes.
TEST(TurningRoughing, RetractAtRapidWhenAsked) {
  RoughingParams p = params(2, 0.5, 0.25, 0.1);
  p.retractAtFeed = false;
  const auto legs = turningRoughingLegs(RZ(50, 2), odTaperContour(), p);
  ASSERT_TRUE(legs.ok()) << legs.error().message;
  int retracts = 0;
  for (const CycleLeg& leg : legs.value()) {
    if (leg.step != 4) continue;
    ++retracts;
    EXPECT_EQ(leg.kind, kRapid);
  }
  EXPECT_EQ(retracts, 14);
}

// A = X60 Z2 (radius 30); N10 G00 X20; N20 G01 Z-10;
// N30 G02 X40 Z-20 R10 (concave fillet, centre (20, -10));
// N40 G03 X60 Z-30 R10 (convex, centre (20, -30)); N50 G01 Z-40.
Contour odArcContour() {
  return {segment(kRapid, 30, 2, 10, 2, 10), segment(kFeed, 10, 2, 10, -10, 20),
          arcSegment(kCw, 10, -10, 20, -20, 20, -10, 30),
          arcSegment(kCcw, 20, -20, 30, -30, 20, -30, 40), segment(kFeed, 30, -30, 30, -40, 50)};
}

// Δd 3, e 1, allowance (0.5, 0.2): A′ = (30.5, 2.2), B′ = (10.5, 2.2); the arcs' centres move
// to (20.5, -9.8) and (20.5, -29.8), radius 10. Depth to cut 20: levels 27.5, 24.5, 21.5,
// 18.5, 15.5, 12.5. With θ the angle from the centre (X = Xc + 10 sin θ, Z = Zc + 10 cos θ):
//   convex arc (cos θ ≥ 0): 27.5 → sin 0.7, Z = -29.8 + 10·√0.51 = -22.658571571457152
//                           24.5 → sin 0.4, Z = -29.8 + 10·√0.84 = -20.63484861008832
//                           21.5 → sin 0.1, Z = -29.8 + 10·√0.99 = -19.850125628933803
//   concave arc (cos θ ≤ 0): 18.5 → sin -0.2, Z = -9.8 - 10·√0.96 = -19.597958971132712
//                           15.5 → sin -0.5, Z = -9.8 - 10·√0.75 = -18.460254037844386
//                           12.5 → sin -0.8, Z = -9.8 - 10·0.6 = -15.8
TEST(TurningRoughing, PassesEndOnTheTranslatedArcs) {
  const auto legs = turningRoughingLegs(RZ(30, 2), odArcContour(), params(3, 1, 0.5, 0.2));
  ASSERT_TRUE(legs.ok()) << legs.error().message;
  std::vector<CycleLeg> cutLegs;
  std::vector<CycleLeg> semiFinishLegs;
  for (const CycleLeg& leg : legs.value()) {
    if (leg.step == 3) cutLegs.push_back(leg);
    if (leg.step == 7) semiFinishLegs.push_back(leg);
  }
  expectLegsNear(cutLegs, {
      {kFeed, 27.5, 2.2, 27.5, -22.658571571457152, 3},
      {kFeed, 24.5, 2.2, 24.5, -20.63484861008832, 3},
      {kFeed, 21.5, 2.2, 21.5, -19.850125628933803, 3},
      {kFeed, 18.5, 2.2, 18.5, -19.597958971132712, 3},
      {kFeed, 15.5, 2.2, 15.5, -18.460254037844386, 3},
      {kFeed, 12.5, 2.2, 12.5, -15.8, 3},
  });
  // The arcs stay arcs, about the translated centres.
  expectLegsNear(semiFinishLegs, {
      {kFeed, 10.5, 2.2, 10.5, -9.8, 7},
      {kCw, 10.5, -9.8, 20.5, -19.8, 7, 20.5, -9.8},
      {kCcw, 20.5, -19.8, 30.5, -29.8, 7, 20.5, -29.8},
      {kFeed, 30.5, -29.8, 30.5, -39.8, 7},
  });
  // Last level 12.5 retracts to (13.5, -14.8), returns to (13.5, 2.2), then infeeds to B′.
  const CycleLeg& toB = legs.value()[legs.value().size() - 6];
  EXPECT_EQ(toB.step, 6);
  EXPECT_NEAR(toB.from.x(), 13.5, 1e-9);
  EXPECT_NEAR(toB.to.x(), 10.5, 1e-9);
  EXPECT_NEAR(toB.to.y(), 2.2, 1e-9);
}

// Boring. A = X20 Z2 (radius 10) inside the drilled hole; N10 G01 X60 (radius 30);
// N20 Z-20; N30 X40 Z-30 (radius 20); N40 Z-50; N50 X20 (radius 10).
// G71 U4 R0.5; G71 P10 Q50 U-0.5 W0.1, Fanuc-style rapid retract.
// Allowance (-0.25, 0.1): A′ = (9.75, 2.1), B′ = (29.75, 2.1): the levels step OUTWARD.
// Rough contour: B′ → (29.75, -19.9) → (19.75, -29.9) → (19.75, -49.9) → C′ (9.75, -49.9).
// Depth 20: levels 13.75, 17.75, 21.75, 25.75 (k = 5 reaches B′).
// 13.75 and 17.75 meet the face Z-49.9 last; the taper X = 29.75 - 10t, Z = -19.9 - 10t
// meets 21.75 at t 0.8 (Z -27.9) and 25.75 at t 0.4 (Z -23.9).
// Retract e = 0.5 back toward A: -0.5 in X, +0.5 in Z. Infeed at feed (the ns block is G01).
TEST(TurningRoughing, IdBoringStepsOutward) {
  const Contour contour = {segment(kFeed, 10, 2, 30, 2, 10), segment(kFeed, 30, 2, 30, -20, 20),
                           segment(kFeed, 30, -20, 20, -30, 30),
                           segment(kFeed, 20, -30, 20, -50, 40),
                           segment(kFeed, 20, -50, 10, -50, 50)};
  RoughingParams p = params(4, 0.5, -0.25, 0.1);
  p.retractAtFeed = false;
  const auto legs = turningRoughingLegs(RZ(10, 2), contour, p);
  ASSERT_TRUE(legs.ok()) << legs.error().message;
  expectLegsNear(legs.value(), {
      {kRapid, 10, 2, 9.75, 2.1, 1},
      {kFeed, 9.75, 2.1, 13.75, 2.1, 2},
      {kFeed, 13.75, 2.1, 13.75, -49.9, 3},
      {kRapid, 13.75, -49.9, 13.25, -49.4, 4},
      {kRapid, 13.25, -49.4, 13.25, 2.1, 5},
      {kFeed, 13.25, 2.1, 17.75, 2.1, 6},
      {kFeed, 17.75, 2.1, 17.75, -49.9, 3},
      {kRapid, 17.75, -49.9, 17.25, -49.4, 4},
      {kRapid, 17.25, -49.4, 17.25, 2.1, 5},
      {kFeed, 17.25, 2.1, 21.75, 2.1, 6},
      {kFeed, 21.75, 2.1, 21.75, -27.9, 3},
      {kRapid, 21.75, -27.9, 21.25, -27.4, 4},
      {kRapid, 21.25, -27.4, 21.25, 2.1, 5},
      {kFeed, 21.25, 2.1, 25.75, 2.1, 6},
      {kFeed, 25.75, 2.1, 25.75, -23.9, 3},
      {kRapid, 25.75, -23.9, 25.25, -23.4, 4},
      {kRapid, 25.25, -23.4, 25.25, 2.1, 5},
      {kFeed, 25.25, 2.1, 29.75, 2.1, 6},
      {kFeed, 29.75, 2.1, 29.75, -19.9, 7},
      {kFeed, 29.75, -19.9, 19.75, -29.9, 7},
      {kFeed, 19.75, -29.9, 19.75, -49.9, 7},
      {kFeed, 19.75, -49.9, 9.75, -49.9, 7},
      {kRapid, 9.75, -49.9, 10, 2, 8},
  });
}

// ---- Type II: pockets ------------------------------------------------------------------

// A = X50 Z2 (radius 25). N10 G00 X30 W0 (radius 15: type II); N20 G01 Z-10; N30 X40
// (radius 20, a shoulder); N40 Z-15; N50 X24 Z-20 (radius 12: down into a pocket); N60 Z-25;
// N70 X48 Z-30 (radius 24); N80 X50. G71 U4 R1; G71 P10 Q80 U0 W0.
Contour pocketContour() {
  return {segment(kRapid, 25, 2, 15, 2, 10),     segment(kFeed, 15, 2, 15, -10, 20),
          segment(kFeed, 15, -10, 20, -10, 30),  segment(kFeed, 20, -10, 20, -15, 40),
          segment(kFeed, 20, -15, 12, -20, 50),  segment(kFeed, 12, -20, 12, -25, 60),
          segment(kFeed, 12, -25, 24, -30, 70),  segment(kFeed, 24, -30, 25, -30, 80)};
}

// No allowance: A′ = A. Deepest contour point: radius 12, depth 13: levels 21, 17, 13.
// Wall N50: X = 20 - 8t, Z = -15 - 5t (17 → Z -16.875; 13 → Z -19.375).
// Wall N70: X = 12 + 12t, Z = -25 - 5t (21 → Z -28.75; 17 → Z -27.083333…; 13 → -25.416666…).
// Level 21 lies in the material all the way to N70: one interval; climb N70 and N80 up to the
//   previous level, X_A′ = 25, back off 1 to 26.
// Level 17: material over Z 2…-10 (the cylinder radius 15) and over the pocket Z -16.875 …
//   -27.083333 (the shoulder radius 20 sticks out between). First interval: climb the
//   shoulder face and across its top to (20, -15), where N50 heads down, back off to 21.
//   The pocket: its entry wall, walked back from (17, -16.875), climbs to (20, -15) and stops
//   at the flat top; the tool stands right above it, so it feeds the last e onto it, follows
//   N50 down, cuts, climbs N70 to the level 21 at Z -28.75, backs off to 22.
// Level 13: only the pocket, Z -19.375 … -25.416666. Entry wall N50 walked back up to the
//   previous level 17 at Z -16.875: rapid up to 25, along Z, down to 18 (e short), feed to 17,
//   down the wall, cut, climb N70 to 17 at Z -27.083333, back off to 18.
// Then back over X 25 to Z 2, infeed to B′ (rapid: G00), the semi-finishing pass, rapid to A.
TEST(TurningRoughingTypeII, PocketIsEnteredDownItsWallAndLeftUpTheOther) {
  RoughingParams p = params(4, 1, 0, 0);
  p.typeII = true;
  const auto legs = turningRoughingLegs(RZ(25, 2), pocketContour(), p);
  ASSERT_TRUE(legs.ok()) << legs.error().message;
  constexpr double z17 = -25 - 25.0 / 12;  // -27.083333…
  constexpr double z13 = -25 - 5.0 / 12;   // -25.416666…
  expectLegsNear(legs.value(), {
      {kRapid, 25, 2, 21, 2, 2},
      {kFeed, 21, 2, 21, -28.75, 3},
      {kFeed, 21, -28.75, 24, -30, 4},
      {kFeed, 24, -30, 25, -30, 4},
      {kFeed, 25, -30, 26, -30, 4},
      {kRapid, 26, -30, 26, 2, 5},
      {kRapid, 26, 2, 17, 2, 6},
      {kFeed, 17, 2, 17, -10, 3},
      {kFeed, 17, -10, 20, -10, 4},
      {kFeed, 20, -10, 20, -15, 4},
      {kFeed, 20, -15, 21, -15, 4},
      {kFeed, 21, -15, 20, -15, 6},
      {kFeed, 20, -15, 17, -16.875, 6},
      {kFeed, 17, -16.875, 17, z17, 3},
      {kFeed, 17, z17, 21, -28.75, 4},
      {kFeed, 21, -28.75, 22, -28.75, 4},
      {kRapid, 22, -28.75, 25, -28.75, 5},
      {kRapid, 25, -28.75, 25, -16.875, 5},
      {kRapid, 25, -16.875, 18, -16.875, 5},
      {kFeed, 18, -16.875, 17, -16.875, 6},
      {kFeed, 17, -16.875, 13, -19.375, 6},
      {kFeed, 13, -19.375, 13, z13, 3},
      {kFeed, 13, z13, 17, z17, 4},
      {kFeed, 17, z17, 18, z17, 4},
      {kRapid, 18, z17, 25, z17, 5},
      {kRapid, 25, z17, 25, 2, 5},
      {kRapid, 25, 2, 15, 2, 6},
      {kFeed, 15, 2, 15, -10, 7},
      {kFeed, 15, -10, 20, -10, 7},
      {kFeed, 20, -10, 20, -15, 7},
      {kFeed, 20, -15, 12, -20, 7},
      {kFeed, 12, -20, 12, -25, 7},
      {kFeed, 12, -25, 24, -30, 7},
      {kFeed, 24, -30, 25, -30, 7},
      {kRapid, 25, -30, 25, 2, 8},
  });
}

// A = X50 Z2 (radius 25). N10 G00 X40 W0 (radius 20); N20 G01 Z-10;
// N30 G02 Z-20 R5 (a round groove about (20, -15), down to radius 15: X reverses inside the
// arc, which type II allows); N40 G01 Z-30; N50 X50. G71 U3 R0.5; G71 P10 Q50 U0 W0.
Contour roundGrooveContour() {
  return {segment(kRapid, 25, 2, 20, 2, 10), segment(kFeed, 20, 2, 20, -10, 20),
          arcSegment(kCw, 20, -10, 20, -20, 20, -15, 30), segment(kFeed, 20, -20, 20, -30, 40),
          segment(kFeed, 20, -30, 25, -30, 50)};
}

// Deepest point radius 15 (depth 10): levels 22, 19, 16. On the groove X = 20 − √(25 − (Z+15)²):
//   X 19 at Z = -15 ± √24 = -10.101020514433644 (za) and -19.898979485566358 (zb)
//   X 16 at Z = -15 ± 3 = -12 and -18.
// Level 22: one interval to the end face at Z-30; climb the face to 25, back off to 25.5.
// Level 19: the cylinder radius 20 lies above it, so only the groove: its entry wall, walked
//   back from (19, za), climbs the arc to (20, -10) and stops at the flat cylinder. Rapid
//   over X 25 to Z-10, down to the previous level 22 (e short of W would be 20.5, below the
//   level 22, where the band over the cylinder is still uncut), feed to W, down the arc, cut,
//   climb the arc to (20, -20), across the flat to Z-30 (cutting the band there), up the face
//   to 22, back off to 22.5.
// Level 16: entry wall walked back up to the level 19 at za; rapid down to 19.5, feed to 19,
//   down the arc to (16, -12), cut to -18, climb the arc to 19 at zb, back off to 19.5.
TEST(TurningRoughingTypeII, RoundGrooveFollowsTheArc) {
  RoughingParams p = params(3, 0.5, 0, 0);
  p.typeII = true;
  const auto legs = turningRoughingLegs(RZ(25, 2), roundGrooveContour(), p);
  ASSERT_TRUE(legs.ok()) << legs.error().message;
  constexpr double za = -10.101020514433644;
  constexpr double zb = -19.898979485566358;
  expectLegsNear(legs.value(), {
      {kRapid, 25, 2, 22, 2, 2},
      {kFeed, 22, 2, 22, -30, 3},
      {kFeed, 22, -30, 25, -30, 4},
      {kFeed, 25, -30, 25.5, -30, 4},
      {kRapid, 25.5, -30, 25, -30, 5},
      {kRapid, 25, -30, 25, -10, 5},
      {kRapid, 25, -10, 22, -10, 5},
      {kFeed, 22, -10, 20, -10, 6},
      {kCw, 20, -10, 19, za, 6, 20, -15},
      {kFeed, 19, za, 19, zb, 3},
      {kCw, 19, zb, 20, -20, 4, 20, -15},
      {kFeed, 20, -20, 20, -30, 4},
      {kFeed, 20, -30, 22, -30, 4},
      {kFeed, 22, -30, 22.5, -30, 4},
      {kRapid, 22.5, -30, 25, -30, 5},
      {kRapid, 25, -30, 25, za, 5},
      {kRapid, 25, za, 19.5, za, 5},
      {kFeed, 19.5, za, 19, za, 6},
      {kCw, 19, za, 16, -12, 6, 20, -15},
      {kFeed, 16, -12, 16, -18, 3},
      {kCw, 16, -18, 19, zb, 4, 20, -15},
      {kFeed, 19, zb, 19.5, zb, 4},
      {kRapid, 19.5, zb, 25, zb, 5},
      {kRapid, 25, zb, 25, 2, 5},
      {kRapid, 25, 2, 20, 2, 6},
      {kFeed, 20, 2, 20, -10, 7},
      {kCw, 20, -10, 20, -20, 7, 20, -15},
      {kFeed, 20, -20, 20, -30, 7},
      {kFeed, 20, -30, 25, -30, 7},
      {kRapid, 25, -30, 25, 2, 8},
  });
}

// The same pocket contour is refused as type I: X turns back toward B at N50.
TEST(TurningRoughingTypeII, PocketNeedsTypeII) {
  expectRoughingError(turningRoughingLegs(RZ(25, 2), pocketContour(), params(4, 1, 0, 0)), 50,
                      1, "G71 type I contour must be monotonic in X");
}

// Type II still needs Z monotonic: N60 turned back to Z-18.
TEST(TurningRoughingTypeII, ZMustStayMonotonic) {
  Contour contour = pocketContour();
  contour[5] = segment(kFeed, 12, -20, 12, -18, 60);
  contour[6] = segment(kFeed, 12, -18, 24, -30, 70);
  RoughingParams p = params(4, 1, 0, 0);
  p.typeII = true;
  expectRoughingError(turningRoughingLegs(RZ(25, 2), contour, p), 60, 1,
                      "G71 contour must be monotonic in Z: this block moves Z against");
}

// ---- The contour rules --------------------------------------------------------------

TEST(TurningRoughingErrors, DepthMustBePositive) {
  expectRoughingError(turningRoughingLegs(RZ(50, 2), odTaperContour(), params(0, 0.5, 0, 0)),
                      10, 1, "G71 depth of cut Δd is 0; expected a depth greater than 0");
  expectRoughingError(turningRoughingLegs(RZ(50, 2), odTaperContour(), params(-1, 0.5, 0, 0)),
                      10, 1, "depth of cut Δd is -1");
}

TEST(TurningRoughingErrors, RetractMustNotBeNegative) {
  expectRoughingError(turningRoughingLegs(RZ(50, 2), odTaperContour(), params(2, -0.5, 0, 0)),
                      10, 1, "G71 retract e is -0.5; expected 0 or more");
}

TEST(TurningRoughingErrors, EmptyContour) {
  expectRoughingError(turningRoughingLegs(RZ(50, 2), {}, params(2, 0.5, 0, 0)), 0, 0,
                      "G71 contour is empty");
}

TEST(TurningRoughingErrors, NsBlockMustNotBeAnArc) {
  const Contour contour = {arcSegment(kCw, 50, 2, 40, -8, 40, 2, 10),
                           segment(kFeed, 40, -8, 50, -8, 20)};
  expectRoughingError(turningRoughingLegs(RZ(50, 2), contour, params(2, 0.5, 0, 0)), 10, 1,
                      "G71 ns block is an arc; expected G00 or G01");
}

TEST(TurningRoughingErrors, NsBlockMustMoveX) {
  const Contour contour = {segment(kFeed, 50, 2, 50, -8, 10), segment(kFeed, 50, -8, 60, -8, 20)};
  expectRoughingError(turningRoughingLegs(RZ(50, 2), contour, params(2, 0.5, 0, 0)), 10, 1,
                      "G71 ns block does not move X");
}

TEST(TurningRoughingErrors, TypeIContourMustBeMonotonicInX) {
  // N30 goes from radius 30 back down to 25: toward B again (a pocket, type I cannot).
  Contour contour = odTaperContour();
  contour[3] = segment(kFeed, 30, -40, 25, -60, 40);
  contour[4] = segment(kFeed, 25, -60, 50, -60, 50);
  expectRoughingError(turningRoughingLegs(RZ(50, 2), contour, params(2, 0.5, 0, 0)), 40, 1,
                      "G71 type I contour must be monotonic in X: this block moves X back "
                      "toward B");
}

TEST(TurningRoughingErrors, ContourMustBeMonotonicInZ) {
  // N40 goes back from Z-40 to Z-35.
  Contour contour = odTaperContour();
  contour[3] = segment(kFeed, 30, -40, 30, -35, 40);
  contour[4] = segment(kFeed, 30, -35, 50, -35, 50);
  expectRoughingError(turningRoughingLegs(RZ(50, 2), contour, params(2, 0.5, 0, 0)), 40, 1,
                      "G71 contour must be monotonic in Z: this block moves Z against the "
                      "blocks before it");
}

TEST(TurningRoughingErrors, ArcMustNotReverseX) {
  // N30 G02 from (10, -10) to (10, -30) about (10, -20): a half circle bulging to radius 20,
  // X rises then falls inside it.
  const Contour contour = {segment(kRapid, 30, 2, 10, 2, 10), segment(kFeed, 10, 2, 10, -10, 20),
                           arcSegment(kCw, 10, -10, 10, -30, 10, -20, 30),
                           segment(kFeed, 10, -30, 30, -30, 40)};
  expectRoughingError(turningRoughingLegs(RZ(30, 2), contour, params(2, 0.5, 0, 0)), 30, 1,
                      "G71 type I contour must be monotonic in X: this arc reverses X inside "
                      "its span");
}

TEST(TurningRoughingErrors, ArcMustNotReverseZ) {
  // N30 G02 from (10, -10) to (20, -10) about (15, -10): a half circle dipping to Z-15 and
  // coming back: Z reverses inside it (its ends have the same Z).
  const Contour contour = {segment(kRapid, 30, 2, 10, 2, 10), segment(kFeed, 10, 2, 10, -10, 20),
                           arcSegment(kCw, 10, -10, 20, -10, 15, -10, 30),
                           segment(kFeed, 20, -10, 20, -30, 40)};
  expectRoughingError(turningRoughingLegs(RZ(30, 2), contour, params(2, 0.5, 0, 0)), 30, 1,
                      "G71 contour must be monotonic in Z: this arc reverses Z inside its span");
}

// ---- Property: the roughing never gouges the rough contour ---------------------------

TEST(TurningRoughingProperty, RoughingNeverGougesTheRoughContour) {
  const Contour contour = odArcContour();
  for (const double depthMm : {0.7, 1.3, 2.9}) {
    const RoughingParams p = params(depthMm, 0.4, 0.5, 0.2);
    const auto legs = turningRoughingLegs(RZ(30, 2), contour, p);
    ASSERT_TRUE(legs.ok()) << legs.error().message;
    Contour rough = contour;
    for (ContourSegment& s : rough) {
      s.from += RZ(0.5, 0.2);
      s.to += RZ(0.5, 0.2);
      s.center += RZ(0.5, 0.2);
    }
    test::expectNoGouge(legs.value(), rough, -1.0);
  }
  // A bore: A = X10 Z2 (radius 5); N10 G00 X40 (radius 20); N20 G01 Z-10;
  // N30 G03 X20 Z-20 R10 (about (10, -10)); N40 G01 Z-30; N50 X10.
  const Contour bore = {segment(kRapid, 5, 2, 20, 2, 10), segment(kFeed, 20, 2, 20, -10, 20),
                        arcSegment(kCcw, 20, -10, 10, -20, 10, -10, 30),
                        segment(kFeed, 10, -20, 10, -30, 40), segment(kFeed, 10, -30, 5, -30, 50)};
  for (const double depthMm : {0.9, 2.2, 4.1}) {
    const auto legs = turningRoughingLegs(RZ(5, 2), bore, params(depthMm, 0.5, -0.3, 0.1));
    ASSERT_TRUE(legs.ok()) << legs.error().message;
    Contour rough = bore;
    for (ContourSegment& s : rough) {
      s.from += RZ(-0.3, 0.1);
      s.to += RZ(-0.3, 0.1);
      s.center += RZ(-0.3, 0.1);
    }
    test::expectNoGouge(legs.value(), rough, 1.0);
  }
  const Contour taper = odTaperContour();
  const auto legs = turningRoughingLegs(RZ(50, 2), taper, params(1.7, 0.3, 0.25, 0.1));
  ASSERT_TRUE(legs.ok()) << legs.error().message;
  Contour rough = taper;
  for (ContourSegment& s : rough) {
    s.from += RZ(0.25, 0.1);
    s.to += RZ(0.25, 0.1);
  }
  test::expectNoGouge(legs.value(), rough, -1.0);
}

// Type II, OD and boring, straight and round pockets, several depths and retracts, with an
// allowance: no roughing cut crosses the rough contour.
TEST(TurningRoughingProperty, TypeIINeverGougesTheRoughContour) {
  // A bore (A = X10 Z2, radius 5) with a round groove outward: N10 G00 X20 W0 (radius 10);
  // N20 G01 Z-10; N30 G03 Z-20 R5 (about (10, -15), out to radius 15); N40 G01 Z-30; N50 X10.
  const Contour bore = {segment(kRapid, 5, 2, 10, 2, 10), segment(kFeed, 10, 2, 10, -10, 20),
                        arcSegment(kCcw, 10, -10, 10, -20, 10, -15, 30),
                        segment(kFeed, 10, -20, 10, -30, 40), segment(kFeed, 10, -30, 5, -30, 50)};
  struct Case {
    Contour contour;
    RZ start;
    RZ allowance;
  };
  // The pocket contour with an ns block that moves Z too: N10 G00 X30 Z0 (from Z2).
  Contour slantedNs = pocketContour();
  slantedNs[0].to = RZ(15, 0);
  slantedNs[1].from = RZ(15, 0);
  const std::vector<Case> cases = {{pocketContour(), RZ(25, 2), RZ(0.3, 0)},
                                   {slantedNs, RZ(25, 2), RZ(0.3, 0)},
                                   {roundGrooveContour(), RZ(25, 2), RZ(0.2, 0)},
                                   {bore, RZ(5, 2), RZ(-0.2, 0)}};
  for (const Case& c : cases) {
    const double stepDir = c.contour.front().to.x() > c.start.x() ? 1.0 : -1.0;
    for (const double depthMm : {0.6, 1.1, 2.3, 3.7}) {
      for (const double retractMm : {0.0, 0.4, 1.5}) {
        RoughingParams p = params(depthMm, retractMm, c.allowance.x(), c.allowance.y());
        p.typeII = true;
        const auto legs = turningRoughingLegs(c.start, c.contour, p);
        ASSERT_TRUE(legs.ok()) << legs.error().message;
        Contour rough = c.contour;
        for (ContourSegment& s : rough) {
          s.from += c.allowance;
          s.to += c.allowance;
          s.center += c.allowance;
        }
        SCOPED_TRACE(testing::Message() << "depth " << depthMm << " retract " << retractMm);
        test::expectNoGouge(legs.value(), rough, stepDir);
      }
    }
  }
}

// Random contours (fixed seed): type I staircases and tapers toward -Z and out in X, and
// type II profiles whose X wanders, each with random Δd, e and allowance.
TEST(TurningRoughingProperty, RandomContoursNeverGouge) {
  std::mt19937 random(71);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 60; ++trial) {
    const bool typeII = trial % 2 == 1;
    const RZ start(30, 2);
    Contour contour;
    RZ at(5 + 10 * unit(random), 2);
    contour.push_back({kRapid, start, at, RZ(0, 0), 10, 1});
    for (int i = 0; i < 6; ++i) {
      RZ next = at + RZ(0, -(0.5 + 6 * unit(random)));  // Z always falls
      if (typeII) {
        next.x() = 3 + 22 * unit(random);
      } else {
        next.x() = std::min(28.0, at.x() + (unit(random) < 0.3 ? 0 : 6 * unit(random)));
      }
      if (unit(random) < 0.3) next.y() = at.y();  // a face: X only
      contour.push_back({kFeed, at, next, RZ(0, 0), 20 + 10 * i, 1});
      at = next;
    }
    RoughingParams p = params(0.3 + 3 * unit(random), 2 * unit(random), unit(random) - 0.3,
                              typeII ? 0 : 0.3 * unit(random));
    p.typeII = typeII;
    const auto legs = turningRoughingLegs(start, contour, p);
    ASSERT_TRUE(legs.ok()) << legs.error().message;
    Contour rough = contour;
    for (ContourSegment& s : rough) {
      s.from += RZ(p.allowanceXMm, p.allowanceZMm);
      s.to += RZ(p.allowanceXMm, p.allowanceZMm);
    }
    SCOPED_TRACE(testing::Message() << "trial " << trial);
    test::expectNoGouge(legs.value(), rough, -1.0);
  }
}

// The checker itself: a cut that dips below the contour is caught.
TEST(TurningRoughingProperty, GougeCheckerCatchesADip) {
  const Contour rough = odTaperContour();
  const std::vector<CycleLeg> gouging = {
      {kFeed, RZ(25, -10), RZ(19, -10), 3}};  // the contour has radius 20 at Z-10
  EXPECT_NONFATAL_FAILURE(test::expectNoGouge(gouging, rough, -1.0), "leg step 3");
}

}  // namespace
}  // namespace lathesim::interp
