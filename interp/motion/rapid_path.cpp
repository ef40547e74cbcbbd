#include "interp/motion/rapid_path.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace lathesim::interp {
namespace {

// Axis times closer than this (relative) arrive together: the path is straight.
constexpr double kSameTime = 1e-12;

double signOf(double value) { return value > 0 ? 1.0 : value < 0 ? -1.0 : 0.0; }

}  // namespace

void splitRapidsIntoAxisLegs(std::vector<Move>& moves, const MachineLimits& machine) {
  std::vector<Move> split;
  split.reserve(moves.size());
  for (const Move& move : moves) {
    const RZ d = move.to - move.from;
    const double tX = std::abs(d.x()) / machine.rapidXMmPerMin;
    const double tZ = std::abs(d.y()) / machine.rapidZMmPerMin;
    if (move.kind != MoveKind::Rapid || tX == 0 || tZ == 0 ||
        std::abs(tX - tZ) <= kSameTime * std::max(tX, tZ)) {
      split.push_back(move);
      continue;
    }
    // The axis that arrives first lands exactly on its end value.
    RZ corner = move.to;
    if (tX < tZ) corner.y() = move.from.y() + signOf(d.y()) * machine.rapidZMmPerMin * tX;
    else corner.x() = move.from.x() + signOf(d.x()) * machine.rapidXMmPerMin * tZ;
    Move diagonal = move;
    diagonal.to = corner;
    Move rest = move;
    rest.from = corner;
    split.push_back(diagonal);
    split.push_back(rest);
  }
  moves = std::move(split);
}

}  // namespace lathesim::interp
