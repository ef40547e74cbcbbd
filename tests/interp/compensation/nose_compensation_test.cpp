// G40/G41/G42 through the interpreter: every compensated point worked out by hand.
// Conventions (lathe-cycles.md §8): drawing view, Z to the right, X (radius) up; the travel
// direction t = (tr, tz) has left normal (tz, −tr) in (radius, Z); G41 offsets the nose
// centre C by +R·left, G42 by −R·left; the toolpath carries the imaginary tip C + R·s, s from
// the tip number (3: (−1, −1), 2: (+1, −1), 0/9: (0, 0)).

#include <gtest/gtest.h>

#include <cmath>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::kCw;
using test::kFeed;
using test::kRapid;

// Offset 1: R0.8 tip 3 (an OD turning tool); offset 2: R0.4 tip 2 (a boring bar);
// offset 3: R0.8 tip 9 (the programmed point is the nose centre).
InterpreterOptions compOptions() {
  InterpreterOptions options = test::defaultOptions();
  options.offsets[1] = ToolOffset{0, 0, 0.8, 3, 0, 0};
  options.offsets[2] = ToolOffset{0, 0, 0.4, 2, 0, 0};
  options.offsets[3] = ToolOffset{0, 0, 0.8, 9, 0, 0};
  return options;
}

struct Point {
  MoveKind kind;
  double r0, z0, r1, z1;
  double rc = 0, zc = 0;  // arcs: the centre
};

void expectPath(const std::vector<Move>& moves, const std::vector<Point>& expected) {
  ASSERT_EQ(moves.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE(testing::Message() << "move " << i << " (line " << moves[i].line << ")");
    const Move& m = moves[i];
    const Point& e = expected[i];
    EXPECT_EQ(m.kind, e.kind);
    EXPECT_NEAR(m.from.x(), e.r0, 1e-6);
    EXPECT_NEAR(m.from.y(), e.z0, 1e-6);
    EXPECT_NEAR(m.to.x(), e.r1, 1e-6);
    EXPECT_NEAR(m.to.y(), e.z1, 1e-6);
    if (isArc(e.kind)) {
      EXPECT_NEAR(m.center.x(), e.rc, 1e-6);
      EXPECT_NEAR(m.center.y(), e.zc, 1e-6);
    }
  }
}

const double kRoot2 = std::sqrt(2.0);

TEST(NoseCompensation, OdProfileUnderG42WithTip3) {
  // Drawn (radius, Z): face (0,0)→(8,0), 45° chamfer →(10,-2), diameter →(10,-10), G02
  // fillet R5 about (15,-10) →(15,-15), shoulder →(17,-15). G42, R = 0.8, tip 3.
  // Right normal of t = (tr, tz) is (−tz, tr). Nose-centre path:
  //   face     t (1,0), normal (0,1):      z = 0.8
  //   chamfer  t (1,-1)/√2, normal (1,1)/√2: r + z = 8 + 0.8√2
  //   diameter t (0,-1), normal (1,0):     r = 10.8
  //   fillet   CW about (15,-10), the right normal points at the centre: radius 5 − 0.8
  //            = 4.2, from (10.8,-10) to (15,-14.2)
  //   shoulder t (1,0), normal (0,1):      z = -14.2, r 15 → 17
  // Corners face→chamfer and chamfer→diameter turn left by 45° (outer for G42, at most 90°):
  // the offset lines meet at (8 + 0.8√2 − 0.8, 0.8) and (10.8, -2 + 0.8√2 − 0.8).
  // Diameter→fillet and fillet→shoulder are tangent: no corner.
  // Start-up N3 (0,5)→(0,0): the centre ends perpendicular to the face at its start, (0,0.8).
  // Cancel N9: the centre ends the shoulder at (17,-14.2); G00 to the programmed (20,-15).
  // Tip = centre + 0.8·(−1,−1).
  const std::string_view program =
      "N1 G99 M03 S800 T0101\n"
      "N2 G00 X0 Z5\n"
      "N3 G42 G01 Z0 F0.1\n"
      "N4 X16\n"
      "N5 X20 Z-2\n"
      "N6 Z-10\n"
      "N7 G02 X30 Z-15 R5\n"
      "N8 G01 X34\n"
      "N9 G40 G00 X40\n"
      "M30\n";
  const auto result = test::run(program, compOptions());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const double corner = 0.8 * kRoot2 - 0.8;  // 0.331371: the extension past each 45° corner
  expectPath(result.toolpath.moves,
             {{kRapid, 100, 200, 0, 5},
              {kFeed, 0, 5, 0 - 0.8, 0.8 - 0.8},
              {kFeed, -0.8, 0, 8 + corner - 0.8, 0},
              {kFeed, 8 + corner - 0.8, 0, 10.8 - 0.8, -2 + corner - 0.8},
              {kFeed, 10, -2 + corner - 0.8, 10, -10.8},
              {kCw, 10, -10.8, 15 - 0.8, -15, 15 - 0.8, -10 - 0.8},
              {kFeed, 14.2, -15, 16.2, -15},
              {kRapid, 16.2, -15, 20, -15}});
  // The chamfer's tip line is the drawn one moved by 0.8·(2 − √2) = 0.4686 in r + z.
  const Move& chamfer = result.toolpath.moves[3];
  EXPECT_NEAR(chamfer.to.x() + chamfer.to.y(), 8 - 0.8 * (2 - kRoot2), 1e-9);
  EXPECT_EQ(chamfer.noseComp.side, NoseSide::Right);
  EXPECT_EQ(chamfer.noseComp.tip, 3);
  EXPECT_DOUBLE_EQ(chamfer.noseComp.radiusMm, 0.8);
}

