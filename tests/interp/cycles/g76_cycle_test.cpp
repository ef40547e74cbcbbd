// G76 multiple threading cycle (lathe-cycles.md §6, GSK980TDi 3.24.12), expanded by hand.
// Each pass at depth D below the crest: step 1 rapid A → B = (root line + (k − D) out,
// Z_A + ζ·D·tan(a/2)), step 2 thread parallel to the root line to Z_D (run-out included),
// step 3 rapid X back to A's X, step 4 rapid Z back to A.

#include "interp/cycles/g76_cycle.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::defaultOptions;
using test::expectError;
using test::ExpectedThread;
using test::expectThreadMoves;
using test::kRapid;
using test::kThread;
using test::run;

void expectDepths(const std::optional<std::vector<double>>& depths, const std::vector<double>& expected) {
  ASSERT_TRUE(depths);
  ASSERT_EQ(depths->size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR((*depths)[i], expected[i], 1e-8) << "pass " << i + 1;
}

// Δd = 1, Δdmin = 0.3, k − d = 3: 1, √2, √3; √4 − √3 = 0.268 < 0.3, so the fourth pass is
// √3 + 0.3 and every later one adds 0.3 (GSK: no return to the formula, though √5 − 2.032
// would be 0.204 and √6 − 2.332 0.117); the eighth would pass 3 and stops there.
TEST(RoughPassDepths, SquareRootUntilDeltaMinThenDeltaMin) {
  const double r3 = std::sqrt(3.0);
  expectDepths(roughPassDepths(1.0, 0.3, 3.0, 100),
               {1.0, std::sqrt(2.0), r3, r3 + 0.3, r3 + 0.6, r3 + 0.9, r3 + 1.2, 3.0});
}

TEST(RoughPassDepths, FirstPassDeeperThanTheThreadStopsAtKMinusD) {
  expectDepths(roughPassDepths(2.0, 0.1, 1.5, 100), {1.5});
  expectDepths(roughPassDepths(0.5, 0.0, 1.0, 100), {0.5, 0.5 * std::sqrt(2.0), 0.5 * std::sqrt(3.0), 1.0});
}

TEST(RoughPassDepths, TooManyPassesIsNoAnswer) {
  EXPECT_FALSE(roughPassDepths(0.001, 0.0, 5.0, 1000));  // (5/0.001)² passes
}

// M30×2: A = X32 Z5 (radius 16); G76 P020060 Q100 R0.05 (m 2, no run-out, 60°, Δdmin 0.1,
// d 0.05); G76 X27.546 Z-30 P1227 Q400 F2 (root radius 13.773, k 1.227, Δd 0.4).
// Rough depths: 0.4, 0.4√2 = 0.5657, 0.4√3 = 0.6928, 0.8 (each adds ≥ 0.1); 0.4√5 = 0.8944
// adds 0.094 < 0.1, so 0.9, then 1.0, 1.1, and 1.2 would pass k − d = 1.177: 1.177. Then two
// finishing passes at 1.227. Pass at D: B = (13.773 + 1.227 − D, 5 − D·tan 30°) = (15 − D,
// 5 − D/√3), its cut to (15 − D, −30), out to (16, −30), back to A.
std::vector<ExpectedThread> metricThirtyByTwoMoves(double startAngleDeg = 0) {
  std::vector<ExpectedThread> expected{{kRapid, 100, 200, 16, 5, 0, 0}};
  const double depths[] = {0.4, 0.4 * std::sqrt(2.0), 0.4 * std::sqrt(3.0), 0.8, 0.9, 1.0, 1.1, 1.177, 1.227, 1.227};
  for (const double d : depths) {
    const double r = 15.0 - d;
    const double z = 5.0 - d / std::sqrt(3.0);
    expected.push_back({kRapid, 16, 5, r, z, 0, 1});
    expected.push_back({kThread, r, z, r, -30, 2, 2, startAngleDeg});
    expected.push_back({kRapid, r, -30, 16, -30, 0, 3});
    expected.push_back({kRapid, 16, -30, 16, 5, 0, 4});
  }
  return expected;
}

TEST(MultipleThreading, MetricThirtyByTwo) {
  const auto result = run("G00 X32 Z5\nG76 P020060 Q100 R0.05\nG76 X27.546 Z-30 P1227 Q400 F2\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectThreadMoves(result.toolpath.moves, metricThirtyByTwoMoves());
  ASSERT_EQ(result.toolpath.cycleStarts.size(), 1u);
  EXPECT_EQ(result.toolpath.cycleStarts[0].line, 3);
}

// Without a first block the control's parameters give m, a, Δdmin and d (GSK No.57–60, Fanuc
// 5140–5143): set to 2, 60°, 0.1 and 0.05 they make the same thread.
TEST(MultipleThreading, FirstBlockOmittedTakesTheControlsParameters) {
  InterpreterOptions options = defaultOptions();
  options.control.threadFinishingPasses = 2;
  options.control.threadToolAngleDeg = 60;
  options.control.threadMinDepthMm = 0.1;
  options.control.threadAllowanceMm = 0.05;
  const auto result = run("G00 X32 Z5\nG76 X27.546 Z-30 P1227 Q400 F2\n", options);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectThreadMoves(result.toolpath.moves, metricThirtyByTwoMoves());
  // A first block that gives only Q and R keeps the parameters' m and a.
  const auto partial = run("G00 X32 Z5\nG76 Q100 R0.05\nG76 X27.546 Z-30 P1227 Q400 F2\n", options);
  ASSERT_TRUE(partial.ok()) << partial.diagnostics[0].message;
  expectThreadMoves(partial.toolpath.moves, metricThirtyByTwoMoves());
}

// HNC's one-block G76 C(m) A(a) X Z K(k) U(d) V(Δdmin) Q(Δd) F, all in mm: the same thread as
// Fanuc's two blocks, by the same hand expansion.
TEST(HncMultipleThreading, MetricThirtyByTwoInOneBlock) {
  InterpreterOptions hnc = defaultOptions();
  hnc.dialect = Dialect::Hnc;
  const auto result = run("G00 X32 Z5\nG76 C2 A60 X27.546 Z-30 K1.227 U0.05 V0.1 Q0.4 F2\n", hnc);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectThreadMoves(result.toolpath.moves, metricThirtyByTwoMoves());
  // U and V left out: the control's g76_allowance and g76_min_depth; P the start angle (°).
  hnc.control.threadAllowanceMm = 0.05;
  hnc.control.threadMinDepthMm = 0.1;
  const auto defaults = run("G00 X32 Z5\nG76 C2 A60 X27.546 Z-30 K1.227 Q0.4 P120 F2\n", hnc);
  ASSERT_TRUE(defaults.ok()) << defaults.diagnostics[0].message;
  expectThreadMoves(defaults.toolpath.moves, metricThirtyByTwoMoves(120));
}

// Under G91 X and Z are distances: from A = X32 Z5 (radius 16), X-4 Z-25 ends at D = (14, −20).
// I-1: the root runs from C = (13, 5). A0: radial infeed; k = Δd = 1, d 0: one rough pass at
// depth 1 and C1 one finishing pass, both on the root line. R-2 E1 (a vector along −Z, its size
// counts): the run-out starts 2 mm before Z-20, at (13 + 23/25, −18), 11.5 turns after the
// start at P90, so at 270°, and ends 1 mm out at (15, −20).
// The next G76 keeps C, A, R and E: X-5 Z-25 from A is D = (13.5, −20), no taper.
TEST(HncMultipleThreading, IncrementalTaperRunoutAndModalWords) {
  InterpreterOptions hnc = defaultOptions();
  hnc.dialect = Dialect::Hnc;
  const auto result =
      run("G00 X32 Z5\nG91\nG76 C1 A0 R-2 E1 X-4 Z-25 I-1 K1 U0 Q1 P90 F2\nG76 X-5 Z-25 K1 Q1 F2\n", hnc);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  std::vector<ExpectedThread> expected{{kRapid, 100, 200, 16, 5, 0, 0}};
  for (int pass = 0; pass < 2; ++pass) {
    expected.push_back({kRapid, 16, 5, 13, 5, 0, 1});
    expected.push_back({kThread, 13, 5, 13.92, -18, 2, 2, 90});
    expected.push_back({kThread, 13.92, -18, 15, -20, 2, 2, 270});
    expected.push_back({kRapid, 15, -20, 16, -20, 0, 3});
    expected.push_back({kRapid, 16, -20, 16, 5, 0, 4});
  }
  // Second block: from (13.5, 5) straight to Z-18 (11.5 turns from 0°: 180°), out to (14.5, −20).
  for (int pass = 0; pass < 2; ++pass) {
    expected.push_back({kRapid, 16, 5, 13.5, 5, 0, 1});
    expected.push_back({kThread, 13.5, 5, 13.5, -18, 2, 2, 0});
    expected.push_back({kThread, 13.5, -18, 14.5, -20, 2, 2, 180});
    expected.push_back({kRapid, 14.5, -20, 16, -20, 0, 3});
    expected.push_back({kRapid, 16, -20, 16, 5, 0, 4});
  }
  expectThreadMoves(result.toolpath.moves, expected);
}

TEST(HncMultipleThreading, Alarms) {
  InterpreterOptions hnc = defaultOptions();
  hnc.dialect = Dialect::Hnc;
  expectError(run("G00 X32 Z5\nG76 C2 A60 X27.546 Z-30 Q0.4 F2\n", hnc), 2, 1,
              "G76 needs K(the thread height k): the thread height k, a radius in mm");
  expectError(run("G00 X32 Z5\nG76 C2 A60 X27.546 Z-30 K1.227 F2\n", hnc), 2, 1, "G76 needs Q(the first depth");
  expectError(run("G00 X32 Z5\nG76 C2 A45 X27.546 Z-30 K1.227 Q0.4 F2\n", hnc), 2, 8,
              "G76 A45: the tool angle is not one this control takes");
  expectError(run("G00 X32 Z5\nG76 C0 X27.546 Z-30 K1.227 Q0.4 F2\n", hnc), 2, 5,
              "G76 C0 is not a number of finishing passes");
  expectError(run("G00 X32 Z5\nG76 E1 X27.546 Z-30 K1.227 Q0.4 F2\n", hnc), 2, 1,
              "a run-out E of 1 mm along X needs its length along Z, R");
  expectError(run("G00 X32 Z5\nG76 C2 A60 K1.227 Q0.4 F2\n", hnc), 2, 1, "G76 needs X and Z");
  expectError(run("G00 X32 Z5\nG76 X27.546 Z-30 K0.05 U0.05 Q0.4 F2\n", hnc), 2, 18,
              "the thread height k = 0.05 mm must exceed the finishing allowance d = 0.05 mm");
  expectError(run("G00 X32 Z5\nG76 X27.546 Z5 K1.227 Q0.4 F2\n", hnc), 2, 13, "G76 cannot cut a face thread");
  expectError(run("G00 X32 Z5\nG76 X27.546 Z-30 K1.227 U-1 Q0.4 F2\n", hnc), 2, 25,
              "G76 U-1 is not a finishing allowance d");
  expectError(run("G00 X32 Z5\nG76 X27.546 Z-30 K1.227 Q0.4\n", hnc), 2, 1, "the lead is not set: G76 needs F");
}

// P010560: m 1, r 05 = half a lead (1 mm of F2) both along Z and out, a 60°. k 0.5 with
// Δd 0.5: one rough pass at k − d = 0.5 and one finishing pass, both at the root (out 0):
// B = (14.5, 5 − 0.5·tan 30°); the run-out starts at Z-19 after (5 − 0.5/√3 + 19)/2 turns.
TEST(MultipleThreading, RunoutFromR) {
  const auto result = run("G00 X32 Z5\nG76 P010560 Q0 R0\nG76 X29 Z-20 P500 Q500 F2\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const double z = 5.0 - 0.5 / std::sqrt(3.0);
  const double turns = (z + 19.0) / 2.0;
  const double angle = 360.0 * (turns - std::floor(turns));
  std::vector<ExpectedThread> expected{{kRapid, 100, 200, 16, 5, 0, 0}};
  for (int pass = 0; pass < 2; ++pass) {
    expected.push_back({kRapid, 16, 5, 14.5, z, 0, 1});
    expected.push_back({kThread, 14.5, z, 14.5, -19, 2, 2, 0});
    expected.push_back({kThread, 14.5, -19, 15.5, -20, 2, 2, angle});
    expected.push_back({kRapid, 15.5, -20, 16, -20, 0, 3});
    expected.push_back({kRapid, 16, -20, 16, 5, 0, 4});
  }
  expectThreadMoves(result.toolpath.moves, expected);
}

// A taper i = R-1 with radial infeed (a = 0): the root runs from C = (13.5 − 1, 5) to D = (13.5,
// −20). k 1 = Δd: one rough pass at 1 (d 0), one finishing pass at 1, both on the root line.
TEST(MultipleThreading, TaperWithRadialInfeed) {
  const auto result = run("G00 X32 Z5\nG76 P010000\nG76 X27 Z-20 R-1 P1000 Q1000 F1.5\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  std::vector<ExpectedThread> expected{{kRapid, 100, 200, 16, 5, 0, 0}};
  for (int pass = 0; pass < 2; ++pass) {
    expected.push_back({kRapid, 16, 5, 12.5, 5, 0, 1});
    expected.push_back({kThread, 12.5, 5, 13.5, -20, 1.5, 2, 0});
    expected.push_back({kRapid, 13.5, -20, 16, -20, 0, 3});
    expected.push_back({kRapid, 16, -20, 16, 5, 0, 4});
  }
  expectThreadMoves(result.toolpath.moves, expected);
}

// An internal thread cut toward +Z: σ = −1 (A below the root), ζ = +1. A = X20 Z-25 (radius
// 10), D = X24 Z0 (radius 12), k 0.6 (P600), Δd 0.6, d 0, m 1, a 60: both passes at depth 0.6,
// B = (12 − 0 , −25 + 0.6·tan 30°).
TEST(MultipleThreading, InternalTowardTailstock) {
  const auto result = run("G00 X20 Z-25\nG76 P010060 R0\nG76 X24 Z0 P600 Q600 F1\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const double z = -25.0 + 0.6 / std::sqrt(3.0);
  std::vector<ExpectedThread> expected{{kRapid, 100, 200, 10, -25, 0, 0}};
  for (int pass = 0; pass < 2; ++pass) {
    expected.push_back({kRapid, 10, -25, 12, z, 0, 1});
    expected.push_back({kThread, 12, z, 12, 0, 1, 2, 0});
    expected.push_back({kRapid, 12, 0, 10, 0, 0, 3});
    expected.push_back({kRapid, 10, 0, 10, -25, 0, 4});
  }
  expectThreadMoves(result.toolpath.moves, expected);
}

TEST(MultipleThreading, Alarms) {
  expectError(run("G00 X32 Z5\nG76 X27.546 Z-30 Q400 F2\n"), 2, 1, "G76 needs P(the thread height k)");
  expectError(run("G00 X32 Z5\nG76 X27.546 Z-30 P1227 F2\n"), 2, 1, "G76 needs Q(the first depth of cut Δd)");
  expectError(run("G00 X32 Z5\nG76 X27.546 Z-30 P0 Q400 F2\n"), 2, 18, "G76 P0 is not the thread height k");
  expectError(run("G00 X32 Z5\nG76 R1.5\nG76 X27.546 Z-30 P1227 Q400 F2\n"), 3, 18,
              "the thread height k = 1.227 mm must exceed the finishing allowance d = 1.5 mm");
  expectError(run("G00 X32 Z5\nG76 X27.546 W0 P1227 Q400 F2\n"), 2, 13, "G76 cannot cut a face thread");
  expectError(run("G00 X32 Z5\nG76 P1234567\n"), 2, 5, "G76 P1234567 is not P(m)(r)(a)");
  expectError(run("G00 X32 Z5\nG76 X27.546 Z-30 P1227 Q400\n"), 2, 1, "the lead is not set: G76 needs F");
  expectError(run("G00 X32 Z5\nG76 X27.546 Z-30 P5000 Q1 F2\n"), 2, 24, "more than 1000 rough passes");
  // V is HNC's Δdmin: in a Fanuc G76 it is a word nothing takes (elsewhere an unknown letter).
  expectError(run("G00 X32 Z5\nG76 X27.546 Z-30 P1227 Q400 F2 V1\n"), 2, 32, "V1 is not used by any code");
  expectError(run("G00 X32 Z5 V1\n"), 1, 12, "unknown letter 'V'");
  InterpreterOptions fanucB = defaultOptions();
  fanucB.dialect = Dialect::FanucB;
  expectError(run("G00 X32 Z5\nG76 P010045\n", fanucB), 2, 5, "the tool angle a = 45 is not one this control takes");
  EXPECT_TRUE(run("G00 X32 Z5\nG76 P010045\n").ok());  // GSK takes 00–99
  // Fanuc's m is 01–99, GSK's 00–99 (lathe-cycles.md §6).
  expectError(run("G00 X32 Z5\nG76 P000060\n", fanucB), 2, 5, "G76 P000060: the finishing passes m = 00 is not a number this control takes (01 to 99)");
  EXPECT_TRUE(run("G00 X32 Z5\nG76 P010060\n", fanucB).ok());
  EXPECT_TRUE(run("G00 X32 Z5\nG76 P990060\n", fanucB).ok());
  EXPECT_TRUE(run("G00 X32 Z5\nG76 P000060\n").ok());
}

}  // namespace
}  // namespace lathesim::interp
