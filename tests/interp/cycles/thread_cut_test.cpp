// G32 (lathe-cycles.md §2, GSK980TDi 3.24.1), expanded by hand: the lead along the long
// axis, Q in 0.001°, a chain of G32 blocks starting each cut where the last one ended (its
// Q ignored), GSK's J/K run-out, face threads, G20 leads and I (threads per inch).
// Angles: a cut of travel t along the long axis with lead L turns the spindle t/L times, so
// the next cut of a chain starts (θ + 360·t/L) mod 360.

#include "interp/cycles/thread_cut.hpp"

#include <gtest/gtest.h>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;
using test::expectThreadMoves;
using test::kRapid;
using test::kThread;
using test::run;

// A = X30 Z5 (radius 15). G32 Z-20 F2 Q90000: 25 mm at lead 2 = 12.5 turns from 90°, so the
// chained taper G32 X34 Z-25 (Δz 5 > Δr 2: Z is the long axis) starts at 90 + 4500 = 4590 ≡ 270°
// and its Q45000 is ignored; it turns 2.5 times, to 270 + 900 ≡ 90°. After the G00 the next G32
// waits for the one-rev signal again: no Q, 0°.
TEST(ThreadCut, ChainStartsWhereTheLastCutEnded) {
  const auto result = run("G00 X30 Z5\nG32 Z-20 F2 Q90000\nG32 X34 Z-25 Q45000\nG00 X40\nG32 Z-30\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectThreadMoves(result.toolpath.moves, {{kRapid, 100, 200, 15, 5, 0, 0},
                                            {kThread, 15, 5, 15, -20, 2, 0, 90},
                                            {kThread, 15, -20, 17, -25, 2, 0, 270},
                                            {kRapid, 17, -25, 20, -25, 0, 0},
                                            {kThread, 20, -25, 20, -30, 2, 0, 0}});
  EXPECT_TRUE(result.toolpath.moves[1].thread.leadAlongZ);
  EXPECT_TRUE(result.toolpath.moves[2].thread.leadAlongZ);
}

// Any block between two G32 blocks ends the chain, even one that moves nothing.
TEST(ThreadCut, AnyOtherBlockEndsTheChain) {
  const auto result = run("G00 X30 Z5\nG32 Z-20 F2 Q90000\nM08\nG32 Z-25 Q45000\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  EXPECT_NEAR(result.toolpath.moves[2].thread.startAngleDeg, 45, 1e-9);
}

// A face (scroll) thread: Z omitted, X the long axis, the lead along X as a radius:
// X40 → X10 is 15 mm of radius, 10 turns of F1.5.
TEST(ThreadCut, FaceThreadLeadsAlongX) {
  const auto result = run("G00 X40 Z0\nG32 X10 F1.5\nG32 X4 Z-1\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectThreadMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 0, 0, 0},
                                            {kThread, 20, 0, 5, 0, 1.5, 0, 0},
                                            {kThread, 5, 0, 2, -1, 1.5, 0, 0}});
  EXPECT_FALSE(result.toolpath.moves[1].thread.leadAlongZ);
  // Δr 3 > Δz 1: X stays the long axis; 10 turns brought the spindle back to 0°.
  EXPECT_FALSE(result.toolpath.moves[2].thread.leadAlongZ);
}

// GSK J/K: over the last K = 2 of Z travel the tool moves J = +1 (a radius) in X: from (15, 5)
// to P = (15, -18) (23 mm, 11.5 turns: 0° → 180°), then to (16, -20) (one more turn: 180°).
// The chain's next G32 keeps J and K (modal within a chain) and starts at 180°: Z-40 from
// (16, -20) is 9 turns to Z-38 (180° again), then runs out to radius 17 at Z-40.
TEST(ThreadCut, RunoutJK) {
  const auto result = run("G00 X30 Z5\nG32 Z-20 F2 J1 K2\nG32 Z-40\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectThreadMoves(result.toolpath.moves, {{kRapid, 100, 200, 15, 5, 0, 0},
                                            {kThread, 15, 5, 15, -18, 2, 0, 0},
                                            {kThread, 15, -18, 16, -20, 2, 0, 180},
                                            {kThread, 16, -20, 16, -38, 2, 0, 180},
                                            {kThread, 16, -38, 17, -40, 2, 0, 180}});
}

// K omitted: K = |J|. J-0.5 pulls in toward the axis.
TEST(ThreadCut, RunoutWithoutKIsFortyFiveDegrees) {
  const auto result = run("G00 X30 Z5\nG32 Z-20 F2 J-0.5\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectThreadMoves(result.toolpath.moves, {{kRapid, 100, 200, 15, 5, 0, 0},
                                            {kThread, 15, 5, 15, -19.5, 2, 0, 0},
                                            {kThread, 15, -19.5, 14.5, -20, 2, 0, 90}});
}