TEST(NoseCompensation, BoringUnderG41WithTip2) {
  // Drawn: taper from (16,0) in to (12,-4), bore r 12 to Z-20. G41, R = 0.4, tip 2 (+X, −Z).
  // Left normal of t = (tr, tz) is (tz, −tr):
  //   taper t (-1,-1)/√2, normal (-1,1)/√2: centre from (16 − 0.2√2, 0.2√2), line
  //         r − z = 16 − 0.4√2
  //   bore  t (0,-1), normal (-1,0): r = 11.6
  // The corner turns right by 45° (outer for G41): the lines meet at z = 11.6 − 16 + 0.4√2.
  // Start-up N3 (16,3)→(16,0): the centre ends at the taper's offset start. Cancel N6: the
  // bore's centre end (11.6,-20), then G00 to (10,-20). Tip = centre + 0.4·(1,−1).
  const std::string_view program =
      "N1 G99 M03 S800 T0202\n"
      "N2 G00 X32 Z3\n"
      "N3 G41 G01 Z0 F0.1\n"
      "N4 X24 Z-4\n"
      "N5 Z-20\n"
      "N6 G40 G00 X20\n"
      "M30\n";
  const auto result = test::run(program, compOptions());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const double h = 0.2 * kRoot2;  // 0.4/√2
  const double cornerZ = 11.6 - 16 + 0.4 * kRoot2;
  expectPath(result.toolpath.moves, {{kRapid, 100, 200, 16, 3},
                                     {kFeed, 16, 3, 16 - h + 0.4, h - 0.4},
                                     {kFeed, 16 - h + 0.4, h - 0.4, 12, cornerZ - 0.4},
                                     {kFeed, 12, cornerZ - 0.4, 12, -20.4},
                                     {kRapid, 12, -20.4, 10, -20}});
}

TEST(NoseCompensation, SharpOuterCornerGetsFanucsExtraVectors) {
  // G42 R0.8, tip 9 (the toolpath is the centre path). N4 turns along r 10 to Z-5; N5 backs
  // off to (7,-1), t2 = (-3,4)/5: a left turn by more than 90° (t1·t2 = -0.8), outer for G42.
  //   N4 centre: r = 10.8, (10.8,2) → (10.8,-5); N5 right normal (−tz, tr) = (-0.8,-0.6):
  //   (10,-5) + 0.8·(-0.8,-0.6) = (9.36,-5.48) → (7,-1) + (-0.64,-0.48) = (6.36,-1.48)
  // Extra vectors at the corner (line N4): E = (10.8,-5) → E + 0.8·t1 = (10.8,-5.8) →
  // S − 0.8·t2 = (9.36 + 0.48, -5.48 − 0.64) = (9.84,-6.12) → S = (9.36,-5.48).
  const std::string_view program =
      "N1 G99 M03 S800 T0103\n"
      "N2 G00 X20 Z5\n"
      "N3 G42 G01 Z2 F0.1\n"
      "N4 Z-5\n"
      "N5 X14 Z-1\n"
      "N6 G40 G00 X30\n"
      "M30\n";
  const auto result = test::run(program, compOptions());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const auto& moves = result.toolpath.moves;
  expectPath(moves, {{kRapid, 100, 200, 10, 5},
                     {kFeed, 10, 5, 10.8, 2},
                     {kFeed, 10.8, 2, 10.8, -5},
                     {kFeed, 10.8, -5, 10.8, -5.8},
                     {kFeed, 10.8, -5.8, 9.84, -6.12},
                     {kFeed, 9.84, -6.12, 9.36, -5.48},
                     {kFeed, 9.36, -5.48, 6.36, -1.48},
                     {kRapid, 6.36, -1.48, 15, -1}});
  for (int i : {3, 4, 5}) EXPECT_EQ(moves[static_cast<std::size_t>(i)].line, 4);
}

