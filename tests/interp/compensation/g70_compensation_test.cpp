// G41/G42 given before G70, the manuals' form (`G00 G42 X42. Z2.` then `G70 P Q`), under the
// gsk980tdi and fanuc-0i-t presets: the finish is the compensated contour, expanded here by
// hand for every nose radius and tip number swept.
//
// Drawn contour (radius, Z), from A = (21, 2):
//   N100 G00 X14        approach  (21, 2) → (7, 2)       t = (−1, 0)
//   N110 G01 X20 Z-1    chamfer   (7, 2) → (10, −1)      t = (1, −1)/√2, 45°
//   N120 Z-10           diameter  (10, −1) → (10, −10)   t = (0, −1)
//   N130 G02 X30 Z-15 R5  fillet  → (15, −15), CW about (15, −10) (concave)
//   N140 G01 X42        shoulder  (15, −15) → (21, −15)  t = (1, 0)
// G42: the nose centre C lies right of the travel, the right normal of t = (tr, tz) being
// (−tz, tr). With nose radius R:
//   approach  C on z = 2 − R
//   chamfer   C on r + z = 9 + R√2 (normal (1, 1)/√2)
//   diameter  C on r = 10 + R
//   fillet    C on the circle about (15, −10) of radius 5 − R (the normal points at the centre)
//   shoulder  C on z = −15 + R
// Corners: approach→chamfer turns right (inner for G42): trimmed to their meeting point
// (7 + R(1 + √2), 2 − R). Chamfer→diameter turns left by 45° (outer, ≤ 90°): both extended to
// (10 + R, −1 + R(√2 − 1)). Diameter→fillet→shoulder are tangent.
// Start-up (the G42 block): C ends perpendicular to the approach at its start, (21, 2 − R).
// The G70's rapid back to A cancels: from C (21, −15 + R) to A as programmed.
// The toolpath carries the imaginary tip P = C + R·s, s the tip's direction (tip 1 (+X, +Z),
// 2 (+X, −Z), 3 (−X, −Z), 4 (−X, +Z), 5 +Z, 6 +X, 7 −Z, 8 −X, 0/9 none: lathe-cycles.md §8).

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

// The contour is roughed by G71 first (a G70 must follow its contour, GSK980TDi §3.23.4 note
// 1); then the tool goes away and comes back to A under G42 for the finish.
constexpr std::string_view kProgram =  // decimal points: fanuc-0i-t reads X14 as 0.014 mm
    "T0101 G99 M03 S800\n"              // 1
    "G00 X42. Z2.\n"                    // 2
    "G71 U1.5 R0.5\n"                   // 3
    "G71 P100 Q140 U0 W0 F0.2\n"        // 4
    "N100 G00 X14.\n"                   // 5
    "N110 G01 X20. Z-1. F0.1\n"         // 6
    "N120 Z-10.\n"                      // 7
    "N130 G02 X30. Z-15. R5.\n"         // 8
    "N140 G01 X42.\n"                   // 9
    "G00 X60. Z20.\n"                   // 10
    "G00 G42 X42. Z2.\n"                // 11 start-up
    "G70 P100 Q140\n"                   // 12
    "G40 G00 X60. Z20.\n"               // 13 (the chain already ended at A)
    "M30\n";
constexpr int kStartUpLine = 11;

struct CompensatedMove {
  MoveKind kind;
  double r0, z0, r1, z1;
  double rc = 0, zc = 0;
};

// The tip's direction for tip numbers 0–9, from the table in lathe-cycles.md §8.
void tipDirection(int tip, double& sr, double& sz) {
  const double table[10][2] = {{0, 0},  {1, 1},  {1, -1}, {-1, -1}, {-1, 1},
                               {0, 1},  {1, 0},  {0, -1}, {-1, 0},  {0, 0}};
  sr = table[tip][0];
  sz = table[tip][1];
}