// G20: F0.1 is a lead of 2.54 mm; X1.2 Z0.2 → Z-1.0 is 30.48 mm, 12 turns. GSK's I8 is eight
// threads per inch, a lead of 3.175 mm, under G21 as under G20.
TEST(ThreadCut, InchLeadsAndThreadsPerInch) {
  const auto inch = run("G20\nG00 X1.2 Z0.2\nG32 Z-1.0 F0.1\n");
  ASSERT_TRUE(inch.ok()) << inch.diagnostics[0].message;
  EXPECT_NEAR(inch.toolpath.moves[1].feed, 2.54, 1e-12);
  EXPECT_NEAR(inch.toolpath.moves[1].to.y(), -25.4, 1e-12);
  const auto tpi = run("G00 X30 Z5\nG32 Z-20 I8\n");
  ASSERT_TRUE(tpi.ok()) << tpi.diagnostics[0].message;
  EXPECT_NEAR(tpi.toolpath.moves[1].feed, 3.175, 1e-12);
}

TEST(ThreadCut, StartAngleIsInThousandthsOfADegree) {
  const auto result = run("G00 X30 Z5\nG32 Z-20 F2 Q180\n");
  ASSERT_TRUE(result.ok());
  EXPECT_NEAR(result.toolpath.moves[1].thread.startAngleDeg, 0.18, 1e-12);
  EXPECT_TRUE(result.diagnostics.empty());
  const auto decimal = run("G00 X30 Z5\nG32 Z-20 F2 Q180.0\n");
  ASSERT_TRUE(decimal.ok());
  ASSERT_EQ(decimal.diagnostics.size(), 1u);
  EXPECT_EQ(decimal.diagnostics[0].line, 2);
  EXPECT_EQ(decimal.diagnostics[0].column, 13);
  EXPECT_NE(decimal.diagnostics[0].message.find("Q180.0 is read in 0.001°"), std::string::npos);
}

TEST(ThreadCut, Alarms) {
  expectError(run("G00 X30 Z5\nG32 Z-20\n"), 2, 1, "the lead is not set: G32 needs F");
  expectError(run("G00 X30 Z5\nG32 Z-20 F0\n"), 2, 1, "the lead is 0: G32 needs F > 0");
  expectError(run("F0\nG00 X30 Z5\nG92 X29 Z-20\n"), 3, 1, "the lead is 0: G92 needs F > 0");
  expectError(run("G00 X30 Z5\nG32 Z-20 F2 Q400000\n"), 2, 13, "G32 Q400000 is not a start angle");
  expectError(run("G00 X30 Z5\nG32 Z-20 F2 I8\n"), 2, 13, "not both");
  expectError(run("G00 X30 Z5\nG32 Z-20 I0\n"), 2, 10, "I0 is not a number of threads per inch");
}

TEST(ThreadCut, WarnsUnderG96AndG42) {
  const auto result = run("G50 S2000\nG96 S100\nG42 G00 X30 Z5\nG32 Z-20 F2\nG40 G00 X40\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  ASSERT_EQ(result.diagnostics.size(), 2u);
  EXPECT_NE(result.diagnostics[0].message.find("G32 under G42: thread moves get no nose radius compensation"),
            std::string::npos);
  EXPECT_NE(result.diagnostics[1].message.find("G32 under G96"), std::string::npos);
  EXPECT_EQ(result.toolpath.moves[1].noseComp.side, NoseSide::None);
}

// S3000 × lead 3 = 9000 mm/min along Z, above the default setup's 8000 mm/min rapid Z.
TEST(ThreadCut, WarnsWhenTheLeadOutrunsTheAxis) {
  const auto result = run("M03 S3000\nG00 X30 Z5\nG32 Z-20 F3\n");
  ASSERT_TRUE(result.ok());
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_NE(result.diagnostics[0].message.find("needs 9000 mm/min along Z"), std::string::npos);
  EXPECT_TRUE(run("M03 S2000\nG00 X30 Z5\nG32 Z-20 F3\n").diagnostics.empty());
}

// M04 is carried on the moves (the sense in which the angle advances).
TEST(ThreadCut, CarriesTheSpindleDirection) {
  const auto result = run("M04 S500\nG00 X30 Z5\nG32 Z-20 F2\n");
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(result.toolpath.moves[1].spindleDirection, SpindleDirection::CounterClockwise);
  EXPECT_EQ(run("M03 S500\nG00 X30 Z5\nG32 Z-20 F2\n").toolpath.moves[1].spindleDirection,
            SpindleDirection::Clockwise);
}

TEST(ThreadCutLegs, RunoutLongerThanTheCutStartsAtOnce) {
  const auto legs = threadCutLegs(RZ(15, 0), RZ(15, -2), {5, 1}, ThreadMotion{2, true, 0, 1}, 2);
  ASSERT_EQ(legs.size(), 1u);
  EXPECT_EQ(legs[0].to, RZ(16, -2));
  EXPECT_EQ(legs[0].step, 2);
}

}  // namespace
}  // namespace lathesim::interp
