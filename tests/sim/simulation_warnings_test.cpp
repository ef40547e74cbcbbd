// The simulation's warnings: cutting with the spindle stopped, a cycle started inside the
// stock; and the stock query they rest on.

#include <gtest/gtest.h>

#include <functional>

#include "sim/simulate.hpp"
#include "test_moves.hpp"

namespace lathesim::sim {
namespace {

constexpr double kWarningVoxelMm = 0.25;

interp::Move feedMove(RZ from, RZ to, bool spindleOn) {
  interp::Move m = test::turningMove(interp::MoveKind::Feed, from, to, 0, 4);
  m.column = 2;
  m.spindleOn = spindleOn;
  return m;
}

TEST(StockQuery, SignedDistanceIsNegativeInsidePositiveOutsideZeroOnTheSurface) {
  // Φ40 × 30, face at Z0: r ≤ 20, −30 ≤ Z ≤ 0.
  const Stock stock({40.0, 30.0, 0.0}, kWarningVoxelMm);
  EXPECT_LT(stock.signedDistanceAt(RZ(10, -10)), -2 * kWarningVoxelMm);  // deep inside: the band's −3 voxels
  EXPECT_GT(stock.signedDistanceAt(RZ(30, -10)), 2 * kWarningVoxelMm);
  EXPECT_NEAR(stock.signedDistanceAt(RZ(19.5, -10)), -0.5, 0.5 * kWarningVoxelMm);  // 0.5 mm under the OD
  EXPECT_NEAR(stock.signedDistanceAt(RZ(10, 0.5)), 0.5, 0.5 * kWarningVoxelMm);     // 0.5 mm above the face
}

TEST(SimulationWarnings, CuttingWithTheSpindleStopped) {
  Stock stock({40.0, 30.0, 0.0}, kWarningVoxelMm);
  interp::Toolpath path;
  path.blockCount = 1;
  // A face cut to the axis at Z-2 with the spindle stopped at 0°: a straight slot 4 mm thick
  // (the default insert) along +x, |y| ≤ 2, Z-2…0: 2·∫ √(400 − y²) dy over |y| ≤ 2 = 159.7 mm³.
  path.moves.push_back(feedMove({25, -2}, {0, -2}, false));
  path.moves.push_back(feedMove({0, -2}, {0, 5}, false));
  const SimulationResult result = simulate(path, test::squareTool(4), stock);
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_EQ(result.warnings[0].line, 4);
  EXPECT_EQ(result.warnings[0].column, 2);
  EXPECT_NE(result.warnings[0].message.find("cutting with the spindle stopped: this block cuts a straight slot of 15"),
            std::string::npos)
      << result.warnings[0].message;
  EXPECT_NE(result.warnings[0].message.find("at spindle angle 0°) with no M03/M04 in force"), std::string::npos)
      << result.warnings[0].message;
}

TEST(SimulationWarnings, NoneWhenTheSpindleTurnsOrNothingIsCut) {
  Stock stock({40.0, 30.0, 0.0}, kWarningVoxelMm);
  interp::Toolpath path;
  path.blockCount = 2;
  path.moves.push_back(feedMove({25, -2}, {0, -2}, true));
  interp::Move air = feedMove({25, 10}, {0, 10}, false);  // above the face: cuts nothing
  air.block = 1;
  path.moves.push_back(air);
  EXPECT_TRUE(simulate(path, test::squareTool(4), stock).warnings.empty());
}

TEST(SimulationWarnings, CycleStartInsideTheStockAsItIsThen) {
  Stock stock({40.0, 30.0, 0.0}, kWarningVoxelMm);
  interp::Toolpath path;
  path.blockCount = 3;
  // Block 0 faces the bar down to Z-2. Block 1 is a "cycle" starting at (10, -1): material
  // before block 0, air after it. Block 2 starts at (10, -5): inside.
  path.moves.push_back(feedMove({25, -2}, {0, -2}, true));
  path.moves.push_back(feedMove({0, -2}, {0, 5}, true));
  for (int block : {1, 2}) {
    interp::Move m = feedMove({30, 5}, {30, 6}, true);
    m.block = block;
    m.line = 10 + block;
    path.moves.push_back(m);
  }
  path.cycleStarts.push_back({1, 11, 1, RZ(10, -1), "G94"});
  path.cycleStarts.push_back({2, 12, 1, RZ(10, -5), "G90"});
  const SimulationResult result = simulate(path, test::squareTool(4), stock);
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_EQ(result.warnings[0].line, 12);
  EXPECT_EQ(result.warnings[0].message,
            "G90 starts at X20 Z-5 (the cycle start point), which is inside the stock: the cycle's rapid "
            "legs start in material; start the cycle clear of the blank");
}

// A block's moves as the interpreter hands them on: `block` ordinal, on line 10 + block.
interp::Move blockMove(int block, RZ from, RZ to) {
  interp::Move m = feedMove(from, to, true);
  m.block = block;
  m.line = 10 + block;
  return m;
}

// Faces the bar down to Z-2 in block `block`.
void faceTo2(interp::Toolpath& path, int block) {
  path.moves.push_back(blockMove(block, {25, -2}, {0, -2}));
  path.moves.push_back(blockMove(block, {0, -2}, {0, 5}));
}

// Simulates the path `pathStartingAt` makes with a G90 on line 11 starting at r 10 (X20) and
// Z `startZ`, after the bar was faced to Z-2: from Z-1, in air by then, it says nothing; from
// Z-5, in material still, it warns of that start.
void expectWarnedOnlyOfAStartInMaterial(const std::function<interp::Toolpath(double startZ)>& pathStartingAt) {
  for (const double startZ : {-1.0, -5.0}) {
    SCOPED_TRACE(startZ);
    Stock stock({40.0, 30.0, 0.0}, kWarningVoxelMm);
    const SimulationResult result = simulate(pathStartingAt(startZ), test::squareTool(4), stock);
    if (startZ == -1.0) {
      EXPECT_TRUE(result.warnings.empty()) << result.warnings.front().message;
    } else {
      ASSERT_EQ(result.warnings.size(), 1u);
      EXPECT_EQ(result.warnings[0].line, 11);
      EXPECT_NE(result.warnings[0].message.find("G90 starts at X20 Z-5 "), std::string::npos);
    }
  }
}

// A cycle start is checked when its block runs, in the order blocks run, not by block number:
// a subprogram written after M30 has higher numbers than the main program's blocks that run
// after it. Here the subprogram (block 5) faces the bar, then the main program's cycle (block
// 1) starts.
TEST(SimulationWarnings, CycleStartAfterASubprogramIsCheckedWhenItsBlockRuns) {
  expectWarnedOnlyOfAStartInMaterial([](double startZ) {
    interp::Toolpath path;
    path.blockCount = 6;
    faceTo2(path, 5);
    path.moves.push_back(blockMove(1, {30, 5}, {30, 6}));
    path.cycleStarts.push_back({1, 11, 1, RZ(10, startZ), "G90"});
    return path;
  });
}

// A cycle in a loop runs its block again: each run's start is checked at that run. The first
// run starts above the face; the second runs after block 2 faced the bar.
TEST(SimulationWarnings, CycleStartOfEachRunOfALoopIsCheckedAtThatRun) {
  expectWarnedOnlyOfAStartInMaterial([](double secondZ) {
    interp::Toolpath path;
    path.blockCount = 3;
    path.moves.push_back(blockMove(1, {30, 5}, {30, 6}));
    faceTo2(path, 2);
    path.moves.push_back(blockMove(1, {30, 5}, {30, 6}));
    path.cycleStarts.push_back({1, 11, 1, RZ(10, 5), "G90"});
    path.cycleStarts.push_back({1, 11, 1, RZ(10, secondZ), "G90"});
    return path;
  });
}

TEST(Simulate, BlockTimesAreTheirMovesTimesAndADwellRemovesNothing) {
  Stock stock({40.0, 30.0, 0.0}, kWarningVoxelMm);
  interp::Toolpath path;
  path.blockCount = 2;
  interp::Move cut = feedMove({25, -2}, {0, -2}, true);
  cut.timeS = 2.0;
  interp::Move back = feedMove({0, -2}, {0, 5}, true);
  back.timeS = 0.5;
  interp::Move dwell = feedMove({0, 5}, {0, 5}, true);
  dwell.kind = interp::MoveKind::Dwell;
  dwell.block = 1;
  dwell.line = 5;
  dwell.dwellS = dwell.timeS = 1.5;
  path.moves = {cut, back, dwell};
  const SimulationResult result = simulate(path, test::squareTool(4), stock);
  ASSERT_EQ(result.blocks.size(), 2u);
  EXPECT_DOUBLE_EQ(result.blocks[0].timeS, 2.5);
  EXPECT_EQ(result.blocks[1].line, 5);  // a dwell-only block is listed, with its time
  EXPECT_DOUBLE_EQ(result.blocks[1].timeS, 1.5);
  EXPECT_EQ(result.blocks[1].removedMm3, 0.0);
}

}  // namespace
}  // namespace lathesim::sim
