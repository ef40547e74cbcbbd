#pragma once
// The threads a toolpath cuts, as programmed: its thread moves grouped into passes and the
// passes into threads, with what the program says of each (lead, starts, hand, root).
//
// A pass is a run of thread moves each starting where the last ended (a G32 chain, a G92 or
// G76 cut with its run-out). A thread is a run of passes of one tool, one lead, lead axis,
// direction of travel and spindle direction, whose spans along the lead axis overlap, with
// nothing but rapids and dwells between them: the passes of one G92 or G76 block and its
// modal repetitions, or of G32 chains at growing depth.

#include <map>
#include <string>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "interp/control/dialect.hpp"
#include "interp/base/move.hpp"

namespace lathesim::measure {

struct ThreadPass {
  std::size_t firstMove = 0;  // into Toolpath::moves
  std::size_t endMove = 0;    // one past its last thread move
};

struct ProgrammedThread {
  int line = 0;          // of its first pass
  int column = 0;
  std::string code;      // as the program writes it: "G32", "G92", "G76" (or the dialect's)
  int tool = 0;
  double leadMm = 0;
  bool leadAlongZ = true;   // false: a face (scroll) thread
  int starts = 1;           // G92 L / HNC C, or G32's distinct start angles; G76: 1
  bool rightHand = true;    // M03 feeding toward the chuck: right hand (ThreadMotion's frame)
  int travelSign = -1;      // along the lead axis, of its passes' cuts
  int spindleSense = 1;     // +1 M03, −1 M04
  bool internal = false;    // the tool points away from the axis (a bore's thread)
  double rootRadiusMm = 0;  // the deepest pass's programmed point at the cut's start (a radius)
  double startAngleDeg = 0; // the last pass's start angle mod 360°/starts, in (−half, half]
  double zMinMm = 0, zMaxMm = 0;  // the span its passes' cuts cover along Z
  std::vector<ThreadPass> passes;
};

/// The threads of `toolpath`; `tools` gives each tool's outline (to tell an internal thread
/// tool, pointing outward, from an external one); `dialect` names the codes.
std::vector<ProgrammedThread> programmedThreads(const interp::Toolpath& toolpath,
                                                const std::map<int, ConvexPolygon>& tools, interp::Dialect dialect);

}  // namespace lathesim::measure
