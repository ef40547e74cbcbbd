#pragma once
// Moves built by hand for the sim tests, as the interpreter would make them.

#include <vector>

#include "interp/base/move.hpp"
#include "sim/simulate.hpp"

namespace lathesim::sim::test {

/// A move of tool 1 with the spindle turning at 500 rpm (S0 would be a stopped spindle), made
/// by block `block` on line `line`, column 1; a cutting move at 0.1 mm/rev, an arc about
/// `center`.
inline interp::Move turningMove(interp::MoveKind kind, RZ from, RZ to, int block = 0, int line = 1,
                                RZ center = RZ(0, 0)) {
  interp::Move m;
  m.kind = kind;
  m.from = from;
  m.to = to;
  m.center = center;
  m.feed = interp::isCutting(kind) ? 0.1 : 0.0;
  m.tool = 1;
  m.block = block;
  m.line = line;
  m.column = 1;
  m.spindleOn = true;
  m.spindleS = 500;
  return m;
}

/// Tool 1: a square `sideMm` wide, its tip the corner nearest the axis at −Z.
inline ToolOutlines squareTool(double sideMm) {
  const std::vector<RZ> square{{0, 0}, {sideMm, 0}, {sideMm, sideMm}, {0, sideMm}};
  ToolOutlines tools;
  tools.emplace(1, *ConvexPolygon::fromOutline(square).polygon);
  return tools;
}

}  // namespace lathesim::sim::test
