#include "app/gouge_causes.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace lathesim::app {
namespace {

constexpr double kArcChordErrorMm = 0.01;
constexpr std::size_t kMaxProbesPerRegion = 400;

struct Swept {
  std::vector<ConvexPolygon> pieces;
  RZ lower, upper;
  int line;
};

bool barHeld(const RZ& p, const sim::StockSpec& stock) {
  return p.x() <= stock.diameterMm / 2 && p.y() <= stock.faceZMm && p.y() >= stock.faceZMm - stock.lengthMm;
}

}  // namespace

std::vector<ConvexPolygon> sweptPieces(const interp::Move& move, const ConvexPolygon& tool) {
  if (!interp::isArc(move.kind)) return {tool.sweptAlong(move.from, move.to)};
  // Angles in the drawing view (u = Z right, v = r up); clockwise decreases them.
  const auto angle = [&](const RZ& p) { return std::atan2(p.x() - move.center.x(), p.y() - move.center.y()); };
  const double radius = (move.from - move.center).norm();
  double sweep = angle(move.to) - angle(move.from);
  if (move.kind == interp::MoveKind::ArcCW)
    while (sweep >= 0) sweep -= 2 * M_PI;
  else
    while (sweep <= 0) sweep += 2 * M_PI;
  const double maxStep = 2 * std::acos(std::max(-1.0, 1 - kArcChordErrorMm / std::max(radius, 1e-9)));
  const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / maxStep)));
  std::vector<ConvexPolygon> pieces;
  RZ previous = move.from;
  for (int s = 1; s <= steps; ++s) {
    const double a = angle(move.from) + sweep * s / steps;
    const RZ next = s == steps ? move.to : RZ(move.center + radius * RZ(std::sin(a), std::cos(a)));
    pieces.push_back(tool.sweptAlong(previous, next));
    previous = next;
  }
  return pieces;
}

void attributeGouges(DeviationReport& report, const interp::Toolpath& toolpath, const sim::ToolOutlines& tools,
                     const sim::StockSpec& stock) {
  std::vector<Swept> swept;
  for (const interp::Move& move : toolpath.moves) {
    const auto tool = tools.find(move.tool);
    if (tool == tools.end()) continue;  // interp checks T words; sim would have thrown
    Swept s{sweptPieces(move, tool->second), {0, 0}, {0, 0}, move.line};
    s.lower = s.pieces.front().lowerBound();
    s.upper = s.pieces.front().upperBound();
    for (const auto& piece : s.pieces) {
      s.lower = s.lower.cwiseMin(piece.lowerBound());
      s.upper = s.upper.cwiseMax(piece.upperBound());
    }
    swept.push_back(std::move(s));
  }
  for (DeviationRegion& region : report.regions) {
    if (!region.gouge) continue;
    std::set<int> lines;
    const std::size_t stride = std::max<std::size_t>(1, region.midpoints.size() / kMaxProbesPerRegion);
    for (std::size_t n = 0; n < region.midpoints.size(); n += stride) {
      const RZ& probe = region.midpoints[n];
      if (!barHeld(probe, stock)) continue;
      for (const Swept& s : swept) {
        if (probe.y() < s.lower.y() || probe.y() > s.upper.y() || probe.x() > std::max(s.upper.x(), -s.lower.x())) continue;
        const bool covers = std::any_of(s.pieces.begin(), s.pieces.end(),
                                        [&](const ConvexPolygon& piece) {  // a piece across the axis revolves with its mirror image
                                          return piece.signedDistance(probe) < 0 ||
                                                 piece.signedDistance(RZ(-probe.x(), probe.y())) < 0;
                                        });
        if (covers) {
          lines.insert(s.line);
          break;
        }
      }
    }
    region.lines.assign(lines.begin(), lines.end());
  }
}

}  // namespace lathesim::app
