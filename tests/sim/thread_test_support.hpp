#pragma once
// What the thread-sweep tests share: a sharp 60° tool and a thread move built by hand.

#include <cmath>
#include <numbers>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "interp/move.hpp"

namespace lathesim::sim::test {

inline const double kTan30 = std::tan(std::numbers::pi / 6.0);

/// A sharp 60° V pointing at the axis, `heightMm` tall: its apex the programmed point.
inline ConvexPolygon sharpVee(double heightMm) {
  const std::vector<RZ> v{{0, 0}, {heightMm, -heightMm * kTan30}, {heightMm, heightMm * kTan30}};
  return *ConvexPolygon::fromOutline(v).polygon;
}

/// A thread move of tool 1 on line 1, the spindle turning at 500 rpm in `direction`.
inline interp::Move threadMove(RZ from, RZ to, double leadMm, double startDeg, interp::SpindleDirection direction) {
  interp::Move m;
  m.kind = interp::MoveKind::Thread;
  m.from = from;
  m.to = to;
  m.feed = leadMm;
  m.thread = {leadMm, true, startDeg, 1};
  m.tool = 1;
  m.line = 1;
  m.column = 1;
  m.spindleOn = true;
  m.spindleS = 500;
  m.spindleDirection = direction;
  return m;
}

}  // namespace lathesim::sim::test
