#include "interp/motion/rapid_path.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace lathesim::interp {
namespace {

// Axis times closer than this (relative) arrive together: the path is straight.
constexpr double kSameTime = 1e-12;

double signOf(double value) { return value > 0 ? 1.0 : value < 0 ? -1.0 : 0.0; }

// Where the axis that arrives first lands, for a rapid that moves both axes at different
// times; nullopt for one that stays a single straight move.
std::optional<RZ> dogLegCorner(const Move& move, const MachineLimits& machine) {
  if (move.kind != MoveKind::Rapid) return std::nullopt;
  const RZ d = move.to - move.from;
  const double tX = std::abs(d.x()) / machine.rapidXMmPerMin;
  const double tZ = std::abs(d.y()) / machine.rapidZMmPerMin;
  if (tX == 0 || tZ == 0 || std::abs(tX - tZ) <= kSameTime * std::max(tX, tZ)) return std::nullopt;
  // The axis that arrives first lands exactly on its end value.
  RZ corner = move.to;
  if (tX < tZ) corner.y() = move.from.y() + signOf(d.y()) * machine.rapidZMmPerMin * tX;
  else corner.x() = move.from.x() + signOf(d.x()) * machine.rapidXMmPerMin * tZ;
  return corner;
}

}  // namespace

// In place, from the back: the toolpath is the largest thing the interpreter holds (a million
// blocks, a million moves), so it is not copied to add the second legs.
void splitRapidsIntoAxisLegs(std::vector<Move>& moves, const MachineLimits& machine) {
  std::size_t legs = 0;
  for (const Move& move : moves) legs += dogLegCorner(move, machine) ? 1 : 0;
  if (legs == 0) return;
  std::size_t read = moves.size();
  moves.resize(moves.size() + legs);
  std::size_t write = moves.size();
  while (write != read) {  // once they meet, the moves before stay where they are
    Move& move = moves[--read];
    const std::optional<RZ> corner = dogLegCorner(move, machine);
    if (!corner) {
      if (--write != read) moves[write] = std::move(move);
      continue;
    }
    Move rest = move;
    rest.from = *corner;
    moves[--write] = std::move(rest);
    if (--write != read) moves[write] = std::move(move);
    moves[write].to = *corner;
  }
}

}  // namespace lathesim::interp
