// Chamfers and corner radii between two G01 cuts (GSK980TDi §3.11: L, D; Fanuc ,C ,R). The
// corner here: a face cut out to X30 (r 15) at Z0, then the turn along Z to Z-10, so the
// corner P = (r 15, Z0), u1 = (−1, 0) back along the face, u2 = (0, −1) along the turn, φ = 90°.

#include "interp/motion/corners.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../test_support.hpp"
#include "interp/control/control_preset.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;
using test::expectMoves;
using test::kFeed;
using test::kRapid;

InterpretResult runUnder(std::string_view preset, std::string_view cornerBlock, ChamferSize size = ChamferSize::Length) {
  InterpreterOptions options = test::defaultOptions();
  options.control = controlPreset(preset)->parameters;
  options.control.rapidPath = RapidPath::Linear;
  options.control.chamferSize = size;
  return interpret("G99 G00 X20. Z0.\nG01 " + std::string(cornerBlock) + " F0.1\nG01 Z-10.\n", "t.nc", options);
}

const double kRoot2 = std::sqrt(2.0);

TEST(Corners, GskChamferLIsTheChamfersOwnLength) {
  // No.181#0 = 0: L2 is the chamfer's length: d = 2 / |u1 − u2| = 2/√2 = √2 from the corner.
  const auto result = runUnder("gsk980tdi", "X30. L2.");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 10, 0, 0, 0},
                                      {kFeed, 10, 0, 15 - kRoot2, 0, 0.1, 0},
                                      {kFeed, 15 - kRoot2, 0, 15, -kRoot2, 0.1, 0},
                                      {kFeed, 15, -kRoot2, 15, -10, 0.1, 0}});
  EXPECT_EQ(result.toolpath.moves[2].line, 2);  // the chamfer is the asking block's
  // No.181#0 = 1: L2 is the distance from the corner.
  const auto fromCorner = runUnder("gsk980tdi", "X30. L2.", ChamferSize::FromCorner);
  ASSERT_TRUE(fromCorner.ok());
  EXPECT_EQ(fromCorner.toolpath.moves[2].from, RZ(13, 0));
  EXPECT_EQ(fromCorner.toolpath.moves[2].to, RZ(15, -2));
}

TEST(Corners, FanucCommaCIsTheDistanceFromTheCorner) {
  const auto result = runUnder("fanuc-0i-t", "X30. ,C2.");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves({result.toolpath.moves.begin() + 1, result.toolpath.moves.end()},
              {{kFeed, 10, 0, 13, 0, 0.1, 0}, {kFeed, 13, 0, 15, -2, 0.1, 0}, {kFeed, 15, -2, 15, -10, 0.1, 0}});
}

TEST(Corners, ACornerRadiusIsTangentToBothLines) {
  // D2 at 90°: tangent points d = R / tan 45° = 2 from P, centre P + (R / sin 45°)·(u1 + u2)/√2 =
  // (13, -2); the path turns left (up the face, then toward the chuck): counter-clockwise.
  for (const auto& [preset, word] : {std::pair{"gsk980tdi", "D2."}, {"fanuc-0i-t", ",R2."}}) {
    SCOPED_TRACE(preset);
    const auto result = runUnder(preset, std::string("X30. ") + word);
    ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
    const auto& moves = result.toolpath.moves;
    ASSERT_EQ(moves.size(), 4u);
    EXPECT_EQ(moves[1].to, RZ(13, 0));
    EXPECT_EQ(moves[2].kind, MoveKind::ArcCCW);
    EXPECT_NEAR((moves[2].from - RZ(13, 0)).norm(), 0, 1e-12);
    EXPECT_NEAR((moves[2].to - RZ(15, -2)).norm(), 0, 1e-12);
    EXPECT_NEAR((moves[2].center - RZ(13, -2)).norm(), 0, 1e-12);
    EXPECT_EQ(moves[3].from, moves[2].to);
  }
}

