// G02/G03 end to end through the interpreter. Positions are (radius, Z); X20 is radius 10.
// Centres are worked out by hand in the drawing view (Z to the right, radius up), where
// G02 turns clockwise and G03 counter-clockwise.

#include "interp/motion/arc_move.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "interp/interpreter.hpp"
#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;
using test::run;

using test::kCw;
using test::kCcw;

struct ExpectedArc {
  MoveKind kind;
  double r0, z0, r1, z1;
  double rc, zc;  // the centre
  double feed;
};

void expectArc(const Move& m, const ExpectedArc& e) {
  EXPECT_EQ(m.kind, e.kind);
  EXPECT_NEAR(m.from.x(), e.r0, 1e-9);
  EXPECT_NEAR(m.from.y(), e.z0, 1e-9);
  EXPECT_NEAR(m.to.x(), e.r1, 1e-9);
  EXPECT_NEAR(m.to.y(), e.z1, 1e-9);
  EXPECT_NEAR(m.center.x(), e.rc, 1e-9);
  EXPECT_NEAR(m.center.y(), e.zc, 1e-9);
  EXPECT_NEAR(m.feed, e.feed, 1e-12);
}

// From S = (10, 0) to E = (10, -8) with |R| = 5: half the chord is 4, so the centres lie
// √(25 − 16) = 3 either side of the chord's midpoint (10, -4): (13, -4) above, (7, -4) below.
// Travelling S → E is leftwards in the drawing view, so "right of the travel" is up.
//   G02 R5:  clockwise minor arc, centre on the right: (13, -4); it dips to r = 8 (a groove)
//   G02 R-5: the other centre (7, -4): the major arc, 360° − 106.26° = 253.74°
//   G03 R5:  counter-clockwise minor arc, centre on the left: (7, -4); it bulges to r = 12
//   G03 R-5: (13, -4)
TEST(ArcMove, RadiusFormPicksTheMinorOrMajorArc) {
  const auto result = run(
      "G00 X20 Z0\n"
      "G02 X20 Z-8 R5 F0.1\n"
      "G00 X20 Z0\n"
      "G02 X20 Z-8 R-5\n"
      "G00 X20 Z0\n"
      "G03 X20 Z-8 R5\n"
      "G00 X20 Z0\n"
      "G03 X20 Z-8 R-5\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const auto& moves = result.toolpath.moves;
  ASSERT_EQ(moves.size(), 8u);
  expectArc(moves[1], {kCw, 10, 0, 10, -8, 13, -4, 0.1});
  expectArc(moves[3], {kCw, 10, 0, 10, -8, 7, -4, 0.1});
  expectArc(moves[5], {kCcw, 10, 0, 10, -8, 7, -4, 0.1});
  expectArc(moves[7], {kCcw, 10, 0, 10, -8, 13, -4, 0.1});
  EXPECT_EQ(moves[1].line, 2);
  EXPECT_EQ(moves[1].cycleStep, 0);
}

// A chord at 45°: from (10, 0) to (15, -5), R5. The centres are (15, 0) and (10, -5).
// G02 minor: (15, 0), from straight below the centre to straight left of it, a quarter turn
// clockwise (a concave fillet). G03 minor: (10, -5), from right of it to above it (a
// convex round).
TEST(ArcMove, RadiusFormQuarterArcs) {
  const auto result = run("G00 X20 Z0\nG02 X30 Z-5 R5 F0.2\nG00 X20 Z0\nG03 X30 Z-5 R5\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectArc(result.toolpath.moves.at(1), {kCw, 10, 0, 15, -5, 15, 0, 0.2});
  expectArc(result.toolpath.moves.at(3), {kCcw, 10, 0, 15, -5, 10, -5, 0.2});
}

TEST(ArcMove, OffsetFormIsARadiusVectorFromTheStart) {
  // I-3 K-4 from (10, 0): centre (7, -4), radius 5. The end X24 Z-4 = (12, -4) is 5 from it.
  // (Read as a diameter, I-3 would put the centre at r 8.5 and the end 3.5 from it.)
  const auto result = run("G00 X20 Z0\nG03 X24 Z-4 I-3 K-4 F0.1\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectArc(result.toolpath.moves.at(1), {kCcw, 10, 0, 12, -4, 7, -4, 0.1});
}

TEST(ArcMove, OffsetFormWithTheEndAtTheStartIsAFullCircle) {
  // Centre (10, -4); with or without the end point words.
  const auto result = run("G00 X20 Z0\nG02 I0 K-4 F0.1\nG03 X20 Z0 K-4\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  ASSERT_EQ(result.toolpath.moves.size(), 3u);
  expectArc(result.toolpath.moves[1], {kCw, 10, 0, 10, 0, 10, -4, 0.1});
  expectArc(result.toolpath.moves[2], {kCcw, 10, 0, 10, 0, 10, -4, 0.1});
}

TEST(ArcMove, IncrementalEndPoint) {
  // U4 W-4 from (10, 0): end (12, -4). In the drawing view (Z, r) the chord is (-4, 2),
  // length √20, half √5; the centres lie √(25 − 5) = √20 from the midpoint (Z -2, r 11).
  // Left of the travel is the chord turned a quarter counter-clockwise, (-2, -4)/√20; G03
  // takes the left one: (Z -2 − 2, r 11 − 4) = (Z -4, r 7), i.e. (7, -4), 5 from both ends.
  const auto result = run("G00 X20 Z0\nG03 U4 W-4 R5 F0.1\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectArc(result.toolpath.moves.at(1), {kCcw, 10, 0, 12, -4, 7, -4, 0.1});
}

TEST(ArcMove, ModalContinuationAndSwitchingBack) {
  // Line 3 repeats G03 from (12, -4) to (12, -10) with R5: half chord 3, offset 4; travel
  // is leftwards, so the left (centre of a G03) is down: (8, -7). Line 4 (F only) makes
  // nothing; line 5 is a straight feed again.
  const auto result = run("G00 X20 Z0\nG03 U4 W-4 R5 F0.1\nZ-10 R5\nF0.2\nG01 X30\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const auto& moves = result.toolpath.moves;
  ASSERT_EQ(moves.size(), 4u);
  expectArc(moves[2], {kCcw, 12, -4, 12, -10, 8, -7, 0.1});
  EXPECT_EQ(moves[2].line, 3);
  EXPECT_EQ(moves[3].kind, MoveKind::Feed);
  EXPECT_NEAR(moves[3].feed, 0.2, 1e-12);
}

TEST(ArcMove, ArcCodeClearsTheRetainedCycleValues) {
  // G90 keeps X40 Z-10; G03 (another group-01 code) ends that, so line 4's G90 lacks X.
  expectError(run("G00 X50 Z2\nG90 X40 Z-10 F0.1\nG03 X46 Z-1 R3\nG90 Z-20\n"), 4, 1,
              "G90 needs X(U) and Z(W): the end point's X(U) is neither in this block");
}

TEST(ArcMove, InchWordsIncludingRBecomeMillimetres) {
  // X1 Z0 → (12.7, 0); end Z-0.5 → (12.7, -12.7); R0.25 = 6.35 mm, exactly half the chord:
  // a half circle about the chord's midpoint (12.7, -6.35).
  const auto result = run("G20 G00 X1 Z0\nG02 Z-0.5 R0.25 F0.01\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectArc(result.toolpath.moves.at(1), {kCw, 12.7, 0, 12.7, -12.7, 12.7, -6.35, 0.254});
}

TEST(ArcMove, RadiusWithinTheToleranceOfHalfTheChordIsAHalfCircle) {
  // Chord 12, R5.995: 0.005 short of 6, within 0.01 mm: the centre is the midpoint (10, -6).
  const auto result = run("G00 X20 Z0\nG02 Z-12 R5.995 F0.1\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectArc(result.toolpath.moves.at(1), {kCw, 10, 0, 10, -12, 10, -6, 0.1});
}

// An I/K end point off the circle: the control keeps the radius |IK| and moves the centre onto
// the chord's bisector, on the side of the centre I/K gave, so that both ends lie on the circle.
void expectCentreMovedOntoBothEnds(const Move& arc, const RZ& givenCentre, double radiusMm) {
  EXPECT_NEAR((arc.from - arc.center).norm(), radiusMm, 1e-9);
  EXPECT_NEAR((arc.to - arc.center).norm(), radiusMm, 1e-9);
  // Of the two centres at that radius (each the other's mirror image in the chord), the one
  // nearer the given centre.
  const RZ along = (arc.to - arc.from).normalized();
  const RZ foot = arc.from + (arc.center - arc.from).dot(along) * along;
  const RZ other = 2.0 * foot - arc.center;
  EXPECT_LE((arc.center - givenCentre).norm(), (other - givenCentre).norm());
}

TEST(ArcMove, EndWithinTheToleranceOfTheCircleMovesTheCentreQuietly) {
  // Centre (15, 0) from I5 K0; end (15, -5.008) is 5.008 from it: 0.008 ≤ 0.01.
  const auto result = run("G00 X20. Z0.\nG03 X30. Z-5.008 I5. K0. F0.1\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  EXPECT_TRUE(result.diagnostics.empty());
  const Move& arc = result.toolpath.moves.at(1);
  EXPECT_EQ(arc.to, RZ(15, -5.008));
  expectCentreMovedOntoBothEnds(arc, RZ(15, 0), 5);
  EXPECT_LT((arc.center - RZ(15, 0)).norm(), 0.01);
}

TEST(ArcMove, BeyondTheToleranceTheGskMovesTheCentreAndTheFanucAlarms) {
  // I given as a diameter by mistake: I10 puts the centre at (20, 0), 10 from the start (10, 0);
  // the end (15, -5) is √50 = 7.0711 from it. The chord, √50, is shorter than 2·10: the GSK moves
  // the centre to the one 10 from both ends on I10's side and warns (GSK980TDi §3.4 note 6).
  const auto result = run("G00 X20 Z0\nG03 X30 Z-5 I10 K0 F0.1\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectCentreMovedOntoBothEnds(result.toolpath.moves.at(1), RZ(20, 0), 10);
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].message.rfind("the end point X30 Z-5 is 2.9289 mm off the circle I and K give: the "
                                                "control keeps the radius 10 and moves the centre to X",
                                                0),
            0u)
      << result.diagnostics[0].message;
  // A chord longer than 2|IK| the GSK cannot reach either: I1 from (10, 0) to (15, -5).
  expectError(run("G00 X20 Z0\nG03 X30 Z-5 I1 K0 F0.1\n"), 2, 1,
              "the end lies 7.0711 mm from the start, farther than the arc's diameter 2");
  // fanuc-0i-t (⚠ PS0020): beyond 0.01 mm an alarm.
  InterpreterOptions fanuc = test::defaultOptions();
  fanuc.control.arcEndOffCircle = ArcEndOffCircle::Alarm;
  expectError(run("G00 X20 Z0\nG03 X30 Z-5.02 I5 K0 F0.1\n", fanuc), 2, 1,
              "the end point X30 Z-5.02 is not on the arc: it is 5.02 mm from the centre X30 Z0, "
              "the start point 5 mm; they may differ by at most 0.01 mm");
  expectError(run("G00 X20 Z0\nG03 X30 Z-5 I10 K0 F0.1\n", fanuc), 2, 1,
              "it is 7.0711 mm from the centre X40 Z0, the start point 10 mm");
}

TEST(ArcMove, TheToleranceIsTheControlsParameter) {
  // The end (15, -5.03) lies 0.03 off the circle of radius 5 about (15, 0) that I5 K0 give. With
  // arc_radius_tolerance 0.05 both presets take it: the centre moves quietly onto the chord's
  // bisector; with the default 0.01 the GSK warns and the Fanuc alarms.
  for (const ArcEndOffCircle rule : {ArcEndOffCircle::MoveCentre, ArcEndOffCircle::Alarm}) {
    InterpreterOptions options = test::defaultOptions();
    options.control.arcEndOffCircle = rule;
    options.control.arcRadiusToleranceMm = 0.05;
    const auto result = run("G00 X20. Z0.\nG03 X30. Z-5.03 I5. K0. F0.1\n", options);
    ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
    EXPECT_TRUE(result.diagnostics.empty());
    expectCentreMovedOntoBothEnds(result.toolpath.moves.at(1), RZ(15, 0), 5);
    options.control.arcRadiusToleranceMm = 0.01;
    const auto strict = run("G00 X20. Z0.\nG03 X30. Z-5.03 I5. K0. F0.1\n", options);
    EXPECT_EQ(strict.ok(), rule == ArcEndOffCircle::MoveCentre);
    ASSERT_EQ(strict.diagnostics.size(), 1u);
    EXPECT_EQ(strict.diagnostics[0].severity, rule == ArcEndOffCircle::MoveCentre ? Severity::Warning : Severity::Error);
  }
}

TEST(ArcMove, NoAxisOrCentreWordsMakeNoMove) {
  const auto result = run("G00 X20 Z0\nG02 F0.1\nG03\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  EXPECT_EQ(result.toolpath.moves.size(), 1u);
}

// ---- errors: the specific message, at its line and column ----

TEST(ArcMoveErrors, MissingFeed) {
  expectError(run("G00 X20 Z0\nG02 X30 Z-5 R5\n"), 2, 1,
              "feed rate F is not set: give F (e.g. F0.2 mm/rev) before the first G02 move");
}

TEST(ArcMove, RWinsOverIAndK) {
  // GSK980TDi §3.4 note 2. R5 from (10, 0) to (15, -5), clockwise: chord √50, centre 3.5355 to
  // the right of the travel from the chord's middle (12.5, -2.5): (15, 0). I3 would say (13, 0).
  const auto result = run("G00 X20 Z0\nG02 X30 Z-5 R5 I3 F0.1\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectArc(result.toolpath.moves.at(1), {kCw, 10, 0, 15, -5, 15, 0, 0.1});
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].column, 16);
  EXPECT_EQ(result.diagnostics[0].message,
            "I3 is ignored: R5 gives the arc's radius (R wins over I and K, GSK980TDi §3.4 note 2)");
}

TEST(ArcMoveErrors, NeitherRadiusNorOffset) {
  expectError(run("G00 X20 Z0\nG03 X30 Z-5 F0.1\n"), 2, 1, "G03 needs the arc's centre: give R");
  // Modal G02: the next block also needs its own R or I/K (R is not modal).
  expectError(run("G00 X20 Z0\nG02 X30 Z-5 R5 F0.1\nZ-9\n"), 3, 1, "G02 needs the arc's centre");
}

TEST(ArcMoveErrors, RadiusShorterThanHalfTheChord) {
  // Chord 12 (Z0 → Z-12 at X20): |R| ≥ 6 needed.
  expectError(run("G00 X20 Z0\nG02 X20 Z-12 R5 F0.1\n"), 2, 14,
              "R5 is too small: the end point is 12 mm from the start, so no arc of radius 5 mm "
              "joins them; |R| must be at least 6 mm");
  expectError(run("G00 X20 Z0\nG03 Z-12 R-5.98 F0.1\n"), 2, 10, "R-5.98 is too small");
}

TEST(ArcMove, RToItsOwnStartMakesNoMove) {
  // GSK980TDi §3.4 note 4: with R, end = start is a 0° arc. Warned: a full circle needs I/K.
  const auto result = run("G00 X20 Z0\nG02 X20 Z0 R5 F0.1\nG03 R5\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  EXPECT_EQ(result.toolpath.moves.size(), 1u);
  ASSERT_EQ(result.diagnostics.size(), 2u);
  EXPECT_EQ(result.diagnostics[0].column, 12);
  EXPECT_EQ(result.diagnostics[0].message,
            "G02 R5 ends where it starts: the control makes a 0° arc, no move (a full circle needs I and K, "
            "GSK980TDi §3.4 note 4)");
  EXPECT_EQ(result.diagnostics[1].line, 3);
}

TEST(ArcMoveErrors, CentreOnTheStartPoint) {
  expectError(run("G00 X20 Z0\nG02 X30 Z-5 I0 K0 F0.1\n"), 2, 13,
              "I and K put the centre on the start point, so the arc has no radius");
}

TEST(ArcMoveErrors, ArcOutsideTheZxPlaneSaysThereIsNoYAxis) {
  expectError(run("G17 G00 X20 Z0\nG02 X30 Z-5 R5 F0.1\n"), 2, 1,
              "G02 under G17: this machine has no Y axis, so an arc needs the ZX plane");
  expectError(run("G19 G03 X30 Z-5 R5 F0.1\n"), 1, 5, "G03 under G19: this machine has no Y axis");
}

TEST(ArcMoveErrors, OffsetWordsOutsideAnArcAreLeftOver) {
  expectError(run("G01 X20 Z-3 K-2 F0.1\n"), 1, 13, "K-2 is not used by any code in this block");
}

}  // namespace
}  // namespace lathesim::interp