TEST(NoseCompensation, G42AloneStartsOnTheNextMoveAndEmptyBlocksDoNotBreakTheChain) {
  // G42 alone in N3 takes effect with N4's move (the start-up); N6 repeats the position (no
  // move) and must not break the chain. Tip 9, R0.8:
  //   start-up N4 (10,5)→(10,2): the centre ends perpendicular to N5 (t (0,-1), right
  //   normal (1,0)) at (10.8,2); N5 centre r 10.8 to Z-5; N7 X24 (t (1,0), normal (0,1)):
  //   an inner corner (right turn under G42): the lines r = 10.8 and z = -4.2 meet at
  //   (10.8,-4.2); N7's centre ends at (12,-4.2); cancel N8 G40 G00 Z5 → (12,5).
  const std::string_view program =
      "N1 G99 M03 S800 T0103\n"
      "N2 G00 X20 Z5\n"
      "N3 G42\n"
      "N4 G01 Z2 F0.1\n"
      "N5 Z-5\n"
      "N6 Z-5\n"
      "N7 X24\n"
      "N8 G40 G00 Z5\n"
      "M30\n";
  const auto result = test::run(program, compOptions());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectPath(result.toolpath.moves, {{kRapid, 100, 200, 10, 5},
                                     {kFeed, 10, 5, 10.8, 2},
                                     {kFeed, 10.8, 2, 10.8, -4.2},
                                     {kFeed, 10.8, -4.2, 12, -4.2},
                                     {kRapid, 12, -4.2, 12, 5}});
}

TEST(NoseCompensation, InnerCornerIntoAnArcIsTrimmedToTheirIntersection) {
  // G42 R0.8 tip 9. N4 along r 10 to Z-5, then N5 G03 R5 to (15,-10) about (10,-10): it
  // leaves (10,-5) going +X (radial (0,1) turned left), a right turn from −Z: an inner corner
  // for G42. The arc is CCW, its right normal points away from the centre: radius 5.8.
  // The line r = 10.8 meets that circle where (0.8)² + (z + 10)² = 5.8², z = -10 ± √33; the
  // point nearer the corner (10,-5) is z = -10 + √33. The arc ends at (15.8,-10), tangent to
  // N6 along r 15.8; the cancel N7 from (15.8,-15) to (20,-15).
  const auto result = test::run("T0103 G99\nG00 X20 Z5\nG42 G01 Z2 F0.1\nZ-5\n"
                                "G03 X30 Z-10 R5\nG01 Z-15\nG40 G00 X40\nM30\n",
                                compOptions());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const double meet = -10 + std::sqrt(33.0);
  expectPath(result.toolpath.moves, {{kRapid, 100, 200, 10, 5},
                                     {kFeed, 10, 5, 10.8, 2},
                                     {kFeed, 10.8, 2, 10.8, meet},
                                     {MoveKind::ArcCCW, 10.8, meet, 15.8, -10, 10, -10},
                                     {kFeed, 15.8, -10, 15.8, -15},
                                     {kRapid, 15.8, -15, 20, -15}});
}

