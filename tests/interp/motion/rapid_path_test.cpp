// Rapids under non-linear positioning (the default on both presets): each axis at its own
// rate, X 6000 mm/min of radius and Z 8000 mm/min here (the default machine), so a rapid that
// moves both axes is a diagonal until the quicker axis arrives, then a straight leg. Every
// corner below is worked out by hand from tX = |Δr|/6000 and tZ = |ΔZ|/8000 (minutes).

#include "interp/motion/rapid_path.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../test_support.hpp"
#include "interp/motion/cycle_time.hpp"

namespace lathesim::interp {
namespace {

using test::expectMoves;
using test::kFeed;
using test::kRapid;

InterpreterOptions nonLinear() {
  InterpreterOptions options = test::defaultOptions();
  options.control.rapidPath = RapidPath::NonLinear;
  return options;
}

TEST(RapidPath, XArrivesFirstThenZGoesOnAlone) {
  // X200 Z200 → X30 Z2: Δr 85 takes 85/6000 = 0.0141667 min, ΔZ 198 takes 0.02475 min. In
  // 85/6000 min Z moves 8000·85/6000 = 113.333: corner (r 15, Z86.667), then Z alone to 2.
  const auto result = interpret("G00 X30 Z2\n", "test.nc", nonLinear());
  ASSERT_TRUE(result.ok());
  expectMoves(result.toolpath.moves,
              {{kRapid, 100, 200, 15, 200 - 340.0 / 3, 0, 0}, {kRapid, 15, 200 - 340.0 / 3, 15, 2, 0, 0}});
  EXPECT_EQ(result.toolpath.moves[0].line, 1);
  EXPECT_EQ(result.toolpath.moves[1].line, 1);
  EXPECT_EQ(result.toolpath.moves[1].block, result.toolpath.moves[0].block);
}

TEST(RapidPath, ZArrivesFirstThenXGoesOnAlone) {
  // X200 Z10 → X20 Z0 (after a straight Z move): Δr 90 takes 0.015 min, ΔZ 10 takes 0.00125:
  // in 0.00125 min X moves 6000·0.00125 = 7.5 of radius: corner (r 92.5, Z0), then X alone.
  const auto result = interpret("G00 Z10\nG00 X20 Z0\n", "test.nc", nonLinear());
  ASSERT_TRUE(result.ok());
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 100, 10, 0, 0},
                                      {kRapid, 100, 10, 92.5, 0, 0, 0},
                                      {kRapid, 92.5, 0, 10, 0, 0, 0}});
}

TEST(RapidPath, EveryDirectionTakesTheSignOfItsAxis) {
  // From (r 10, Z0) to X60 Z-20 (r 30): Δr +20 takes 20/6000 = 0.003333 min, ΔZ −20 takes
  // 0.0025: Z first; X has moved +15: corner (r 25, Z-20).
  const auto result = interpret("G00 X20 Z0\nG00 X60 Z-20\n", "test.nc", test::defaultOptions());
  ASSERT_TRUE(result.ok());
  auto moves = result.toolpath.moves;
  splitRapidsIntoAxisLegs(moves, MachineLimits{});
  ASSERT_EQ(moves.size(), 4u);  // the first rapid splits too
  EXPECT_NEAR(moves[2].from.x(), 10, 1e-12);
  EXPECT_NEAR(moves[2].to.x(), 25, 1e-12);
  EXPECT_NEAR(moves[2].to.y(), -20, 1e-12);
  EXPECT_NEAR(moves[3].to.x(), 30, 1e-12);
}

TEST(RapidPath, AxesArrivingTogetherOrOneAxisMakeOneMove) {
  // Δr 60 and ΔZ 80 both take 0.01 min: a straight line. Then X alone, then Z alone.
  const auto result = interpret("G00 X80 Z120\nG00 X60\nG00 Z100\n", "test.nc", nonLinear());
  ASSERT_TRUE(result.ok());
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 40, 120, 0, 0},
                                      {kRapid, 40, 120, 30, 120, 0, 0},
                                      {kRapid, 30, 120, 30, 100, 0, 0}});
}

TEST(RapidPath, LinearPositioningKeepsTheStraightLineAndFeedsNeverSplit) {
  const auto result = interpret("G00 X30 Z2\nG01 X0 Z-20 F0.2\n", "test.nc", test::defaultOptions());
  ASSERT_TRUE(result.ok());
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 15, 2, 0, 0}, {kFeed, 15, 2, 0, -20, 0.2, 0}});
}

