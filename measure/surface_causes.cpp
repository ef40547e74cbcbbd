#include "measure/surface_causes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/move_sweep.hpp"

namespace lathesim::measure {

std::vector<std::optional<SurfaceMaker>> surfaceMakers(const std::vector<SurfacePoint>& points, const interp::MoveSpool& moves,
                                                       const sim::ToolOutlines& tools, double voxelMm, double reachMm) {
  std::vector<std::optional<SurfaceMaker>> makers(points.size());
  int xLine = 0, zLine = 0;
  std::vector<double> nearest(points.size(), std::numeric_limits<double>::infinity());
  std::vector<double> alongness(points.size(), 0);  // of the maker: |cos| of its path to the surface
  const double tie = reachMm / 10;
  moves.forEach([&](const interp::Move& move) {
    if (move.to.x() != move.from.x()) xLine = move.line;
    if (move.to.y() != move.from.y()) zLine = move.line;
    if (!interp::isCutting(move.kind)) return;
    const auto tool = tools.find(move.tool);
    if (tool == tools.end()) return;  // interp checks T words; sim would have thrown
    const std::vector<ConvexPolygon> pieces = sim::sweptPieces(move, tool->second, voxelMm);
    if (pieces.empty()) return;
    RZ lower = pieces.front().lowerBound(), upper = pieces.front().upperBound();
    for (const auto& piece : pieces) {
      lower = lower.cwiseMin(piece.lowerBound());
      upper = upper.cwiseMax(piece.upperBound());
    }
    for (std::size_t n = 0; n < points.size(); ++n) {
      const RZ& p = points[n].at;
      if (p.y() < lower.y() - reachMm || p.y() > upper.y() + reachMm ||
          p.x() > std::max(upper.x(), -lower.x()) + reachMm)
        continue;
      double distance = std::numeric_limits<double>::infinity();
      for (const ConvexPolygon& piece : pieces)  // a piece across the axis revolves with its mirror image
        distance = std::min({distance, piece.signedDistance(p), piece.signedDistance(RZ(-p.x(), p.y()))});
      const double off = std::abs(distance);
      if (off > reachMm || off > nearest[n] + tie) continue;
      const RZ path = move.to - move.from;
      const double along =
          points[n].along && path.norm() > 0 ? std::abs(path.normalized().dot(points[n].along->normalized())) : 0.0;
      const bool clearlyNearer = off < nearest[n] - tie;
      if (!clearlyNearer && along < alongness[n] - 1e-6) continue;
      nearest[n] = std::min(nearest[n], off);
      alongness[n] = along;
      makers[n] = SurfaceMaker{move.line, xLine, zLine};
    }
  });
  return makers;
}

}  // namespace lathesim::measure
