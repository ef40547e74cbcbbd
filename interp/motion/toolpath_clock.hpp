#pragma once
// Where the tool is at a moment of the program: the toolpath as a clock, counted in machine
// time (Move::timeS, what a stopwatch by the machine shows) or in travel (path length), for
// pictures taken at an even pace.

#include <cstddef>
#include <vector>

#include "interp/base/move.hpp"

namespace lathesim::interp {

enum class Pace {
  MachineTime,  // seconds of machine time: a long roughing pass takes long, a rapid is quick
  Travel,       // millimetres of tool path: every millimetre alike, dwells take no room
};

struct ToolpathInstant {
  std::size_t move = 0;  // the move under way (moves.size() once all are done)
  double fraction = 0;   // how far along it, 0–1 (of its length; of its time for a dwell)
  RZ position{0, 0};     // the tool's programmed point (radius, Z)
};

class ToolpathClock {
 public:
  ToolpathClock(const Toolpath& toolpath, Pace pace);

  /// The whole program's time (s) or travel (mm).
  double total() const { return ends_.empty() ? 0.0 : ends_.back(); }

  /// The clock when move `index` ends.
  double endOf(std::size_t index) const { return ends_.at(index); }

  /// The instant `t` (clamped to 0 … total): the first move that has not ended before t,
  /// or past the last move when t ≥ total. Within a move the tool is placed by the fraction
  /// of the move's time or travel gone (its path length for a move of time, even where the
  /// feed varies along it, as under G96).
  ToolpathInstant at(double t) const;

 private:
  const Toolpath& toolpath_;
  std::vector<double> ends_;  // cumulative, one per move
};

/// The length of a move's path (mm): its line or arc; 0 for a dwell.
double pathLengthMm(const Move& move);

/// The point a fraction `t` (0–1) along a move's path.
RZ pointAlong(const Move& move, double t);

}  // namespace lathesim::interp