TEST(RapidPath, TheLegsTakeTheRapidsTimeBetweenThem) {
  // X200 Z200 → X30 Z2: 0.85 s for the diagonal (85/6000 min), 0.635 s for the rest
  // ((86.667 − 2)/8000 min): 1.485 s, the slower axis's 198/8000 min as before.
  auto result = interpret("G00 X30 Z2\n", "test.nc", nonLinear());
  ASSERT_TRUE(result.ok());
  (void)assignMoveTimes(result.toolpath, MachineLimits{});
  ASSERT_EQ(result.toolpath.moves.size(), 2u);
  EXPECT_NEAR(result.toolpath.moves[0].timeS, 0.85, 1e-12);
  EXPECT_NEAR(result.toolpath.moves[1].timeS, 0.635, 1e-12);
  EXPECT_NEAR(cycleTimeS(result.toolpath), 1.485, 1e-12);
}

TEST(RapidPath, TheRatesOfTheMachineShapeTheCorner) {
  // Rapid X 3000, Z 12000 mm/min: X200 Z200 → X30 Z2 takes X 85/3000 = 0.028333 min, Z
  // 198/12000 = 0.0165: Z first, X having moved 3000·0.0165 = 49.5: corner (r 50.5, Z2).
  InterpreterOptions options = nonLinear();
  options.machine.rapidXMmPerMin = 3000;
  options.machine.rapidZMmPerMin = 12000;
  const auto result = interpret("G00 X30 Z2\n", "test.nc", options);
  ASSERT_TRUE(result.ok());
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 50.5, 2, 0, 0}, {kRapid, 50.5, 2, 15, 2, 0, 0}});
}

TEST(RapidPath, BothLegsOfG28AndTheRapidsOfCyclesAreDogLegs) {
  // Reference X100 Z150 = (50, 150). From (r 20, Z10): G28 U20 W30 goes to (30, 40): Δr 10
  // takes 10/6000, ΔZ 30 takes 30/8000 = 0.00375: X first, Z +13.333: corner (30, 23.333).
  // Then to (50, 150): Δr 20 takes 0.003333, ΔZ 110 takes 0.01375: X first, Z +26.667:
  // corner (50, 66.667).
  InterpreterOptions options = nonLinear();
  options.referencePosition = RZ(50, 150);
  const auto result = interpret("G00 X40\nG00 Z10\nG28 U20 W30\n", "test.nc", options);
  ASSERT_TRUE(result.ok());
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 200, 0, 0},
                                      {kRapid, 20, 200, 20, 10, 0, 0},
                                      {kRapid, 20, 10, 30, 10 + 40.0 / 3, 0, 1},
                                      {kRapid, 30, 10 + 40.0 / 3, 30, 40, 0, 1},
                                      {kRapid, 30, 40, 50, 40 + 80.0 / 3, 0, 2},
                                      {kRapid, 50, 40 + 80.0 / 3, 50, 150, 0, 2}});
}

