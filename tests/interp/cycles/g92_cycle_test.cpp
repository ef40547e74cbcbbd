// G92 threading cycle (lathe-cycles.md §1, GSK980TDi 3.24.9), expanded by hand:
// A the start, B = (X_C + 2R, Z_A), C the cut's end; step 1 rapid A→B, step 2 thread B→C
// (with the run-out pulling out toward A over its last K), step 3 rapid X back to A's X,
// step 4 rapid Z back to A. Positions (radius, Z); the thread moves' feed is the lead.

#include "interp/cycles/g92_cycle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <fmt/format.h>

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

// GSK980TDi's example O0012: G0 X65 Z5; G92 X58.7 Z-28 F3 J3 K1; X57.7; X57; X56.9.
// A = (32.5, 5). Each pass: B = (r, 5); thread to (r, -27): 32 mm, 10⅔ turns (0° → 240°); the
// run-out K1 J3 to (r + 3, -28); rapid to D = (32.5, -28); rapid to A. J and K are modal.
TEST(ThreadCycle, GskExampleO0012) {
  const auto result = run("G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\nX57.7\nX57\nX56.9\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  std::vector<ExpectedThread> expected{{kRapid, 100, 200, 32.5, 5, 0, 0}};
  for (const double r : {29.35, 28.85, 28.5, 28.45}) {
    expected.push_back({kRapid, 32.5, 5, r, 5, 0, 1});
    expected.push_back({kThread, r, 5, r, -27, 3, 2, 0});
    expected.push_back({kThread, r, -27, r + 3, -28, 3, 2, 240});
    expected.push_back({kRapid, r + 3, -28, 32.5, -28, 0, 3});
    expected.push_back({kRapid, 32.5, -28, 32.5, 5, 0, 4});
  }
  expectThreadMoves(result.toolpath.moves, expected);
  ASSERT_EQ(result.toolpath.cycleStarts.size(), 4u);
  EXPECT_EQ(result.toolpath.cycleStarts[0].code, "G92");
}

// As G90: G92 alone (on a safety line) makes it the modal motion and moves nothing; the X/Z
// block after it runs the cycle from where the tool is. A = (20, 2), B = (14, 2), C = (14, -20).
TEST(ThreadCycle, TheCodeAloneMovesNothing) {
  const auto result = run("G00 X40 Z2\nG92\nX28 Z-20 F1.5\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectThreadMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 2, 0, 0},
                                            {kRapid, 20, 2, 14, 2, 0, 1},
                                            {kThread, 14, 2, 14, -20, 1.5, 2, 0},
                                            {kRapid, 14, -20, 20, -20, 0, 3},
                                            {kRapid, 20, -20, 20, 2, 0, 4}});
}

// A taper: A = X40 Z2 (radius 20), G92 X30 Z-20 R-2: B = (15 - 2, 2) = (13, 2). No J/K and the
// machine's run-out parameter 0: no run-out.
TEST(ThreadCycle, TaperWithoutRunout) {
  const auto result = run("G00 X40 Z2\nG92 X30 Z-20 R-2 F1.5\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectThreadMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 2, 0, 0},
                                            {kRapid, 20, 2, 13, 2, 0, 1},
                                            {kThread, 13, 2, 15, -20, 1.5, 2, 0},
                                            {kRapid, 15, -20, 20, -20, 0, 3},
                                            {kRapid, 20, -20, 20, 2, 0, 4}});
}

// The machine's run-out parameter (GSK No.19 / Fanuc No.5130), one lead: 1.5 mm along Z and
// 1.5 mm out. On the cone (13, 2) → (15, -20) the run-out starts 1.5 mm before Z-20, at Z-18.5,
// radius 13 + 2·20.5/22; 20.5 mm is 13⅔ turns, so it starts at 240°; it ends at (16.5, -20).
TEST(ThreadCycle, RunoutFromTheMachineParameter) {
  InterpreterOptions options = defaultOptions();
  options.control.threadRunoutLeads = 1.0;
  const auto result = run("G00 X40 Z2\nG92 X30 Z-20 R-2 F1.5\n", options);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const double r = 13.0 + 2.0 * 20.5 / 22.0;
  expectThreadMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 2, 0, 0},
                                            {kRapid, 20, 2, 13, 2, 0, 1},
                                            {kThread, 13, 2, r, -18.5, 1.5, 2, 0},
                                            {kThread, r, -18.5, 16.5, -20, 1.5, 2, 240},
                                            {kRapid, 16.5, -20, 20, -20, 0, 3},
                                            {kRapid, 20, -20, 20, 2, 0, 4}});
}