// The hand expansion above for nose radius `r` and tip `tip`, from the start-up on.
std::vector<CompensatedMove> handExpanded(double r, int tip) {
  double sr = 0, sz = 0;
  tipDirection(tip, sr, sz);
  const double k = std::sqrt(2.0);
  const double pr = r * sr, pz = r * sz;  // P − C
  const double rCorner1 = 7 + r * (1 + k), zCorner1 = 2 - r;
  const double rCorner2 = 10 + r, zCorner2 = -1 + r * (k - 1);
  return {
      {MoveKind::Rapid, 30, 20, 21 + pr, 2 - r + pz},                       // line 11, the start-up
      {MoveKind::Rapid, 21 + pr, 2 - r + pz, rCorner1 + pr, zCorner1 + pz},  // N100
      {MoveKind::Feed, rCorner1 + pr, zCorner1 + pz, rCorner2 + pr, zCorner2 + pz},  // N110
      {MoveKind::Feed, rCorner2 + pr, zCorner2 + pz, 10 + r + pr, -10 + pz},         // N120
      {MoveKind::ArcCW, 10 + r + pr, -10 + pz, 15 + pr, -15 + r + pz, 15 + pr, -10 + pz},  // N130
      {MoveKind::Feed, 15 + pr, -15 + r + pz, 21 + pr, -15 + r + pz},      // N140
      {MoveKind::Rapid, 21 + pr, -15 + r + pz, 21, 2},                     // G70's return: cancel
      {MoveKind::Rapid, 21, 2, 30, 20},                                    // line 13
  };
}

void expectCompensatedMoves(const std::vector<Move>& moves, const std::vector<CompensatedMove>& expected) {
  ASSERT_EQ(moves.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE(testing::Message() << "move " << i << " (line " << moves[i].line << ")");
    const Move& m = moves[i];
    const CompensatedMove& e = expected[i];
    EXPECT_EQ(m.kind, e.kind);
    EXPECT_NEAR(m.from.x(), e.r0, 1e-9);
    EXPECT_NEAR(m.from.y(), e.z0, 1e-9);
    EXPECT_NEAR(m.to.x(), e.r1, 1e-9);
    EXPECT_NEAR(m.to.y(), e.z1, 1e-9);
    if (isArc(e.kind)) {
      EXPECT_NEAR(m.center.x(), e.rc, 1e-9);
      EXPECT_NEAR(m.center.y(), e.zc, 1e-9);
    }
  }
}

// The moves from the G42 block on.
std::vector<Move> fromStartUp(const std::vector<Move>& moves) {
  auto first = moves.begin();
  while (first != moves.end() && first->line != kStartUpLine) ++first;
  return std::vector<Move>(first, moves.end());
}

InterpreterOptions withOffset(std::string_view preset, double radiusMm, int tip) {
  InterpreterOptions options = test::under(preset);
  options.control.powerOnFeedMode = FeedMode::PerRevolution;
  options.offsets[1] = ToolOffset{0, 0, radiusMm, tip, 0, 0};
  return options;
}

class G70UnderG42 : public testing::TestWithParam<std::string> {};

TEST_P(G70UnderG42, FinishesTheCompensatedContourForEveryRadiusAndTip) {
  for (const double radiusMm : {0.2, 0.4, 0.8, 1.2}) {
    for (int tip = 0; tip <= 9; ++tip) {
      SCOPED_TRACE(testing::Message() << GetParam() << " R" << radiusMm << " tip " << tip);
      const auto result = test::run(kProgram, withOffset(GetParam(), radiusMm, tip));
      ASSERT_TRUE(result.ok()) << test::messageOf(result);
      expectCompensatedMoves(fromStartUp(result.toolpath.moves), handExpanded(radiusMm, tip));
    }
  }
}

TEST_P(G70UnderG42, TheChamferIsFinishedToTheDrawingByATip3Tool) {
  // At R0.8 tip 3 the tip's chamfer line is r + z = 9 + 0.8√2 − 1.6 = 9 − 0.8(2 − √2): the nose
  // circle, centred 0.8√2 out along the normal, touches the drawn line r + z = 9.
  const auto result = test::run(kProgram, withOffset(GetParam(), 0.8, 3));
  ASSERT_TRUE(result.ok()) << test::messageOf(result);
  const Move chamfer = fromStartUp(result.toolpath.moves)[2];  // a copy: the vector is a temporary
  ASSERT_EQ(chamfer.line, 6);
  EXPECT_NEAR(chamfer.to.x() + chamfer.to.y(), 9 - 0.8 * (2 - std::sqrt(2.0)), 1e-12);
  EXPECT_EQ(chamfer.noseComp.side, NoseSide::Right);
  for (const auto& d : test::warningsOf(result)) {
    EXPECT_EQ(d.message.find("nose radius"), std::string::npos) << d.message;
  }
}

INSTANTIATE_TEST_SUITE_P(Presets, G70UnderG42, testing::Values("gsk980tdi", "fanuc-0i-t"));

}  // namespace
}  // namespace lathesim::interp
