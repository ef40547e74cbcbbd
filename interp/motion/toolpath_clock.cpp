#include "interp/motion/toolpath_clock.hpp"

#include <algorithm>

#include "geometry/arc.hpp"

namespace lathesim::interp {

double pathLengthMm(const Move& move) {
  if (move.kind == MoveKind::Dwell) return 0.0;
  if (isArc(move.kind)) return Arc(move.from, move.to, move.center, move.kind == MoveKind::ArcCW).lengthMm();
  return (move.to - move.from).norm();
}

RZ pointAlong(const Move& move, double t) {
  t = std::clamp(t, 0.0, 1.0);
  if (isArc(move.kind)) return Arc(move.from, move.to, move.center, move.kind == MoveKind::ArcCW).pointAt(t);
  return move.from + t * (move.to - move.from);
}

ToolpathClock::ToolpathClock(const Toolpath& toolpath, Pace pace) : toolpath_(toolpath) {
  ends_.reserve(toolpath.moves.size());
  double sum = 0;
  for (const Move& m : toolpath.moves) {
    sum += pace == Pace::MachineTime ? m.timeS : pathLengthMm(m);
    ends_.push_back(sum);
  }
}

ToolpathInstant ToolpathClock::at(double t) const {
  const auto& moves = toolpath_.moves;
  if (moves.empty()) return {0, 0.0, toolpath_.startPosition};
  t = std::clamp(t, 0.0, total());
  // The first move that ends after t; a move that takes no time is passed at once.
  const auto end = std::upper_bound(ends_.begin(), ends_.end(), t);
  if (end == ends_.end()) return {moves.size(), 1.0, moves.back().to};
  const std::size_t index = static_cast<std::size_t>(end - ends_.begin());
  const double begin = index == 0 ? 0.0 : ends_[index - 1];
  const double fraction = (t - begin) / (*end - begin);  // *end > t ≥ begin
  return {index, fraction, pointAlong(moves[index], fraction)};
}

}  // namespace lathesim::interp
