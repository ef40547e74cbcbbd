#include "render/move_points.hpp"

#include <algorithm>

#include "geometry/arc.hpp"

namespace lathesim::render {

std::vector<RZ> movePoints(const interp::Move& move) {
  if (!interp::isArc(move.kind)) return {move.from, move.to};
  const Arc arc(move.from, move.to, move.center, move.kind == interp::MoveKind::ArcCW);
  const double radiusMm = std::max(arc.startRadiusMm(), arc.endRadiusMm());
  std::vector<RZ> points{move.from};
  for (const Arc& chord : arc.split(kArcDrawingSagittaPerRadius * radiusMm)) points.push_back(chord.end());
  return points;
}

}  // namespace lathesim::render