TEST(NoseCompensation, OuterCornerWhoseArcNeverMeetsTheLineJoinsAtTheTangentsMeeting) {
  // G42 R0.8 tip 9. Along r 10 to Z-5 (centre r 10.8), then G02 R1.2 about (10,-6.2): it
  // leaves (10,-5) going −X, a left turn by 90° (outer for G42). The arc is CW, its right
  // normal points at its centre: radius 1.2 − 0.8 = 0.4, from S = (10,-5.8) to (9.6,-6.2).
  // That circle stays 0.4 short of the line r = 10.8, so the tangents at E = (10.8,-5)
  // (along −Z) and at S (along −X) are extended instead: they meet at (10.8,-5.8), two
  // straight moves of line 4. Then r 9.6 to Z-10 and the cancel to (15,-10).
  const auto result = test::run("T0103 G99\nG00 X20 Z5\nG42 G01 Z2 F0.1\nZ-5\n"
                                "G02 X17.6 Z-6.2 R1.2\nG01 Z-10\nG40 G00 X30\nM30\n",
                                compOptions());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectPath(result.toolpath.moves, {{kRapid, 100, 200, 10, 5},
                                     {kFeed, 10, 5, 10.8, 2},
                                     {kFeed, 10.8, 2, 10.8, -5},
                                     {kFeed, 10.8, -5, 10.8, -5.8},
                                     {kFeed, 10.8, -5.8, 10, -5.8},
                                     {kCw, 10, -5.8, 9.6, -6.2, 10, -6.2},
                                     {kFeed, 9.6, -6.2, 9.6, -10},
                                     {kRapid, 9.6, -10, 15, -10}});
}

TEST(NoseCompensation, ZeroRadiusLeavesThePathAsProgrammed) {
  // Offset 4 is not defined: no shift, R 0, so G42 changes nothing.
  const auto result = test::run(
      "T0104 G99\nG00 X20 Z5\nG42 G01 Z0 F0.1\nX30 Z-5\nG40 G00 X40\nM30\n", compOptions());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectPath(result.toolpath.moves, {{kRapid, 100, 200, 10, 5},
                                     {kFeed, 10, 5, 10, 0},
                                     {kFeed, 10, 0, 15, -5},
                                     {kRapid, 15, -5, 20, -5}});
}

// With no G41/G42 anywhere the path is passed as it is, but for what compensation always does:
// the zero-length G01 Z5 (the tool is at Z5 already) is left out, the dwell stays where the
// tool stands.
TEST(NoseCompensation, WithoutAnyCompensationZeroLengthMovesAreLeftOutAndDwellsStay) {
  const auto result =
      test::run("T0101 G99\nG00 X20 Z5\nG01 Z5 F0.1\nG04 X1.\nG01 X30 Z-5\nM30\n", compOptions());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectPath(result.toolpath.moves, {{kRapid, 100, 200, 10, 5},
                                     {MoveKind::Dwell, 10, 5, 10, 5},
                                     {kFeed, 10, 5, 15, -5}});
  EXPECT_EQ(result.toolpath.moves[1].line, 4);
}

TEST(NoseCompensation, ArcInTheStartUpBlockIsAnError) {
  test::expectError(test::run("T0101 G99\nG00 X20 Z5\nG42 G02 X30 Z0 R5 F0.1\nM30\n",
                              compOptions()),
                    3, 1, "nose radius compensation (G42) cannot start in an arc block (G02)");
}

TEST(NoseCompensation, ArcInTheCancelBlockIsAnError) {
  test::expectError(
      test::run("T0101 G99\nG00 X20 Z5\nG42 G01 Z0 F0.1\nZ-5\nG40 G03 X30 Z-10 R5\nM30\n",
                compOptions()),
      5, 1, "cannot be cancelled in an arc block (G03)");
}

TEST(NoseCompensation, InnerArcSmallerThanTheNoseIsInterference) {
  // G42 along −Z then a CW fillet of radius 0.5 up to a shoulder: the centre would run on
  // radius 0.5 − 0.8 < 0.
  test::expectError(
      test::run("T0101 G99\nG00 X20 Z5\nG42 G01 Z0 F0.1\nZ-5\nG02 X21 Z-5.5 R0.5\n"
                "G01 X30\nG40 G00 X40\nM30\n",
                compOptions()),
      5, 1, "interference: this G02 arc's radius 0.5 is not larger than the nose radius 0.8");
}

TEST(NoseCompensation, GrooveNarrowerThanTheNoseIsInterference) {
  // A groove 1 mm wide under G42, R0.8: the walls' offsets are z = -5 − 0.8 (down wall at
  // Z-5) and z = -6 + 0.8 (up wall at Z-6); the bottom from Z-5 toward Z-6 would run from
  // Z-5.8 to Z-5.2, backwards.
  test::expectError(
      test::run("T0101 G99\nG00 X20 Z5\nG42 G01 Z0 F0.1\nZ-5\nX16\nZ-6\nX20\nZ-10\n"
                "G40 G00 X40\nM30\n",
                compOptions()),
      6, 1, "interference: with the nose radius 0.8 the nose-centre path of this block runs "
            "backwards");
}

