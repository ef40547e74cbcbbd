// The toolpath as a clock: where the tool is at a moment of machine time or of travel.

#include "interp/motion/toolpath_clock.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lathesim::interp {
namespace {

Move moveOf(MoveKind kind, RZ from, RZ to, double timeS) {
  Move m;
  m.kind = kind;
  m.from = from;
  m.to = to;
  m.timeS = timeS;
  return m;
}

// By hand: a rapid (0,0)→(10,0) in 1 s, a feed down to (10,−20) in 4 s, a 2 s dwell there, a
// G03 quarter circle about (10,−30) to (20,−30) in 3 s (length 10·π/2 = 15.708).
// Machine time ends at 1, 5, 7, 10 s; travel at 10, 30, 30, 45.708 mm.
Toolpath handPath() {
  Toolpath path;
  path.startPosition = RZ(0, 0);
  path.moves.push_back(moveOf(MoveKind::Rapid, {0, 0}, {10, 0}, 1));
  path.moves.push_back(moveOf(MoveKind::Feed, {10, 0}, {10, -20}, 4));
  path.moves.push_back(moveOf(MoveKind::Dwell, {10, -20}, {10, -20}, 2));
  Move arc = moveOf(MoveKind::ArcCCW, {10, -20}, {20, -30}, 3);
  arc.center = RZ(10, -30);
  path.moves.push_back(arc);
  return path;
}

void expectAt(const ToolpathClock& clock, double t, std::size_t move, double fraction, RZ position) {
  SCOPED_TRACE(testing::Message() << "t = " << t);
  const ToolpathInstant i = clock.at(t);
  EXPECT_EQ(i.move, move);
  EXPECT_NEAR(i.fraction, fraction, 1e-12);
  EXPECT_NEAR(i.position.x(), position.x(), 1e-9);
  EXPECT_NEAR(i.position.y(), position.y(), 1e-9);
}

TEST(ToolpathClock, MachineTimePlacesTheToolByTheMovesTimes) {
  const Toolpath path = handPath();
  const ToolpathClock clock(path, Pace::MachineTime);
  EXPECT_DOUBLE_EQ(clock.total(), 10.0);
  EXPECT_DOUBLE_EQ(clock.endOf(1), 5.0);
  expectAt(clock, -1.0, 0, 0.0, {0, 0});  // clamped to the start
  expectAt(clock, 0.5, 0, 0.5, {5, 0});
  expectAt(clock, 1.0, 1, 0.0, {10, 0});  // a move's end is the next one's start
  expectAt(clock, 3.0, 1, 0.5, {10, -10});
  expectAt(clock, 6.0, 2, 0.5, {10, -20});  // dwelling
  const double h = 10 / std::sqrt(2.0);
  expectAt(clock, 8.5, 3, 0.5, {10 + h, -30 + h});  // half way round the arc: 45°
  expectAt(clock, 10.0, 4, 1.0, {20, -30});         // past the last move
  expectAt(clock, 99.0, 4, 1.0, {20, -30});
}

TEST(ToolpathClock, TravelSkipsTheDwellAndCountsTheArcsLength) {
  const Toolpath path = handPath();
  const ToolpathClock clock(path, Pace::Travel);
  const double arc = 10 * M_PI / 2;
  EXPECT_NEAR(clock.total(), 30 + arc, 1e-12);
  EXPECT_DOUBLE_EQ(pathLengthMm(path.moves[2]), 0.0);
  expectAt(clock, 20.0, 1, 0.5, {10, -10});
  expectAt(clock, 30.0, 3, 0.0, {10, -20});  // the dwell takes no travel: straight onto the arc
  const double third = 10 * M_PI / 6;        // 30° round
  expectAt(clock, 30 + third, 3, 1.0 / 3, {10 + 10 * std::sin(M_PI / 6), -30 + 10 * std::cos(M_PI / 6)});
}

TEST(ToolpathClock, AnEmptyToolpathStandsAtTheStart) {
  Toolpath path;
  path.startPosition = RZ(100, 200);
  const ToolpathClock clock(path, Pace::MachineTime);
  EXPECT_EQ(clock.total(), 0.0);
  expectAt(clock, 5.0, 0, 0.0, {100, 200});
}

}  // namespace
}  // namespace lathesim::interp