// The run-out's angle to the Z axis (Fanuc No.5131, control thread_runout_angle): 30° with a
// run-out of one lead, 1.5 mm along Z, pulls out 1.5·tan 30° = 0.866025 mm. A = (20, 2), C =
// (15, -20): the run-out starts at Z-18.5, 20.5 mm = 13⅔ turns in (240°). 0, the parameter's
// own default, and 45 both run out as far across as along.
TEST(ThreadCycle, RunoutAngleFromTheControlParameter) {
  InterpreterOptions options = defaultOptions();
  options.control.threadRunoutLeads = 1.0;
  options.control.threadRunoutAngleDeg = 30;
  const auto result = run("G00 X40 Z2\nG92 X30 Z-20 F1.5\n", options);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const double across = 1.5 * std::tan(std::numbers::pi / 6);
  expectThreadMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 2, 0, 0},
                                            {kRapid, 20, 2, 15, 2, 0, 1},
                                            {kThread, 15, 2, 15, -18.5, 1.5, 2, 0},
                                            {kThread, 15, -18.5, 15 + across, -20, 1.5, 2, 240},
                                            {kRapid, 15 + across, -20, 20, -20, 0, 3},
                                            {kRapid, 20, -20, 20, 2, 0, 4}});
  for (const int angle : {0, 45}) {
    options.control.threadRunoutAngleDeg = angle;
    const auto square = run("G00 X40 Z2\nG92 X30 Z-20 F1.5\n", options);
    ASSERT_TRUE(square.ok());
    EXPECT_EQ(square.toolpath.moves[3].to, RZ(16.5, -20)) << angle;
  }
}

// An ID thread runs out toward A too, i.e. toward the axis: A = X20 Z3 (radius 10), C = X26
// Z-15 (radius 13), J1 K1: the run-out ends at radius 12.
TEST(ThreadCycle, InternalThreadRunsOutTowardTheAxis) {
  const auto result = run("G00 X20 Z3\nG92 X26 Z-15 F1 J1 K1\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectThreadMoves(result.toolpath.moves, {{kRapid, 100, 200, 10, 3, 0, 0},
                                            {kRapid, 10, 3, 13, 3, 0, 1},
                                            {kThread, 13, 3, 13, -14, 1, 2, 0},
                                            {kThread, 13, -14, 12, -15, 1, 2, 0},
                                            {kRapid, 12, -15, 10, -15, 0, 3},
                                            {kRapid, 10, -15, 10, 3, 0, 4}});
}