TEST(NoseCompensation, InnerCornerPathsThatNeverMeetAreAnError) {
  // G42 R0.8: along r 10 to Z-5 (centre on r 10.8), then G02 R1 about (10,-4) turning right
  // to +X (inner corner). The arc's centre path has radius 1 − 0.8 = 0.2 about (10,-4): it
  // stays 0.6 mm short of the line r = 10.8, so the two never meet.
  test::expectError(
      test::run("T0101 G99\nG00 X20 Z5\nG42 G01 Z2 F0.1\nZ-5\nG02 X22 Z-4 R1\nG01 Z0\n"
                "G40 G00 X40\nM30\n",
                compOptions()),
      5, 1, "never meet at their inner corner (Fanuc alarm PS0033)");
}

TEST(NoseCompensation, ChangingSidesWithoutCancelIsAnError) {
  test::expectError(
      test::run("T0101 G99\nG00 X20 Z5\nG42 G01 Z0 F0.1\nG41 Z-5\nG40 G00 X40\nM30\n",
                compOptions()),
      4, 1, "nose radius compensation changes while it is on (G42 R0.8 tip 3 becomes G41");
}

TEST(ToolOffsets, TWordShiftsTheTipByGeometryPlusWear) {
  // Offset 5: x 0.4 (diameter), z -0.1, wear_x 0.02, wear_z 0.01: the tip lands at the
  // programmed point + ((0.4 + 0.02)/2, -0.1 + 0.01) = + (0.21, -0.09). T0105 takes effect
  // with the next move (from the unshifted start); T0100 cancels it with its own move, which
  // starts from where the shifted tool stands.
  InterpreterOptions options = compOptions();
  options.offsets[5] = ToolOffset{0.4, -0.1, 0, 0, 0.02, 0.01};
  const auto result =
      test::run("T0105 G99\nG00 X20 Z2\nG01 Z-10 F0.1\nT0100 G00 X40\nM30\n", options);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectPath(result.toolpath.moves, {{kRapid, 100, 200, 10.21, 1.91},
                                     {kFeed, 10.21, 1.91, 10.21, -10.09},
                                     {kRapid, 10.21, -10.09, 20, -10}});
}

TEST(ToolOffsets, AnUndefinedOffsetShiftsNothing) {
  const auto result = test::run("T0107 G99\nG00 X20 Z2\nG01 Z-10 F0.1\nM30\n", compOptions());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectPath(result.toolpath.moves, {{kRapid, 100, 200, 10, 2}, {kFeed, 10, 2, 10, -10}});
}

TEST(ToolOffsets, AnOffsetChangeTakingEffectOnAnArcIsAnError) {
  InterpreterOptions options = compOptions();
  options.offsets[5] = ToolOffset{0.4, 0, 0, 0, 0, 0};
  test::expectError(test::run("G99\nG00 X20 Z2\nT0105 G02 X30 Z-3 R5 F0.1\nM30\n", options), 3,
                    1, "the tool offset changes to 5 in an arc block");
}


// G71 with G42 in the ns block (GSK, lathe-cycles.md §8), R0.8 tip 3. A = (22, 2).
// Contour: N10 G00 X20 (the ns block, A → (10, 2)), a 45° taper to (15, -3), r 15 to Z-10,
// N20 out to r 22. Compensated (right normal of t = (tr, tz) is (−tz, tr)):
//   start-up: C ends perpendicular to the taper at its start: (10, 2) + 0.8(1, 1)/√2
//   taper:    C on r + z = 12 + 0.8√2; tip P = C − (0.8, 0.8) on r + z = 12 − 0.8(2 − √2)
//   r 15:     C on r = 15.8 (outer corner with the taper: extended to z = 12 + 0.8√2 − 15.8)
//   out:      C on z = -9.2 (inner corner with r 15: trimmed to (15.8, -9.2)), to r 22
// The cycle ends the compensation: the contour stops with C at (22, -9.2), P (21.2, -10).
constexpr std::string_view kG71Program =
    "T0101 G99 M03 S800\n"
    "G00 X44 Z2\n"
    "G71 U2 R0.5\n"
    "G71 P10 Q20 U0 W0 F0.2\n"
    "N10 G00 G42 X20\n"
    "G01 X30 Z-3\n"
    "Z-10\n"
    "N20 X44\n"
    "G70 P10 Q20\n"
    "M30\n";

