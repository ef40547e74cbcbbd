#pragma once
// What the thread-sweep tests share: a sharp 60° tool and a thread move built by hand.

#include <cmath>
#include <numbers>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "interp/base/move.hpp"
#include "test_moves.hpp"

namespace lathesim::sim::test {

inline const double kTan30 = std::tan(std::numbers::pi / 6.0);

/// A sharp 60° V pointing at the axis, `heightMm` tall: its apex the programmed point.
inline ConvexPolygon sharpVee(double heightMm) {
  const std::vector<RZ> v{{0, 0}, {heightMm, -heightMm * kTan30}, {heightMm, heightMm * kTan30}};
  return *ConvexPolygon::fromOutline(v).polygon;
}

/// A thread move of tool 1 on line 1, the spindle turning at 500 rpm in `direction`.
inline interp::Move threadMove(RZ from, RZ to, double leadMm, double startDeg, interp::SpindleDirection direction) {
  interp::Move m = turningMove(interp::MoveKind::Thread, from, to);
  m.feed = leadMm;
  m.thread = {leadMm, true, startDeg, 1};
  m.spindleDirection = direction;
  return m;
}

}  // namespace lathesim::sim::test
