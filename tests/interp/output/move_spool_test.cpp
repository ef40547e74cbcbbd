// The move spool gives back exactly the moves written, every field, in order, as often as it
// is read; and refuses a move that still asks for a corner.

#include "interp/output/move_spool.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

namespace lathesim::interp {
namespace {

// Every field of `a` and `b` equal (Move has no operator==: its corner request is a pointer).
void expectSameMove(const Move& a, const Move& b) {
  EXPECT_EQ(a.kind, b.kind);
  EXPECT_EQ(a.from, b.from);
  EXPECT_EQ(a.to, b.to);
  EXPECT_EQ(a.center, b.center);
  EXPECT_EQ(a.dwellS, b.dwellS);
  EXPECT_EQ(a.feed, b.feed);
  EXPECT_EQ(a.feedMode, b.feedMode);
  EXPECT_EQ(a.tool, b.tool);
  EXPECT_EQ(a.toolOffset, b.toolOffset);
  EXPECT_EQ(a.offsetShift, b.offsetShift);
  EXPECT_EQ(a.workShift, b.workShift);
  EXPECT_EQ(a.noseComp, b.noseComp);
  EXPECT_EQ(a.spindleOn, b.spindleOn);
  EXPECT_EQ(a.spindleDirection, b.spindleDirection);
  EXPECT_EQ(a.spindleMode, b.spindleMode);
  EXPECT_EQ(a.spindleS, b.spindleS);
  EXPECT_EQ(a.spindleLimitRpm, b.spindleLimitRpm);
  EXPECT_EQ(a.cornerAfter, b.cornerAfter);
  EXPECT_EQ(a.timeS, b.timeS);
  EXPECT_EQ(a.block, b.block);
  EXPECT_EQ(a.line, b.line);
  EXPECT_EQ(a.column, b.column);
  EXPECT_EQ(a.cycleStep, b.cycleStep);
  EXPECT_EQ(a.source, b.source);
  EXPECT_EQ(a.thread, b.thread);
  EXPECT_EQ(a.spindleAngleDeg, b.spindleAngleDeg);
}

// Moves whose fields all differ from the defaults and from each other's: a G96 arc under G42
// with a spindle limit, a two-start thread pass along X, a dwell, a rapid of a cycle's step.
std::vector<Move> someMoves() {
  Move arc;
  arc.kind = MoveKind::ArcCCW;
  arc.from = RZ(12.5, -3.25);
  arc.to = RZ(14.125, -7.0625);
  arc.center = RZ(10.0 / 3.0, -5.5);
  arc.feed = 0.15;
  arc.feedMode = FeedMode::PerRevolution;
  arc.tool = 3;
  arc.toolOffset = 13;
  arc.offsetShift = RZ(0.4, -0.2);
  arc.workShift = RZ(0, -150.5);
  arc.noseComp = {NoseSide::Right, 0.8, 3};
  arc.spindleOn = true;
  arc.spindleDirection = SpindleDirection::CounterClockwise;
  arc.spindleMode = SpindleMode::SurfaceSpeed;
  arc.spindleS = 180;
  arc.spindleLimitRpm = 2500;
  arc.timeS = 1.0 / 7.0;
  arc.block = 41;
  arc.line = 57;
  arc.column = 3;
  arc.spindleAngleDeg = 359.875;

  Move thread;
  thread.kind = MoveKind::Thread;
  thread.from = RZ(15, 2);
  thread.to = RZ(13.5, 2);
  thread.feed = 3;
  thread.tool = 5;
  thread.thread = {3.0, false, 180.0, 2};
  thread.spindleOn = true;
  thread.spindleS = 600;
  thread.timeS = 0.05;
  thread.block = 1000000;
  thread.line = 1000001;
  thread.column = 1;
  thread.cycleStep = 2;
  thread.source = 65535;  // the last a subprogram's file can be (Toolpath::kMaxSources)
  thread.spindleAngleDeg = 180.0;

  Move dwell;
  dwell.kind = MoveKind::Dwell;
  dwell.from = dwell.to = RZ(13.5, 2);
  dwell.dwellS = 1.5;
  dwell.timeS = 1.5;
  dwell.feedMode = FeedMode::PerMinute;
  dwell.block = 7;
  dwell.line = 9;

  Move rapid;
  rapid.kind = MoveKind::Rapid;
  rapid.from = RZ(-0.0, 1e-300);
  rapid.to = RZ(1e300, -2.5e-7);
  rapid.cycleStep = 4;
  rapid.noseComp = {NoseSide::Left, 0.4, 2};
  return {arc, thread, dwell, rapid};
}

TEST(MoveSpool, ReplaysExactlyTheMovesWritten) {
  const std::vector<Move> written = someMoves();
  MoveSpool spool;
  for (const Move& m : written) spool.take(m);
  EXPECT_EQ(spool.size(), written.size());
  for (int pass = 0; pass < 2; ++pass) {  // as often as it is read
    std::vector<Move> read;
    spool.forEach([&](const Move& m) { read.push_back(m); });
    ASSERT_EQ(read.size(), written.size());
    for (std::size_t i = 0; i < read.size(); ++i) expectSameMove(read[i], written[i]);
  }
  EXPECT_FALSE(written[2].spindleLimitRpm.has_value());
}

// Copies of one move into `spool`, on lines `from` to `to` - 1.
void takeLines(MoveSpool& spool, int from, int to) {
  Move m = someMoves()[0];
  for (m.line = from; m.line < to; ++m.line) spool.take(m);
}

// The line of the reader's next move, or nullopt after the last.
std::optional<int> nextLine(MoveSpool::Reader& reader) {
  const std::optional<Move> move = reader.next();
  return move ? std::optional<int>(move->line) : std::nullopt;
}

// Writing may go on after a read; the reader reads at its own pace, 10 000 moves past any
// buffer, beside another spool's read.
TEST(MoveSpool, ReaderReadsInStepAndWritingGoesOnAfter) {
  MoveSpool first, second;
  takeLines(first, 0, 5000);
  takeLines(second, 0, 5000);
  first.forEach([](const Move&) {});
  takeLines(first, 5000, 10000);
  MoveSpool::Reader reader(first);
  int expected = 0;
  second.forEach([&](const Move& s) {
    EXPECT_EQ(s.line, expected);
    EXPECT_EQ(nextLine(reader), expected++);
  });
  for (; expected < 10000; ++expected) EXPECT_EQ(nextLine(reader), expected);
  EXPECT_EQ(nextLine(reader), std::nullopt);
}

TEST(MoveSpool, RefusesAMoveStillAskingForACorner) {
  Move m;
  m.cornerAfter = std::make_shared<const CornerRequest>();
  MoveSpool spool;
  EXPECT_THROW(spool.take(m), std::logic_error);
  EXPECT_EQ(spool.size(), 0u);
}

}  // namespace
}  // namespace lathesim::interp
