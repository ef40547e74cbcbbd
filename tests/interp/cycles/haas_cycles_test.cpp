// Haas's one-block compound cycles (haas dialect and preset), expanded by hand from the Haas
// manual's rules as lathesim reads them (compound_cycle.cpp haasRoughing, haas_g76.cpp):
//   G71 P Q U W D I K F: levels D apart rough against the contour shifted by (U/2 + I, W + K),
//   retract by Setting 73 (1.27 mm) at rapid, the closing pass along the contour shifted by
//   (U/2, W), rapid back to the start.
//   G76 X Z K D A F [P]: the passes of the two-block G76 at the depths D·√n (P1) or n·D (P3).

#include <gtest/gtest.h>

#include <cmath>

#include "../test_support.hpp"
#include "interp/control/control_preset.hpp"
#include "interp/cycles/haas_g76.hpp"
#include "interp/motion/cycle_time.hpp"

namespace lathesim::interp {
namespace {

using test::Expected;
using test::expectError;
using test::ExpectedThread;
using test::expectMoves;
using test::expectSameMoves;
using test::expectThreadMoves;
using test::haas;
using test::kFeed;
using test::kRapid;
using test::kThread;
using test::run;


// A = X52 Z2 (radius 26). Contour: N10 G00 X30. (B = (15, 2)), Z-20., a taper to X50. Z-30.,
// N20 Z-40. U0.5 W0.1 (0.25, 0.1) and I0.3 K0.2: the levels' contour is shifted (0.55, 0.3):
// A′ = (26.55, 2.3), B′ = (15.55, 2.3), (15.55, −19.7), (25.55, −29.7), (25.55, −39.7).
// Levels D2 apart from A′ toward B′ while short of its 11 mm: X = 24.55 … 16.55 (five); each
// meets the taper x = 15.55 + (−19.7 − z) at z = −19.7 − (X − 15.55). Retract e = 1.27 (Setting
// 73) at rapid (+X, +Z), rapid back to Z2.3. Then rapid (the ns block is G00) to B″ = B +
// (0.25, 0.1) = (15.25, 2.1), feed along the contour shifted by (0.25, 0.1), rapid back to A.
TEST(HaasG71, RoughAllowanceIAndKLeftByTheLevelsOnly) {
  const auto result = run("G00 X52. Z2.\n"
                          "G71 P10 Q20 U0.5 W0.1 D2. I0.3 K0.2 F0.25\n"
                          "N10 G00 X30.\n"
                          "G01 Z-20.\n"
                          "X50. Z-30.\n"
                          "N20 Z-40.\n"
                          "M30\n",
                          haas());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  std::vector<Expected> expected{{kRapid, 100, 200, 26, 2, 0, 0}, {kRapid, 26, 2, 26.55, 2.3, 0, 1}};
  double x = 26.55;
  double z = 2.3;
  for (int k = 1; k <= 5; ++k) {
    const double level = 26.55 - 2.0 * k;
    const double end = -19.7 - (level - 15.55);
    expected.push_back({kRapid, x, z, level, 2.3, 0, k == 1 ? 2 : 6});
    expected.push_back({kFeed, level, 2.3, level, end, 0.25, 3});
    expected.push_back({kRapid, level, end, level + 1.27, end + 1.27, 0, 4});
    expected.push_back({kRapid, level + 1.27, end + 1.27, level + 1.27, 2.3, 0, 5});
    x = level + 1.27;
  }
  expected.push_back({kRapid, x, 2.3, 15.25, 2.1, 0, 6});
  expected.push_back({kFeed, 15.25, 2.1, 15.25, -19.9, 0.25, 7});
  expected.push_back({kFeed, 15.25, -19.9, 25.25, -29.9, 0.25, 7});
  expected.push_back({kFeed, 25.25, -29.9, 25.25, -39.9, 0.25, 7});
  expected.push_back({kRapid, 25.25, -39.9, 26, 2, 0, 8});
  expectMoves(result.toolpath.moves, expected);
}

// The same contour without I/K is Fanuc's G71 with D for Δd: the levels and the closing pass
// share the contour shifted by (U/2, W). A boring contour (negative U) steps away from the axis.
// Swept over depths that divide the 11 mm and that do not, OD and ID.
TEST(HaasG71, WithoutIKMatchesTheFanucTwoBlockForm) {
  for (const char* depth : {"1.", "2.", "2.75", "3.3", "11.", "12."}) {
    for (const bool bore : {false, true}) {
      SCOPED_TRACE(testing::Message() << "D" << depth << (bore ? " bore" : " turn"));
      const std::string start = bore ? "G00 X8. Z2.\n" : "G00 X52. Z2.\n";
      const std::string contour = bore ? "N10 G00 X30.\nG01 Z-20.\nX10. Z-30.\nN20 Z-40.\n"
                                       : "N10 G00 X30.\nG01 Z-20.\nX50. Z-30.\nN20 Z-40.\n";
      const char* allowance = bore ? "U-0.5 W0.1" : "U0.5 W0.1";
      const auto haasRun = run(start + "G71 P10 Q20 " + allowance + " D" + depth + " F0.25\n" + contour + "M30\n", haas());
      const auto fanucRun = run(start + "G71 U" + depth + " R1.27\nG71 P10 Q20 " + allowance + " F0.25\n" + contour +
                                    "M30\n",
                                test::under("haas", Dialect::FanucA));
      ASSERT_TRUE(haasRun.ok()) << haasRun.diagnostics[0].message;
      ASSERT_TRUE(fanucRun.ok()) << fanucRun.diagnostics[0].message;
      expectSameMoves(haasRun.toolpath.moves, fanucRun.toolpath.moves);
    }
  }
}

// I and K with signs: a boring contour leaves its rough allowance toward the axis (I < 0); the
// levels never cross the contour shifted by (U/2 + I, W + K), the closing pass lies on the one
// shifted by (U/2, W). Checked on every move: no level reaches past the rough contour.
TEST(HaasG71, LevelsStopAtTheRoughAllowanceForEverySign) {
  for (const double i : {-0.4, 0.0, 0.4}) {
    for (const double k : {-0.2, 0.0, 0.2}) {
      SCOPED_TRACE(testing::Message() << "I" << i << " K" << k);
      const bool bore = i < 0;
      const std::string program = std::string(bore ? "G00 X8. Z2.\n" : "G00 X52. Z2.\n") +
                                  "G71 P10 Q20 U" + (bore ? "-0.5" : "0.5") + " W0.1 D1.5 I" + std::to_string(i) +
                                  " K" + std::to_string(k) + " F0.2\nN10 G00 X30.\nN20 G01 Z-20.\nM30\n";
      const auto result = run(program, haas());
      ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
      const double finishRadius = 15.0 + (bore ? -0.25 : 0.25);
      const double roughRadius = finishRadius + i;
      for (const Move& m : result.toolpath.moves) {
        if (m.cycleStep == 3) {  // a level's cut stays on the material's side of the rough contour
          EXPECT_GE(bore ? roughRadius - m.to.x() : m.to.x() - roughRadius, -1e-9);
        }
        if (m.cycleStep == 7) {
          EXPECT_NEAR(m.to.x(), finishRadius, 1e-9);
        }
      }
    }
  }
}

TEST(HaasG71, BadForms) {
  expectError(run("G00 X52. Z2.\nG71 U2. R1.\n", haas()), 2, 1, "Haas form is one block");
  expectError(run("G00 X52. Z2.\nG71 P10 Q20 D0 F0.2\nN10 G00 X30.\nN20 G01 Z-20.\n", haas()), 2, 13,
              "not a depth of cut D");
  expectError(run("G00 X52. Z2.\nG71 P10 Q20 D1. R1 F0.2\nN10 G00 X30.\nN20 G01 Z-20.\n", haas()), 2, 17,
              "YASNAC");
}

// Where a Haas contour may go (its operator's manual, "Type 2 details"): only the Q block may
// pass the start point in the step axis (a short retraction at the end of the contour), and it
// is roughed as any block: N20 X55. beyond the start's X52. ends the closing pass at C′ =
// (27.5 + 0.25, −30 + 0.1); a block before Q passing the start is refused at its line. G72's
// Q block Z3. beyond Z2. likewise. A type I contour with a pocket (X26. after X30.) is roughed
// under haas (haas_troughs_test.cpp) and is still the Fanuc's alarm under fanuc-a.
TEST(HaasG71, OnlyTheQBlockMayPassTheStartPointAndTypeIPocketsAreRoughed) {
  const std::string start = "G00 X52. Z2.\nG71 P10 Q20 U0.5 W0.1 D2. F0.25\nN10 G00 X30.\nG01 Z-20.\nX50. Z-30.\n";
  const auto pastStart = run(start + "N20 X55.\n", haas());
  ASSERT_TRUE(pastStart.ok()) << pastStart.diagnostics[0].message;
  EXPECT_NEAR(pastStart.toolpath.moves.back().from.x(), 27.75, 1e-12);
  EXPECT_NEAR(pastStart.toolpath.moves.back().from.y(), -29.9, 1e-12);
  expectError(run(start + "X55.\nN20 Z-35.\n", haas()), 6, 1,
              "goes past the start point before its last block (X55 beyond the start's X52)");
  const auto facing = run("G00 X52. Z2.\nG72 P10 Q20 W0.2 D4. F0.2\nN10 G00 Z-10.\nG01 X20.\nN20 Z3.\n", haas());
  ASSERT_TRUE(facing.ok()) << facing.diagnostics[0].message;
  EXPECT_NEAR(facing.toolpath.moves.back().from.y(), 3.2, 1e-12);
  const std::string pocket = "N10 G00 X20.\nG01 Z-10.\nX30. Z-15.\nX26. Z-20.\nN20 X50. Z-30.\n";
  const auto haasPocket = run("G00 X52. Z2.\nG71 P10 Q20 U0.5 D2. F0.25\n" + pocket, haas());
  ASSERT_TRUE(haasPocket.ok()) << haasPocket.diagnostics[0].message;
  expectError(run("G00 X52. Z2.\nG71 U2. R1.\nG71 P10 Q20 U0.5 F0.25\n" + pocket, test::under("haas", Dialect::FanucA)),
              7, 1, "type I contour must be monotonic");
}

// G72 with K: the rough allowance along Z is on the face's side; levels step in Z.
// A = X52 Z2; contour N10 G00 Z-10. (B = (26, −10)), G01 X20., N20 Z0. W0.2 K0.3 D4.:
// levels shifted (0, 0.5): A′ = (26, 2.5), B′ = (26, −9.5). Levels every 4 from Z2.5 toward
// −9.5 while short of 12: Z −1.5, −5.5 (−9.5 is the last depth: left to the closing pass);
// each runs in −X to the rough contour's X = 10 (radius 10), retract +1.27 both, rapid back to
// X26 (radius). Closing pass: rapid to (26, −9.8), feed (10, −9.8), (10, 0.2), rapid A.
TEST(HaasG72, FaceRoughingWithK) {
  const auto result = run("G00 X52. Z2.\n"
                          "G72 P10 Q20 W0.2 D4. K0.3 F0.2\n"
                          "N10 G00 Z-10.\n"
                          "G01 X20.\n"
                          "N20 Z0.\n"
                          "M30\n",
                          haas());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  std::vector<Expected> expected{{kRapid, 100, 200, 26, 2, 0, 0}, {kRapid, 26, 2, 26, 2.5, 0, 1}};
  double z = 2.5;
  for (int k = 1; k <= 2; ++k) {
    const double level = 2.5 - 4.0 * k;
    expected.push_back({kRapid, 26, z, 26, level, 0, k == 1 ? 2 : 6});
    expected.push_back({kFeed, 26, level, 10, level, 0.2, 3});
    expected.push_back({kRapid, 10, level, 11.27, level + 1.27, 0, 4});
    expected.push_back({kRapid, 11.27, level + 1.27, 26, level + 1.27, 0, 5});
    z = level + 1.27;
  }
  expected.push_back({kRapid, 26, z, 26, -9.8, 0, 6});
  expected.push_back({kFeed, 26, -9.8, 10, -9.8, 0.2, 7});
  expected.push_back({kFeed, 10, -9.8, 10, 0.2, 0.2, 7});
  expected.push_back({kRapid, 10, 0.2, 26, 2, 0, 8});
  expectMoves(result.toolpath.moves, expected);
}

// G75 with Haas's I (X peck, a radius) and K (Z shift), lengths with a point. A = X42 Z-10
// (radius 21), G75 X30. Z-14. I2. K2. F0.1, back-off e 0.5 (the preset's g74_retract): at each
// of Z-10, -12, -14: feed 21 → 19, rapid back to 19.5, feed to 17, back to 17.5, feed to 15;
// rapid out to 21; rapid 2 along Z to the next plunge; after the last, rapid back to A.
TEST(HaasG75, PecksInIAndShiftsInK) {
  const auto result = run("G00 X42. Z-10.\nG75 X30. Z-14. I2. K2. F0.1\n", haas());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  std::vector<Expected> expected{{kRapid, 100, 200, 21, -10, 0, 0}};
  for (int j = 0; j < 3; ++j) {
    const double z = -10.0 - 2.0 * j;
    expected.push_back({kFeed, 21, z, 19, z, 0.1, 1});
    expected.push_back({kRapid, 19, z, 19.5, z, 0, 2});
    expected.push_back({kFeed, 19.5, z, 17, z, 0.1, 1});
    expected.push_back({kRapid, 17, z, 17.5, z, 0, 2});
    expected.push_back({kFeed, 17.5, z, 15, z, 0.1, 1});
    expected.push_back({kRapid, 15, z, 21, z, 0, 4});
    if (j < 2) expected.push_back({kRapid, 21, z, 21, z - 2.0, 0, 5});
  }
  expected.push_back({kRapid, 21, -14, 21, -10, 0, 6});
  expectMoves(result.toolpath.moves, expected);
  expectError(run("G00 X42. Z-10.\nG75 X30. Z-14. K2. F0.1\n", haas()), 2, 1, "I(Δi) > 0");
}

TEST(HaasPassDepths, SquareRootConstantDepthAndMinimumCut) {
  const auto expectDepths = [](const std::optional<std::vector<double>>& depths, const std::vector<double>& expected) {
    ASSERT_TRUE(depths);
    ASSERT_EQ(depths->size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR((*depths)[i], expected[i], 1e-12) << i;
  };
  expectDepths(haasPassDepths(false, 0.75, 0.0254, 1.5, 100), {0.75, 0.75 * std::sqrt(2.0), 0.75 * std::sqrt(3.0), 1.5});
  expectDepths(haasPassDepths(true, 0.4, 0.0254, 1.5, 100), {0.4, 0.8, 1.2, 1.5});
  expectDepths(haasPassDepths(true, 0.5, 0.0, 1.5, 100), {0.5, 1.0, 1.5});
  // Minimum cut 0.3: √4 − √3 = 0.268 is below it, so each later pass adds 0.3.
  const double r3 = std::sqrt(3.0);
  expectDepths(haasPassDepths(false, 1.0, 0.3, 3.0, 100), {1.0, std::sqrt(2.0), r3, r3 + 0.3, r3 + 0.6, r3 + 0.9, r3 + 1.2, 3.0});
  EXPECT_FALSE(haasPassDepths(false, 0.001, 0.0, 5.0, 1000));
}

// A = X22 Z5 (radius 11); G76 X17. Z-20. K1.5 D0.75 A60 F2.: depths 0.75·√n: 0.75, 1.0607,
// 1.2990, then 1.5 reaches K: four passes (Setting 86 = 0: no finish pass). Pass at depth d:
// B = (8.5 + 1.5 − d, 5 − d·tan 30°), thread to Z-20, rapid X back to 11, rapid Z back to 5.
TEST(HaasG76, OneBlockExternal) {
  const auto result = run("G00 X22. Z5.\nG76 X17. Z-20. K1.5 D0.75 A60 F2.\n", haas());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  std::vector<ExpectedThread> expected{{kRapid, 100, 200, 11, 5, 0, 0}};
  for (const double d : {0.75, 0.75 * std::sqrt(2.0), 0.75 * std::sqrt(3.0), 1.5}) {
    const double r = 10.0 - d;
    const double z = 5.0 - d * std::tan(M_PI / 6.0);
    expected.push_back({kRapid, 11, 5, r, z, 0, 1});
    expected.push_back({kThread, r, z, r, -20, 2, 2, 0});
    expected.push_back({kRapid, r, -20, 11, -20, 0, 3});
    expected.push_back({kRapid, 11, -20, 11, 5, 0, 4});
  }
  expectThreadMoves(result.toolpath.moves, expected);
}

// Internal, radial infeed (A0), constant depth P3 and a finish allowance (Setting 86 = 0.1):
// A = X20 Z5 (radius 10), G76 X24. Z-20. K1. D0.3 P3 F1.5: depths 0.3, 0.6, 0.9 = K − 0.1 … the
// next, 1.2, passes 0.9: 0.9; then one pass at K. Pass at d: (12 − (1 − d), 5).
TEST(HaasG76, InternalConstantDepthWithFinishAllowance) {
  InterpreterOptions options = haas();
  options.control.threadAllowanceMm = 0.1;
  const auto result = run("G00 X20. Z5.\nG76 X24. Z-20. K1. D0.3 P3 F1.5\n", options);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  std::vector<ExpectedThread> expected{{kRapid, 100, 200, 10, 5, 0, 0}};
  for (const double d : {0.3, 0.6, 0.9, 1.0}) {
    const double r = 12.0 - (1.0 - d);
    expected.push_back({kRapid, 10, 5, r, 5, 0, 1});
    expected.push_back({kThread, r, 5, r, -20, 1.5, 2, 0});
    expected.push_back({kRapid, r, -20, 10, -20, 0, 3});
    expected.push_back({kRapid, 10, -20, 10, 5, 0, 4});
  }
  expectThreadMoves(result.toolpath.moves, expected);
}

TEST(HaasG76, BadForms) {
  expectError(run("G00 X22. Z5.\nG76 X17. Z-20. D0.5 F2.\n", haas()), 2, 1, "G76 needs K");
  expectError(run("G00 X22. Z5.\nG76 X17. Z-20. K1. F2.\n", haas()), 2, 1, "G76 needs D");
  expectError(run("G00 X22. Z5.\nG76 X17. Z-20. K1. D0.3 P2 F2.\n", haas()), 2, 25, "double edge");
  expectError(run("G00 X22. Z5.\nG76 X17. Z-20. K1. D0.3 A60. F2.\n", haas()), 2, 25, "without a decimal point");
  expectError(run("G00 X22. Z5.\nG76 X17. Z-20. K1. D0.3 A130 F2.\n", haas()), 2, 25, "0 to 120");
  expectError(run("G00 X22. Z5.\nG76 X17. Z5. K1. D0.3 F2.\n", haas()), 2, 10, "face thread");
  expectError(run("G00 X22. Z5.\nG76 X17. Z-20. K-1. D0.3 F2.\n", haas()), 2, 16, "not the thread height");
}

}  // namespace
}  // namespace lathesim::interp

namespace lathesim::interp {
namespace {

// G83 on the axis from A = (0, 5): R2. (Haas: the R point's Z), pecks Q5. to Z-12.: depths 5,
// 10, 14 below R; after each peck but the last rapid back to R, then rapid down to the last
// depth less the clearance 0.5 (g74_retract), feed on; after the bottom rapid back to Z5.
TEST(DrillingCycles, HaasG83PecksBackToTheRPoint) {
  const auto result = run("G00 X0. Z5.\nG83 Z-12. R2. Q5. F0.1\n", haas());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const std::vector<Expected> expected{
      {kRapid, 100, 200, 0, 5, 0, 0},   {kRapid, 0, 5, 0, 2, 0, 1},      {kFeed, 0, 2, 0, -3, 0.1, 2},
      {kRapid, 0, -3, 0, 2, 0, 3},      {kRapid, 0, 2, 0, -2.5, 0, 4},   {kFeed, 0, -2.5, 0, -8, 0.1, 2},
      {kRapid, 0, -8, 0, 2, 0, 3},      {kRapid, 0, 2, 0, -7.5, 0, 4},   {kFeed, 0, -7.5, 0, -12, 0.1, 2},
      {kRapid, 0, -12, 0, 5, 0, 5},
  };
  expectMoves(result.toolpath.moves, expected);
  // Fanuc T writes R as the distance from the start and Q in least increments: the same holes.
  InterpreterOptions fanuc = test::defaultOptions();
  const auto same = run("G00 X0 Z5\nG83 Z-12 R-3 Q5000 F0.1\n", fanuc);
  ASSERT_TRUE(same.ok()) << same.diagnostics[0].message;
  expectMoves(same.toolpath.moves, expected);
}

// G81 stays in force: "Z-15." drills again from the same R point; after G80 a Z word is a move
// of the modal G00 again. G82 dwells P (Haas: P0.5 is half a second) at the bottom.
TEST(DrillingCycles, ModalUntilG80AndG82Dwells) {
  const auto result = run("G00 X0. Z5.\nG81 Z-10. R1. F0.1\nZ-15.\nG80\nZ20.\nG00 Z5.\nG82 Z-4. R1. P0.5\n", haas());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const auto& m = result.toolpath.moves;
  ASSERT_EQ(m.size(), 13u);
  expectMoves({m.begin() + 1, m.begin() + 7},
              {{kRapid, 0, 5, 0, 1, 0, 1}, {kFeed, 0, 1, 0, -10, 0.1, 2}, {kRapid, 0, -10, 0, 5, 0, 5},
               {kRapid, 0, 5, 0, 1, 0, 1}, {kFeed, 0, 1, 0, -15, 0.1, 2}, {kRapid, 0, -15, 0, 5, 0, 5}});
  EXPECT_EQ(m[7].kind, MoveKind::Rapid);  // Z20. after G80
  EXPECT_NEAR(m[7].to.y(), 20.0, 1e-12);
  EXPECT_EQ(m[11].kind, MoveKind::Dwell);
  EXPECT_NEAR(m[11].to.y(), -4.0, 1e-12);
  EXPECT_DOUBLE_EQ(m[11].dwellS, 0.5);
}

// G84 taps on the axis (Haas's G84, Fanuc 0i-T's front tapping cycle): from A = (0, 10) to R2.
// (Haas: the R point's Z) at rapid, feed to Z-20. with the spindle forward, feed back to R with
// it reversed, rapid to Z10. F1.5 is the lead (G99) at 300 rpm (G97): each feed is 22 mm at
// 1.5 × 300 = 450 mm/min, 22/450 min = 2.93333 s; each rapid 8 mm at Z's 8000 mm/min, 0.06 s
// (0.3 rev at 300 rpm, 108°). The spindle then stands at 108° (after the first rapid), 108 +
// 360 · 22/1.5 = 5388 ≡ 348° at the bottom, and back at 108° when the tap is out.
TEST(DrillingCycles, G84TapsAndBacksOutReversed) {
  const InterpreterOptions options = haas();
  auto result = run("G00 X0. Z10.\nG99 G97 S300 M03\nG84 Z-20. R2. F1.5\n", options);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  EXPECT_TRUE(assignMoveTimes(result.toolpath, options.machine).empty());
  const auto& m = result.toolpath.moves;
  expectMoves(m, {{kRapid, 100, 200, 0, 10, 0, 0},
                  {kRapid, 0, 10, 0, 2, 0, 1},
                  {kFeed, 0, 2, 0, -20, 1.5, 2},
                  {kFeed, 0, -20, 0, 2, 1.5, 3},
                  {kRapid, 0, 2, 0, 10, 0, 5}});
  ASSERT_EQ(m.size(), 5u);
  EXPECT_EQ(m[2].spindleDirection, SpindleDirection::Clockwise);
  EXPECT_EQ(m[3].spindleDirection, SpindleDirection::CounterClockwise);
  EXPECT_EQ(m[4].spindleDirection, SpindleDirection::Clockwise);
  EXPECT_NEAR(m[1].timeS, 0.06, 1e-9);
  EXPECT_NEAR(m[2].timeS, 22.0 / 450.0 * 60.0, 1e-9);
  EXPECT_NEAR(m[3].timeS, 22.0 / 450.0 * 60.0, 1e-9);
  EXPECT_NEAR(m[4].timeS, 0.06, 1e-9);
  EXPECT_NEAR(m[2].spindleAngleDeg, 108.0, 1e-6);
  EXPECT_NEAR(m[3].spindleAngleDeg, 348.0, 1e-6);
  EXPECT_NEAR(m[4].spindleAngleDeg, 108.0, 1e-6);
  // Fanuc T writes R as the distance from the start (R-8: Z2); a dwell P at the bottom (500 ms),
  // and the cycle stays in force: "Z-15" taps again from the same R point.
  const auto fanuc = run("G00 X0 Z10\nG99 G97 S300 M03\nG84 Z-20 R-8 P500 F1.5\nZ-15\nG80\n");
  ASSERT_TRUE(fanuc.ok()) << fanuc.diagnostics[0].message;
  const auto& f = fanuc.toolpath.moves;
  ASSERT_EQ(f.size(), 11u);
  expectMoves({f.begin() + 1, f.begin() + 3}, {{kRapid, 0, 10, 0, 2, 0, 1}, {kFeed, 0, 2, 0, -20, 1.5, 2}});
  EXPECT_EQ(f[3].kind, MoveKind::Dwell);
  EXPECT_DOUBLE_EQ(f[3].dwellS, 0.5);
  expectMoves({f.begin() + 4, f.begin() + 8}, {{kFeed, 0, -20, 0, 2, 1.5, 3},
                                               {kRapid, 0, 2, 0, 10, 0, 5},
                                               {kRapid, 0, 10, 0, 2, 0, 1},
                                               {kFeed, 0, 2, 0, -15, 1.5, 2}});
  EXPECT_EQ(f[8].kind, MoveKind::Dwell);  // the same dwell at the second hole's bottom
  EXPECT_NEAR(f[8].to.y(), -15.0, 1e-12);
  expectMoves({f.begin() + 9, f.end()}, {{kFeed, 0, -15, 0, 2, 1.5, 3}, {kRapid, 0, 2, 0, 10, 0, 5}});
}

TEST(DrillingCycles, G84NeedsTheSpindleTurning) {
  expectError(run("G00 X0. Z10.\nG84 Z-20. R2. F1.5\n", haas()), 2, 1, "G84 taps with the spindle turning");
  expectError(run("G00 X0. Z10.\nM03 S300\nG84 Z-20. R2. Q2. F1.5\n", haas()), 3, 15, "only G83 pecks");
}

TEST(DrillingCycles, OnlyOnTheAxis) {
  expectError(run("G00 X10. Z5.\nG81 Z-10. R1. F0.1\n", haas()), 2, 1, "drills on the spindle's axis");
  expectError(run("G00 X0. Z5.\nG81 X5. Z-10. R1. F0.1\n", haas()), 2, 5, "needs live tooling");
  expectError(run("G00 X0. Z5.\nG81 R1. F0.1\n", haas()), 2, 1, "G81 needs Z(W)");
  // While G81 is in force an X word asks for a hole there, never a plain move.
  expectError(run("G00 X0. Z5.\nG81 Z-10. R1. F0.1\nX20.\n", haas()), 3, 1, "needs live tooling");
  expectError(run("G00 X0. Z5.\nG81 Z-3. Q1. F0.1\n", haas()), 2, 10, "only G83 pecks");
}

}  // namespace
}  // namespace lathesim::interp

namespace lathesim::interp {
namespace {

// Haas's one-block G73 P Q I K D U W F is Fanuc's G73 U(Δi) W(Δk) R(d); G73 P Q U W F.
TEST(HaasG73, OneBlockIsTheTwoBlockForm) {
  const std::string contour = "N10 G00 X30.\nG01 Z-20.\nN20 X50. Z-30.\nM30\n";
  const auto haasRun = run("G00 X52. Z2.\nG73 P10 Q20 U0.5 W0.1 I3. K1. D3 F0.2\n" + contour, haas());
  const auto fanucRun = run("G00 X52. Z2.\nG73 U3. W1. R3\nG73 P10 Q20 U0.5 W0.1 F0.2\n" + contour,
                            test::under("haas", Dialect::FanucA));
  ASSERT_TRUE(haasRun.ok()) << haasRun.diagnostics[0].message;
  ASSERT_TRUE(fanucRun.ok()) << fanucRun.diagnostics[0].message;
  EXPECT_TRUE(haasRun.diagnostics.empty());  // the relief is the program's, not the parameters'
  EXPECT_GT(haasRun.toolpath.moves.size(), 9u);
  expectSameMoves(haasRun.toolpath.moves, fanucRun.toolpath.moves);
  expectError(run("G00 X52. Z2.\nG73 P10 Q20 I3. K1. D2.5 F0.2\n" + contour, haas()), 2, 21, "not a number of passes");
}

}  // namespace
}  // namespace lathesim::interp

namespace lathesim::interp {
namespace {

// Swept over OD and ID, infeed methods, angles and a D that does or does not divide K: the
// passes cut at the depths haasPassDepths gives, the last on the root (X/2), each pass starting
// depth·tan(A/2) along Z toward the cut, the first at the crest side by K − D.
TEST(HaasG76, SweepOfDepthsAnglesAndSides) {
  for (const bool internal : {false, true}) {
    for (const int method : {1, 3}) {
      for (const int angle : {0, 29, 60}) {
        for (const double d : {0.2, 0.35, 0.5}) {
          const double k = 1.3;
          SCOPED_TRACE(testing::Message() << (internal ? "ID" : "OD") << " P" << method << " A" << angle << " D" << d);
          const double rootDiameter = internal ? 26.0 : 17.0;
          const std::string program = std::string(internal ? "G00 X22. Z5.\n" : "G00 X22. Z5.\n") + "G76 X" +
                                      std::to_string(rootDiameter) + " Z-20. K" + std::to_string(k) + " D" +
                                      std::to_string(d) + " A" + std::to_string(angle) + " P" +
                                      std::to_string(method) + " F1.5\n";
          const auto result = run(program, haas());
          ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
          const auto depths = haasPassDepths(method == 3, d, 0.0254, k, 1000);
          ASSERT_TRUE(depths);
          std::vector<const Move*> cuts;
          for (const Move& m : result.toolpath.moves)
            if (m.kind == MoveKind::Thread) cuts.push_back(&m);
          ASSERT_EQ(cuts.size(), depths->size());
          const double sigma = internal ? -1.0 : 1.0;  // the crest side
          const double flank = std::tan(angle / 2.0 * M_PI / 180.0);
          for (std::size_t i = 0; i < cuts.size(); ++i) {
            const double depth = (*depths)[i];
            EXPECT_NEAR(cuts[i]->from.x(), rootDiameter / 2.0 + sigma * (k - depth), 1e-9) << i;
            EXPECT_NEAR(cuts[i]->from.y(), 5.0 - depth * flank, 1e-9) << i;
            EXPECT_NEAR(cuts[i]->to.y(), -20.0, 1e-9) << i;
          }
          EXPECT_NEAR(cuts.back()->to.x(), rootDiameter / 2.0, 1e-9);
        }
      }
    }
  }
}

}  // namespace
}  // namespace lathesim::interp
