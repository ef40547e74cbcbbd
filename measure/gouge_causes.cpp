#include "measure/gouge_causes.hpp"

#include <algorithm>
#include <set>

#include "sim/move_sweep.hpp"

namespace lathesim::measure {
namespace {

constexpr std::size_t kMaxProbesPerRegion = 400;

struct Swept {
  std::vector<ConvexPolygon> pieces;
  RZ lower, upper;
  int line;
};

bool barHeld(const RZ& p, const sim::StockSpec& stock) {
  return p.x() <= stock.diameterMm / 2 && p.x() >= stock.boreMm / 2 && p.y() <= stock.faceZMm &&
         p.y() >= stock.faceZMm - stock.lengthMm;
}

}  // namespace

void attributeGouges(DeviationReport& report, const interp::Toolpath& toolpath, const sim::ToolOutlines& tools,
                     const sim::StockSpec& stock, double voxelMm) {
  std::vector<Swept> swept;
  for (const interp::Move& move : toolpath.moves) {
    const auto tool = tools.find(move.tool);
    if (tool == tools.end()) continue;  // interp checks T words; sim would have thrown
    Swept s{sim::sweptPieces(move, tool->second, voxelMm), {0, 0}, {0, 0}, move.line};
    if (s.pieces.empty()) continue;  // a dwell sweeps nothing new
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

}  // namespace lathesim::measure