const double kTaperTip = 12 - 0.8 * (2 - std::sqrt(2.0));  // r + z on the tip's taper line
const double kStartUpR = 10 + 0.4 * std::sqrt(2.0) - 0.8;   // B′ = (9.7657, 1.7657)
const double kStartUpZ = 2 + 0.4 * std::sqrt(2.0) - 0.8;

TEST(NoseCompensationInCycles, G71RoughsAgainstTheOffsetContour) {
  const auto result = test::run(kG71Program, compOptions());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  std::vector<Move> passEnds;     // step 3: each level's cut along Z
  std::vector<Move> semiFinish;   // step 7: along the rough contour B′ → C′
  for (const Move& m : result.toolpath.moves) {
    if (m.block != 3) continue;  // the G71 block's moves (those along the contour carry its lines)
    if (m.cycleStep == 3) passEnds.push_back(m);
    if (m.cycleStep == 7) semiFinish.push_back(m);
    EXPECT_EQ(m.noseComp.side, NoseSide::None);  // the legs are already compensated
  }
  // Levels X_k = 22 − 2k down to 10 (> B′'s 9.766). A level meets the rough contour where
  // the tip's path has its r: r 20, 18 and 16 on the last segment (z -10), r 14 and 12 on
  // the tip's taper line (z = 11.5314 − r), r 10 there too.
  ASSERT_EQ(passEnds.size(), 6u);
  const double expectedZ[] = {-10, -10, -10, kTaperTip - 14, kTaperTip - 12, kTaperTip - 10};
  for (std::size_t k = 0; k < 6; ++k) {
    SCOPED_TRACE(testing::Message() << "level " << k + 1);
    EXPECT_NEAR(passEnds[k].to.x(), 20 - 2.0 * static_cast<double>(k), 1e-9);
    EXPECT_NEAR(passEnds[k].to.y(), expectedZ[k], 1e-9);
  }
  // The semi-finishing pass (no allowance) is the compensated contour after B′.
  expectPath(semiFinish, {{kFeed, kStartUpR, kStartUpZ, 15, kTaperTip - 15},
                          {kFeed, 15, kTaperTip - 15, 15, -10},
                          {kFeed, 15, -10, 21.2, -10}});
}

TEST(NoseCompensationInCycles, G70CompensatesItsContourAndTheReturnCancels) {
  const auto result = test::run(kG71Program, compOptions());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  std::vector<Move> finishing;
  for (const Move& m : result.toolpath.moves) {
    if (m.line >= 5 && m.line <= 9 && m.block != 3) finishing.push_back(m);  // not G71's pass along them
  }
  // G70 from A: the ns block's G00 is the start-up to B′, the contour as above, then G70's
  // rapid back to A is the cancel move, from the tip (21.2, -10).
  expectPath(finishing, {{kRapid, 22, 2, kStartUpR, kStartUpZ},
                         {kFeed, kStartUpR, kStartUpZ, 15, kTaperTip - 15},
                         {kFeed, 15, kTaperTip - 15, 15, -10},
                         {kFeed, 15, -10, 21.2, -10},
                         {kRapid, 21.2, -10, 22, 2}});
}