// Every direction, length and pair of rates: the diagonal moves both axes at their full rates
// (|Δr| / rate X = |ΔZ| / rate Z), the rest moves one axis alone, the legs join and end where
// the rapid does, and their times add up to the slower axis's.
TEST(RapidPath, ASweepOfRapidsSplitAsTheAxesMove) {
  const RZ start(40, 10);
  for (const auto& [rateX, rateZ] : {std::pair{6000.0, 8000.0}, {3000.0, 12000.0}, {10000.0, 10000.0}}) {
    const MachineLimits machine{rateX, rateZ, 3000.0, std::nullopt};
    for (const double dr : {-35.0, -7.5, -0.25, 0.0, 0.3, 12.0, 60.0}) {
      for (const double dz : {-120.0, -9.0, -0.4, 0.0, 0.2, 5.0, 80.0}) {
        SCOPED_TRACE(testing::Message() << "rates " << rateX << "/" << rateZ << ", Δr " << dr << ", ΔZ " << dz);
        Move rapid;
        rapid.from = start;
        rapid.to = start + RZ(dr, dz);
        std::vector<Move> moves{rapid};
        splitRapidsIntoAxisLegs(moves, machine);
        const double tX = std::abs(dr) / rateX;
        const double tZ = std::abs(dz) / rateZ;
        if (tX == 0 || tZ == 0 || std::abs(tX - tZ) <= 1e-12 * std::max(tX, tZ)) {
          ASSERT_EQ(moves.size(), 1u);  // one axis, or both arriving together: straight
          continue;
        }
        ASSERT_EQ(moves.size(), 2u);
        EXPECT_EQ(moves[0].from, rapid.from);
        EXPECT_EQ(moves[0].to, moves[1].from);
        EXPECT_EQ(moves[1].to, rapid.to);
        const RZ diagonal = moves[0].to - moves[0].from;
        const RZ rest = moves[1].to - moves[1].from;
        EXPECT_NEAR(std::abs(diagonal.x()) / rateX, std::min(tX, tZ), 1e-15);
        EXPECT_NEAR(std::abs(diagonal.y()) / rateZ, std::min(tX, tZ), 1e-15);
        EXPECT_GE(diagonal.x() * dr, 0.0);  // each axis goes its own way, never back
        EXPECT_GE(diagonal.y() * dz, 0.0);
        EXPECT_EQ(tX < tZ ? rest.x() : rest.y(), 0.0);  // the quicker axis has arrived
        Toolpath toolpath;
        toolpath.moves = moves;
        (void)assignMoveTimes(toolpath, machine);
        EXPECT_NEAR(cycleTimeS(toolpath), 60.0 * std::max(tX, tZ), 1e-12);
      }
    }
  }
}

TEST(RapidPath, TheRapidsOfACycleAreDogLegs) {
  // G73's first rapid goes from A = (r 26, Z2) to A1 = A + (Δi, Δk) = (29, 3): Δr 3 takes
  // 0.0005 min, ΔZ 1 takes 0.000125: Z first, X +0.75: corner (r 26.75, Z3), then X alone.
  const auto result = interpret(
      "G00 X52 Z2\nG73 U3 W1 R2\nG73 P10 Q20 F0.2\nN10 G01 X40\nN20 Z-20\n", "test.nc", nonLinear());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const auto& moves = result.toolpath.moves;
  ASSERT_GE(moves.size(), 4u);
  expectMoves({moves.begin() + 2, moves.begin() + 4},
              {{kRapid, 26, 2, 26.75, 3, 0, 1}, {kRapid, 26.75, 3, 29, 3, 0, 1}});
}

// The legs are added in place: rapids that split, between moves that stay, each move keeping
// its block and the path staying joined. A (r 10, Z0) → (r 30, Z-20): Z first (0.0025 min),
// X +15: corner (25, -20). B (r 30, Z10) → (r 90, Z30): Z first (0.0025 min), X +15: corner
// (45, 30). The feed, the Z-only rapid and the dwell stay as they are.
TEST(RapidPath, LegsAreAddedInPlaceBetweenMovesThatStay) {
  const auto move = [](MoveKind kind, RZ from, RZ to, int block) {
    Move m;
    m.kind = kind, m.from = from, m.to = to, m.block = block;
    return m;
  };
  std::vector<Move> moves = {move(MoveKind::Rapid, {10, 0}, {30, -20}, 0),
                             move(MoveKind::Feed, {30, -20}, {30, -40}, 1),
                             move(MoveKind::Rapid, {30, -40}, {30, 10}, 2),
                             move(MoveKind::Rapid, {30, 10}, {90, 30}, 3),
                             move(MoveKind::Dwell, {90, 30}, {90, 30}, 4)};
  splitRapidsIntoAxisLegs(moves, MachineLimits{});
  const std::vector<std::pair<RZ, int>> ends = {{{25, -20}, 0}, {{30, -20}, 0}, {{30, -40}, 1}, {{30, 10}, 2},
                                                {{45, 30}, 3},  {{90, 30}, 3},  {{90, 30}, 4}};
  ASSERT_EQ(moves.size(), ends.size());
  RZ at(10, 0);
  for (std::size_t i = 0; i < moves.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_NEAR((moves[i].from - at).norm(), 0, 1e-12);
    EXPECT_NEAR((moves[i].to - ends[i].first).norm(), 0, 1e-12);
    EXPECT_EQ(moves[i].block, ends[i].second);
    at = moves[i].to;
  }
  EXPECT_EQ(moves[6].kind, MoveKind::Dwell);
  EXPECT_EQ(moves[2].kind, MoveKind::Feed);
}

}  // namespace
}  // namespace lathesim::interp