// GSK L2: two starts, the second half a turn after the first: the same four legs twice, the
// thread moves at 0° and 180°. L is modal: X27.4 cuts both starts again.
TEST(ThreadCycle, TwoStartsHalfATurnApart) {
  const auto result = run("G00 X32 Z3\nG92 X28 Z-20 F4 L2\nX27.4\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  std::vector<ExpectedThread> expected{{kRapid, 100, 200, 16, 3, 0, 0}};
  for (const double r : {14.0, 13.7})
    for (const double angle : {0.0, 180.0}) {
      expected.push_back({kRapid, 16, 3, r, 3, 0, 1});
      expected.push_back({kThread, r, 3, r, -20, 4, 2, angle});
      expected.push_back({kRapid, r, -20, 16, -20, 0, 3});
      expected.push_back({kRapid, 16, -20, 16, 3, 0, 4});
    }
  expectThreadMoves(result.toolpath.moves, expected);
  EXPECT_EQ(result.toolpath.moves[2].thread.starts, 2);
}

// Fanuc's G92 Q shifts the start angle (0.001°, B-63944EN §4.1.2) and is not modal: Q90000
// starts this pass at 90°, the repetition X27.4 at 0° again. In fanuc-b's G78 alike.
TEST(ThreadCycle, QShiftsTheStartAngleOfThisBlockOnly) {
  for (const auto& [dialect, code] : {std::pair{Dialect::FanucA, "G92"}, std::pair{Dialect::FanucB, "G78"}}) {
    InterpreterOptions options = defaultOptions();
    options.dialect = dialect;
    const auto result = run(fmt::format("G00 X32 Z3\n{} X28 Z-20 F2 Q90000\nX27.4\n", code), options);
    ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
    std::vector<ExpectedThread> expected{{kRapid, 100, 200, 16, 3, 0, 0}};
    for (const auto& [r, angle] : {std::pair{14.0, 90.0}, std::pair{13.7, 0.0}}) {
      expected.push_back({kRapid, 16, 3, r, 3, 0, 1});
      expected.push_back({kThread, r, 3, r, -20, 2, 2, angle});
      expected.push_back({kRapid, r, -20, 16, -20, 0, 3});
      expected.push_back({kRapid, 16, -20, 16, 3, 0, 4});
    }
    expectThreadMoves(result.toolpath.moves, expected);
  }
  expectError(run("G00 X32 Z3\nG92 X28 Z-20 F2 Q400000\n"), 2, 17, "G92 Q400000 is not a start angle");
}

// Fanuc system B writes G92 as G78; its run-out is the machine's chamfer parameter alone.
TEST(ThreadCycle, FanucBWritesItG78) {
  InterpreterOptions options = defaultOptions();
  options.dialect = Dialect::FanucB;
  options.control.threadRunoutLeads = 0.5;
  const auto result = run("G00 X32 Z3\nG78 X28 Z-20 F2\n", options);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectThreadMoves(result.toolpath.moves, {{kRapid, 100, 200, 16, 3, 0, 0},
                                            {kRapid, 16, 3, 14, 3, 0, 1},
                                            {kThread, 14, 3, 14, -19, 2, 2, 0},
                                            {kThread, 14, -19, 15, -20, 2, 2, 0},
                                            {kRapid, 15, -20, 16, -20, 0, 3},
                                            {kRapid, 16, -20, 16, 3, 0, 4}});
  expectError(run("G00 X32 Z3\nG78 X28 Z-20 F2 L2\n", options), 2, 17, "L2 is not used");
}

// Huazhong G82 X Z I(taper) R(Z run-out) E(X run-out, a radius ⚠) C(starts) P(first start, °):
// A = (16, 3), C = (14, -20), I-1: B = (13, 3). The run-out R2 starts at Z-18 on the cone, radius
// 13 + 21/23, 21 mm = 10.5 turns after the start; it ends at (15, -20). C2 P30: starts at 30° and
// 210°.
TEST(ThreadCycle, HncG82) {
  InterpreterOptions options = defaultOptions();
  options.dialect = Dialect::Hnc;
  const auto result = run("G00 X32 Z3\nG82 X28 Z-20 I-1 R2 E1 C2 P30 F2\n", options);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const double r = 13.0 + 21.0 / 23.0;
  std::vector<ExpectedThread> expected{{kRapid, 100, 200, 16, 3, 0, 0}};
  for (const double angle : {30.0, 210.0}) {
    expected.push_back({kRapid, 16, 3, 13, 3, 0, 1});
    expected.push_back({kThread, 13, 3, r, -18, 2, 2, angle});
    expected.push_back({kThread, r, -18, 15, -20, 2, 2, angle + 180.0 - (angle > 180 ? 360.0 : 0.0)});
    expected.push_back({kRapid, 15, -20, 16, -20, 0, 3});
    expected.push_back({kRapid, 16, -20, 16, 3, 0, 4});
  }
  expectThreadMoves(result.toolpath.moves, expected);
}

TEST(ThreadCycle, Alarms) {
  expectError(run("G00 X60 Z2\nG92 X40 Z-20 R12 F2\n"), 2, 14,
              "R12 and U-20 have opposite signs and |R| > |U/2|; G92 needs |R| ≤ |U/2|");
  expectError(run("G00 X60 Z2\nG92 X40 W0 F2\n"), 2, 9, "G92 cannot cut a face thread");
  expectError(run("G00 X60 Z2\nG92 X40 Z-20\n"), 2, 1, "the lead is not set: G92 needs F");
  expectError(run("G00 X60 Z2\nG92 X40 Z-20 F2 L100\n"), 2, 17, "G92 L100 is not a number of starts");
  // G00 ends the cycle: its X, Z and L are not kept.
  expectError(run("G00 X60 Z2\nG92 X40 Z-20 F2 L2\nG00 X60\nG92 X38\n"), 4, 1, "the end point's Z(W)");
}

}  // namespace
}  // namespace lathesim::interp