// A sweep of corners: up the face to P = (r 15, Z0), then 10 mm on at every angle b from +Z
// (b = 90° would be in line, 270° straight back). By the rule, with u1 and u2 the unit vectors
// from P back along the face and on along the second line: the chamfer or the arc runs from
// P + d·u1 to P + d·u2, d the size for ,C (from the corner); for GSK L the chamfer's own length
// is the size; a corner radius R is tangent to both lines (its centre R from each tangent point,
// square to the line there) and turns left (counter-clockwise) when the second line heads
// toward the chuck (cos b < 0).
TEST(Corners, ASweepOfAnglesMakesEachCornerByTheRule) {
  const double pi = std::acos(-1.0);
  for (const int degrees : {-60, -20, 0, 30, 60, 75, 105, 120, 150, 180, 210, 240}) {
    const double b = degrees * pi / 180.0;
    const std::string secondLine =
        "G01 X" + std::to_string(2 * (15 + 10 * std::sin(b))) + " Z" + std::to_string(10 * std::cos(b)) + "\n";
    for (const auto& [preset, word, kind] : {std::tuple{"gsk980tdi", "L1.", "length"},
                                             {"gsk980tdi", "D1.", "radius"},
                                             {"fanuc-0i-t", ",C1.", "from corner"},
                                             {"fanuc-0i-t", ",R1.", "radius"}}) {
      SCOPED_TRACE(testing::Message() << degrees << "° " << preset << " " << word);
      InterpreterOptions options = test::defaultOptions();
      options.control = controlPreset(preset)->parameters;
      options.control.rapidPath = RapidPath::Linear;
      const auto result = interpret("G99 G00 X20. Z0.\nG01 X30. " + std::string(word) + " F0.1\n" + secondLine,
                                    "t.nc", options);
      ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
      const auto& moves = result.toolpath.moves;
      ASSERT_EQ(moves.size(), 4u);
      const RZ p(15, 0);
      const RZ u1(-1, 0);
      const RZ u2 = (moves[3].to - p).normalized();
      const RZ a = moves[2].from;
      const RZ c = moves[2].to;
      EXPECT_EQ(moves[1].to, a);
      EXPECT_EQ(moves[3].from, c);
      const double d = (a - p).norm();
      EXPECT_NEAR((a - (p + d * u1)).norm(), 0, 1e-9);  // on the face
      EXPECT_NEAR((c - (p + d * u2)).norm(), 0, 1e-9);  // on the second line, as far from P
      if (std::string(kind) == "from corner") {
        EXPECT_NEAR(d, 1, 1e-9);
      }
      if (std::string(kind) == "length") {
        EXPECT_NEAR((c - a).norm(), 1, 1e-9);
      }
      if (std::string(kind) != "radius") {
        EXPECT_EQ(moves[2].kind, MoveKind::Feed);
        continue;
      }
      const RZ o = moves[2].center;
      EXPECT_NEAR((a - o).norm(), 1, 1e-9);
      EXPECT_NEAR((c - o).norm(), 1, 1e-9);
      EXPECT_NEAR((a - o).dot(u1), 0, 1e-9);
      EXPECT_NEAR((c - o).dot(u2), 0, 1e-9);
      EXPECT_EQ(moves[2].kind, std::cos(b) < 0 ? MoveKind::ArcCCW : MoveKind::ArcCW);
    }
  }
}

TEST(Corners, WhatTheCornerCannotBeIsNamed) {
  // Too long for the face's 5 mm (GSK §3.11.3); before a rapid; after the program's last move.
  expectError(runUnder("gsk980tdi", "X30. D8."), 2, 10,
              "D8. does not fit: it needs 8 mm of each line from the corner, and the lines are 5 and 10 mm long");
  InterpreterOptions options = test::defaultOptions();
  expectError(interpret("G99 G00 X20. Z0.\nG01 X30. L1. F0.1\nG00 Z5.\n", "t.nc", options), 2, 10,
              "L1.: the chamfer is made between two G01 cuts; next to a rapid");
  expectError(interpret("G99 G00 X20. Z0.\nG01 X30. L1. F0.1\n", "t.nc", options), 2, 10,
              "L1. asks for a chamfer to the next move, but no move follows");
  expectError(interpret("G99 G00 X20. Z0.\nG01 X30. L1. D1. F0.1\n", "t.nc", options), 2, 14,
              "L1. and D1. both ask for a corner");
}

TEST(Corners, AContoursChamferIsRoughedAndFinished) {
  // G70 runs the contour with its chamfer (the N20 → N30 corner, 1 from it along each line
  // under from_corner); G71 roughs against the same chamfered contour.
  InterpreterOptions options = test::defaultOptions();
  options.control.chamferSize = ChamferSize::FromCorner;
  const auto result = interpret(
      "G00 X40. Z2.\nG71 U1. R1.\nG71 P10 Q30 F0.2\nN10 G00 X20.\nN20 G01 X30. Z0. L1.\nN30 Z-10.\nN40 X40.\nG70 P10 Q30\n",
      "t.nc", options);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  // N20 goes from (10, 2) to (15, 0): u1 = (−5, 2)/√29; the chamfer starts √29 − 1 along it.
  const RZ u1 = RZ(-5, 2) / std::sqrt(29.0);
  bool finished = false;
  for (std::size_t i = 0; i + 1 < result.toolpath.moves.size(); ++i) {
    const Move& m = result.toolpath.moves[i];
    if (m.line != 5 || m.block == 2 || (m.to - (RZ(15, 0) + u1)).norm() > 1e-9) continue;  // G70's, not G71's
    EXPECT_NEAR((result.toolpath.moves[i + 1].to - RZ(15, -1)).norm(), 0, 1e-9);
    finished = true;
  }
  EXPECT_TRUE(finished);
  // G71's semi-finishing pass (step 7, no allowance) follows the same chamfer.
  const auto chamfer = std::find_if(result.toolpath.moves.begin(), result.toolpath.moves.end(), [&](const Move& m) {
    return m.block == 2 && m.cycleStep == 7 && (m.from - (RZ(15, 0) + u1)).norm() < 1e-9;
  });
  ASSERT_NE(chamfer, result.toolpath.moves.end());
  EXPECT_NEAR((chamfer->to - RZ(15, -1)).norm(), 0, 1e-9);
}

}  // namespace
}  // namespace lathesim::interp
