// --at-line's cut (app/at_line.hpp) on hand-built toolpaths: where it stops when a line runs
// twice, which cycle starts it keeps, and what it says about lines it cannot stop at.

#include "app/at_line.hpp"

#include <gtest/gtest.h>

namespace lathesim::app {
namespace {

interp::Move moveOn(int line, int block, double toZ) {
  interp::Move m;
  m.kind = interp::MoveKind::Feed;
  m.line = line;
  m.block = block;
  m.to = RZ(10, toZ);
  return m;
}

// A main program (lines 1–3, blocks 0–2) calling a subprogram (lines 5–6, blocks 4–5) twice:
// moves in program order on lines 1, 5, 6, 2, 5, 6, 3 (Z 1..7 to tell them apart). Line 5's
// first execution is the second move, so --at-line 5 keeps 2 moves, --at-line 6 keeps 3.
interp::Toolpath subprogramTwice() {
  interp::Toolpath path;
  const int lines[] = {1, 5, 6, 2, 5, 6, 3};
  const int blocks[] = {0, 4, 5, 1, 4, 5, 2};
  for (int i = 0; i < 7; ++i) path.moves.push_back(moveOn(lines[i], blocks[i], i + 1));
  path.blockCount = 6;
  return path;
}

TEST(AtLine, ALineRunTwiceStopsAfterItsFirstExecution) {
  const interp::Toolpath path = subprogramTwice();
  const ToolpathAtLine at5 = toolpathAtLine(path, 5, 6);
  ASSERT_TRUE(at5.toolpath) << at5.problem;
  ASSERT_EQ(at5.toolpath->moves.size(), 2u);
  EXPECT_EQ(at5.toolpath->moves.back().to, RZ(10, 2));
  EXPECT_EQ(at5.toolpath->blockCount, 5);  // blocks 0 and 4 read: ordinals up to 4
  const ToolpathAtLine at2 = toolpathAtLine(path, 2, 6);
  ASSERT_TRUE(at2.toolpath) << at2.problem;
  EXPECT_EQ(at2.toolpath->moves.size(), 4u);  // lines 1, 5, 6, 2
}

// A subprogram in a file of its own (O2000.nc) called from line 2 of a 3-line program, its
// moves on its lines 2 and 3 (blocks 3 and 4): they run under line 2, so --at-line 2 keeps
// them and the move before, and --at-line 3 of the program is its own move, not the file's.
TEST(AtLine, AMoveOfASubprogramFileRunsUnderItsCallsLine) {
  interp::Toolpath path;
  path.sources.push_back({"O2000.nc", 0, 2, 1});
  const int lines[] = {1, 2, 3, 3};
  const int blocks[] = {0, 3, 4, 2};
  for (int i = 0; i < 4; ++i) path.moves.push_back(moveOn(lines[i], blocks[i], i + 1));
  path.moves[1].source = path.moves[2].source = 1;
  path.blockCount = 5;
  const ToolpathAtLine at2 = toolpathAtLine(path, 2, 3);
  ASSERT_TRUE(at2.toolpath) << at2.problem;
  EXPECT_EQ(at2.toolpath->moves.size(), 3u);
  const ToolpathAtLine at3 = toolpathAtLine(path, 3, 3);
  ASSERT_TRUE(at3.toolpath) << at3.problem;
  EXPECT_EQ(at3.toolpath->moves.size(), 4u);  // not cut after the file's line 3
}

// A cycle on line 4 (block 3) makes 4 moves, after a rapid on line 1: all 4 are kept with
// it, and its cycle start; a later cycle's start (line 7, block 6) is dropped.
TEST(AtLine, ACycleLineKeepsAllItsMovesAndOnlyTheCycleStartsBegun) {
  interp::Toolpath path;
  path.moves.push_back(moveOn(1, 0, 1));
  for (int i = 0; i < 4; ++i) path.moves.push_back(moveOn(4, 3, 2 + i));
  for (int i = 0; i < 4; ++i) path.moves.push_back(moveOn(7, 6, 6 + i));
  path.cycleStarts.push_back({3, 4, 1, RZ(60, 5), "G90"});
  path.cycleStarts.push_back({6, 7, 1, RZ(50, 5), "G90"});
  path.blockCount = 8;
  const ToolpathAtLine at4 = toolpathAtLine(path, 4, 8);
  ASSERT_TRUE(at4.toolpath) << at4.problem;
  EXPECT_EQ(at4.toolpath->moves.size(), 5u);
  ASSERT_EQ(at4.toolpath->cycleStarts.size(), 1u);
  EXPECT_EQ(at4.toolpath->cycleStarts[0].line, 4);
  EXPECT_EQ(at4.toolpath->blockCount, 4);
}

TEST(AtLine, LinesItCannotStopAtAreNamed) {
  const interp::Toolpath path = subprogramTwice();
  EXPECT_EQ(toolpathAtLine(path, 4, 6).problem, "--at-line 4: line 4 makes no move; give a line that moves the tool");
  EXPECT_EQ(toolpathAtLine(path, 7, 6).problem, "--at-line 7: the program has no line 7 (it has lines 1 to 6)");
  EXPECT_EQ(toolpathAtLine(path, 0, 6).problem, "--at-line 0: the program has no line 0 (it has lines 1 to 6)");
}

}  // namespace
}  // namespace lathesim::app