TEST(NoseCompensationInCycles, G42BeforeG73IsSuspendedInsideItAndG70FinishesUnderIt) {
  // G42 in force before G73 and G70, none in the contour: G73 roughs as drawn (GSK: the
  // roughing cycles suspend comp), G70 finishes under it (the manuals' `G42 …; G70 P Q`), and
  // G42 is back after them. Tip 9 R0.8 (offset 3): the toolpath is the centre path.
  //   line 3 start-up (10, 5) → (10.8, 2): perpendicular to line 4 (t (0,-1), normal (1,0))
  //   line 4 r 10.8 to Z-5
  //   G73 U0 W0 R1 from A = (10, -5): d = 1 runs as two passes, both at no shift: the ns
  //   block's G00 to (10, 2) then N20 back to (10, -5), twice. Its first leg is uncompensated,
  //   so it cancels the chain: from (10.8, -5).
  //   G70 from A = (10, -5) runs N10 and N20 under G42: N10's G00 is the start-up, to C
  //   perpendicular to N20 at its start, (10.8, 2); N20 at r 10.8. Its end is A, so the rapid
  //   back to A has no length and the chain goes on, under the G42 still in force, into
  //   line 10 G01 X30 (t (1, 0), C on z = -4.2): an inner corner, both trimmed to (10.8, -4.2).
  //   No compensated move follows line 10, so C ends perpendicular to its end, (15, -4.2).
  //   line 11 G40 G00 X40: the cancel, from (15, -4.2) to (20, -5)
  const auto result = test::run(
      "T0103 G99 M03 S800\n"
      "G00 X20 Z5\n"
      "G42 G01 Z2 F0.1\n"
      "Z-5\n"
      "G73 U0 W0 R1\n"
      "G73 P10 Q20\n"
      "N10 G00 X20 Z2\n"
      "N20 G01 Z-5\n"
      "G70 P10 Q20\n"
      "G01 X30\n"
      "G40 G00 X40\n"
      "M30\n",
      compOptions());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectPath(result.toolpath.moves, {{kRapid, 100, 200, 10, 5},
                                     {kFeed, 10, 5, 10.8, 2},
                                     {kFeed, 10.8, 2, 10.8, -5},
                                     {kRapid, 10.8, -5, 10, 2},
                                     {kFeed, 10, 2, 10, -5},
                                     {kRapid, 10, -5, 10, 2},
                                     {kFeed, 10, 2, 10, -5},
                                     {kRapid, 10, -5, 10.8, 2},
                                     {kFeed, 10.8, 2, 10.8, -4.2},
                                     {kFeed, 10.8, -4.2, 15, -4.2},
                                     {kRapid, 15, -4.2, 20, -5}});
}


TEST(NoseCompensationInCycles, G90TaperIsOffsetByTheTipNumber) {
  // A = (15, 1); G90 X22 Z-5 R-3: C = (11, -5), B = (11 − 3, 1) = (8, 1), D = (15, -5).
  // The cut line 2r + z = 17, its normal toward A n = (2, 1)/√5; R0.8 tip 3, s = (-1, -1):
  // the tip's line moves by 0.8(n + s), so 2r + z grows by 0.8(2·2 + 1)/√5 − 0.8·3
  // = 0.8√5 − 2.4: 2r + z = 14.6 + 0.8√5. Keeping the cut's Z ends:
  //   B′ = ((13.6 + 0.8√5)/2, 1), C′ = ((19.6 + 0.8√5)/2, -5)
  const auto result = test::run("T0101 G99 M03 S800\nG00 X30 Z1\nG42 G90 X22 Z-5 R-3 F0.1\n"
                                "G40 G00 X40\nM30\n",
                                compOptions());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const double b = (13.6 + 0.8 * std::sqrt(5.0)) / 2;
  const double c = (19.6 + 0.8 * std::sqrt(5.0)) / 2;
  expectPath(result.toolpath.moves, {{kRapid, 100, 200, 15, 1},
                                     {kRapid, 15, 1, b, 1},
                                     {kFeed, b, 1, c, -5},
                                     {kFeed, c, -5, 15, -5},
                                     {kRapid, 15, -5, 15, 1},
                                     {kRapid, 15, 1, 20, 1}});
}

TEST(NoseCompensationInCycles, G94TaperIsOffsetByTheTipNumberAndStraightCyclesAreNot) {
  // A = (15, 2); G94 X10 Z-2 R-3: C = (5, -2), B = (15, -2 − 3) = (15, -5), D = (5, 2).
  // The cut line 3r + 10z = -5, its normal toward A (3, 10)/√109; R0.8 tip 3: 3r + 10z grows
  // by 0.8√109 − 0.8·13, to -15.4 + 0.8√109. Keeping the cut's X ends:
  //   B′ = (15, (-60.4 + 0.8√109)/10), C′ = (5, (-30.4 + 0.8√109)/10)
  // Then a straight G94 X10 Z-4 (R0 from here: a new R is given) is unchanged by tip 3.
  const auto result = test::run("T0101 G99 M03 S800\nG00 X30 Z2\nG42 G94 X10 Z-2 R-3 F0.1\n"
                                "X10 Z-4 R0\nG40 G00 X40\nM30\n",
                                compOptions());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const double b = (-60.4 + 0.8 * std::sqrt(109.0)) / 10;
  const double c = (-30.4 + 0.8 * std::sqrt(109.0)) / 10;
  expectPath(result.toolpath.moves, {{kRapid, 100, 200, 15, 2},
                                     {kRapid, 15, 2, 15, b},
                                     {kFeed, 15, b, 5, c},
                                     {kFeed, 5, c, 5, 2},
                                     {kRapid, 5, 2, 15, 2},
                                     {kRapid, 15, 2, 15, -4},
                                     {kFeed, 15, -4, 5, -4},
                                     {kFeed, 5, -4, 5, 2},
                                     {kRapid, 5, 2, 15, 2},
                                     {kRapid, 15, 2, 20, 2}});
}

