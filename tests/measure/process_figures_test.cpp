// Path lengths, air cutting and removal per tool, on a toolpath written out by hand.

#include "measure/process_figures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace lathesim::measure {
namespace {

interp::Move move(interp::MoveKind kind, RZ from, RZ to, int block, int tool, double timeS) {
  interp::Move m;
  m.kind = kind;
  m.from = from;
  m.to = to;
  m.block = block;
  m.line = block + 1;
  m.tool = tool;
  m.timeS = timeS;
  return m;
}

// The figures of `path`'s moves, spooled as a run spools them, against the simulation's rows.
ProcessFigures figuresOf(const interp::Toolpath& path, const std::vector<sim::BlockRemoval>& rows, double voxelMm) {
  interp::MoveSpool spool;
  for (const interp::Move& m : path.moves) spool.take(m);
  return processFigures(spool, sim::HeldBlockRows(rows), voxelMm);
}

// The removal per tool is `expected`, in its order (by tool number).
void expectRemovedPerTool(const ProcessFigures& f, const std::vector<ToolRemoval>& expected) {
  ASSERT_EQ(f.removedPerTool.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(f.removedPerTool[i].tool, expected[i].tool) << i;
    EXPECT_DOUBLE_EQ(f.removedPerTool[i].removedMm3, expected[i].removedMm3) << i;
  }
}

TEST(ProcessFigures, LengthsAirAndRemovalPerTool) {
  interp::Toolpath path;
  // Block 0, tool 1: rapid 10 mm down Z, then a feed 20 mm along −Z that removes 100 mm³.
  path.moves.push_back(move(interp::MoveKind::Rapid, {30, 10}, {30, 0}, 0, 1, 1.0));
  path.moves.push_back(move(interp::MoveKind::Feed, {30, 0}, {30, -20}, 0, 1, 2.0));
  // Block 1, tool 2: a counter-clockwise quarter circle of radius 10 about (r 20, Z-10), from
  // (20, 0) to (30, -10): in the drawing view from straight above the centre round to its
  // left, 90°, length 5π. It removes nothing: feeding through air.
  interp::Move arc = move(interp::MoveKind::ArcCCW, {20, 0}, {30, -10}, 1, 2, 4.0);
  arc.center = RZ(20, -10);
  path.moves.push_back(arc);
  // Block 2, tool 2: a 3-4-5 feed removing 50 mm³.
  path.moves.push_back(move(interp::MoveKind::Feed, {30, -10}, {33, -14}, 2, 2, 0.5));

  const ProcessFigures f = figuresOf(path, {{0, 1, 1, 100.0}, {1, 2, 1, 0.0}, {2, 3, 1, 50.0}}, 0.25);
  EXPECT_DOUBLE_EQ(f.rapidPathMm, 10.0);
  EXPECT_NEAR(f.feedPathMm, 20.0 + 5 * M_PI + 5.0, 1e-9);
  EXPECT_DOUBLE_EQ(f.rapidTimeS, 1.0);
  EXPECT_DOUBLE_EQ(f.feedTimeS, 6.5);
  EXPECT_EQ(f.airFeedMoves, 1);
  EXPECT_NEAR(f.airFeedPathMm, 5 * M_PI, 1e-9);
  EXPECT_DOUBLE_EQ(f.airFeedTimeS, 4.0);
  expectRemovedPerTool(f, {{1, 100.0}, {2, 50.0}});
}

// A block run twice (a subprogram's) is air only if both runs together removed less than a
// voxel (0.5³ = 0.125 mm³): each run here removes 0.1 mm³, 0.2 in all, so neither run's feed is
// air; its removal goes to the tool of its first run's first move (3), both runs' together.
// Block 1, run once between them, removes 0.1 mm³ with tool 4: air.
TEST(ProcessFigures, BlockRunTwiceIsAirByWhatBothRunsRemoved) {
  interp::Toolpath path;
  path.moves.push_back(move(interp::MoveKind::Feed, {30, 0}, {30, -2}, 7, 3, 1.0));
  path.moves.push_back(move(interp::MoveKind::Feed, {30, -2}, {30, -5}, 1, 4, 1.0));
  path.moves.push_back(move(interp::MoveKind::Feed, {30, -5}, {30, -9}, 7, 5, 1.0));
  const ProcessFigures f = figuresOf(path, {{7, 8, 1, 0.1}, {1, 2, 1, 0.1}, {7, 8, 1, 0.1}}, 0.5);
  EXPECT_DOUBLE_EQ(f.feedPathMm, 9.0);
  EXPECT_EQ(f.airFeedMoves, 1);
  EXPECT_DOUBLE_EQ(f.airFeedPathMm, 3.0);
  expectRemovedPerTool(f, {{3, 0.2}, {4, 0.1}});
}

// Rows that are not the moves' blocks are a broken invariant, said at once.
TEST(ProcessFigures, RowsOfOtherBlocksAreAnError) {
  interp::Toolpath path;
  path.moves.push_back(move(interp::MoveKind::Feed, {30, 0}, {30, -2}, 0, 1, 1.0));
  EXPECT_THROW(figuresOf(path, {{3, 4, 1, 0.0}}, 0.5), std::logic_error);
}

// The clockwise way round between the same points is the other three quarters: 15π.
TEST(ProcessFigures, ClockwiseArcGoesTheLongWayRound) {
  interp::Move arc = move(interp::MoveKind::ArcCW, {20, 0}, {30, -10}, 0, 1, 0);
  arc.center = RZ(20, -10);
  EXPECT_NEAR(pathLengthMm(arc), 15 * M_PI, 1e-9);
}

}  // namespace
}  // namespace lathesim::measure