// G28 under G42: the compensation is suspended at the intermediate point, as on the control
// (lathe-cycles.md §10), not the corner into G28's first leg trimmed as if it were a cut. R0.8 tip
// 3. Start-up N3 (0,5)→(0,0): the centre ends perpendicular to the face, (0, 0.8). N4 faces to
// r 8: the last compensated move, its centre ending at (8, 0.8), the tip at (7.2, 0). G28 U10
// W5 is the cancel move: from there to the intermediate point (8 + 5, 0 + 5) = (13, 5), then
// to the reference (100, 200), uncompensated. Nothing past the face's end is cut.
TEST(NoseCompensation, G28EndsTheChainAtItsIntermediatePoint) {
  const auto result = test::run("N1 G99 M03 S800 T0101\nN2 G00 X0 Z5\nN3 G42 G01 Z0 F0.1\nN4 X16\nN5 G28 U10 W5\n",
                                compOptions());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectPath(result.toolpath.moves, {{kRapid, 100, 200, 0, 5},
                                     {kFeed, 0, 5, -0.8, 0},
                                     {kFeed, -0.8, 0, 7.2, 0},
                                     {kRapid, 7.2, 0, 13, 5},
                                     {kRapid, 13, 5, 100, 200}});
  EXPECT_EQ(result.toolpath.moves[3].noseComp.side, NoseSide::None);
}

// After G28 the GSK980TDi forgets the tool offset (No.182#2 = 0, §3.15 note 4); fanuc-0i-t keeps
// it (the 0i-TC manual B-64114EN §14.1.6: G28 does not cancel the offset vector). On both the
// axes that return reach the reference point itself, a position of the machine: the vector is not
// in force in the G28 block. Offset 5 shifts the tip by x 0.4 (diameter), +0.2 of radius, and z
// -0.3. The tool goes to X20 Z2 under the offset, (10.2, 1.7); G28 U0 W0 has no intermediate leg
// and ends at the reference (100, 200) exactly; the next G00 X20 Z2 ends at (10, 2) on the GSK,
// (10.2, 1.7) on the Fanuc.
TEST(ToolOffsets, G28CancelsTheOffsetWhereThePresetSays) {
  for (const auto& [after, shift] :
       {std::pair{OffsetAfterReturn::Cancelled, RZ(0, 0)}, {OffsetAfterReturn::Kept, RZ(0.2, -0.3)}}) {
    InterpreterOptions options = compOptions();
    options.offsets[5] = ToolOffset{0.4, -0.3, 0, 0, 0, 0};
    options.control.offsetAfterReturn = after;
    const auto result = test::run("T0105 G99\nG00 X20 Z2\nG28 U0 W0\nG00 X20 Z2\n", options);
    ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
    expectPath(result.toolpath.moves, {{kRapid, 100, 200, 10.2, 1.7},
                                       {kRapid, 10.2, 1.7, 100, 200},
                                       {kRapid, 100, 200, 10 + shift.x(), 2 + shift.y()}});
    EXPECT_EQ(result.toolpath.moves[2].toolOffset, after == OffsetAfterReturn::Kept ? 5 : 0);
  }
}

// G28 with one axis: only that axis reaches the reference without the offset; the other does not
// move and keeps it. G28 W5 from (10.2, 1.7) (program (10, 2)): to the intermediate point, program
// Z7 under the offset (10.2, 6.7), then Z to the reference Z200 exactly, X staying at 10.2.
TEST(ToolOffsets, G28LeavesTheOffsetOfAnAxisItDoesNotReturn) {
  InterpreterOptions options = compOptions();
  options.offsets[5] = ToolOffset{0.4, -0.3, 0, 0, 0, 0};
  const auto result = test::run("T0105 G99\nG00 X20 Z2\nG28 W5\n", options);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectPath(result.toolpath.moves,
             {{kRapid, 100, 200, 10.2, 1.7}, {kRapid, 10.2, 1.7, 10.2, 6.7}, {kRapid, 10.2, 6.7, 10.2, 200}});
}

}  // namespace
}  // namespace lathesim::interp
