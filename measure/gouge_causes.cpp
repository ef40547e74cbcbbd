#include "measure/gouge_causes.hpp"

#include <algorithm>
#include <set>

#include "sim/move_sweep.hpp"

namespace lathesim::measure {
namespace {

constexpr std::size_t kMaxProbesPerRegion = 400;

// A point of a gouge region, and whether a move has covered it yet.
struct Probe {
  RZ at;
  std::size_t region;
  bool covered = false;
};

bool barHeld(const RZ& p, const sim::StockSpec& stock) {
  return p.x() <= stock.diameterMm / 2 && p.x() >= stock.boreMm / 2 && p.y() <= stock.faceZMm &&
         p.y() >= stock.faceZMm - stock.lengthMm;
}

}  // namespace

void attributeGouges(DeviationReport& report, const interp::MoveSpool& moves, const sim::ToolOutlines& tools,
                     const sim::StockSpec& stock, double voxelMm) {
  std::vector<Probe> probes;
  for (std::size_t r = 0; r < report.regions.size(); ++r) {
    const DeviationRegion& region = report.regions[r];
    if (!region.gouge) continue;
    const std::size_t stride = std::max<std::size_t>(1, region.midpoints.size() / kMaxProbesPerRegion);
    for (std::size_t n = 0; n < region.midpoints.size(); n += stride)
      if (barHeld(region.midpoints[n], stock)) probes.push_back({region.midpoints[n], r});
  }
  std::vector<std::set<int>> lines(report.regions.size());
  std::size_t uncovered = probes.size();
  moves.forEach([&](const interp::Move& move) {
    if (uncovered == 0) return;
    const auto tool = tools.find(move.tool);
    if (tool == tools.end()) return;  // interp checks T words; sim would have thrown
    const std::vector<ConvexPolygon> pieces = sim::sweptPieces(move, tool->second, voxelMm);
    if (pieces.empty()) return;  // a dwell sweeps nothing new
    RZ lower = pieces.front().lowerBound(), upper = pieces.front().upperBound();
    for (const auto& piece : pieces) {
      lower = lower.cwiseMin(piece.lowerBound());
      upper = upper.cwiseMax(piece.upperBound());
    }
    for (Probe& probe : probes) {
      const RZ& p = probe.at;
      if (probe.covered || p.y() < lower.y() || p.y() > upper.y() || p.x() > std::max(upper.x(), -lower.x())) continue;
      const bool covers = std::any_of(pieces.begin(), pieces.end(),
                                      [&](const ConvexPolygon& piece) {  // a piece across the axis revolves with its mirror image
                                        return piece.signedDistance(p) < 0 || piece.signedDistance(RZ(-p.x(), p.y())) < 0;
                                      });
      if (covers) {
        lines[probe.region].insert(move.line);
        probe.covered = true;
        --uncovered;
      }
    }
  });
  for (std::size_t r = 0; r < report.regions.size(); ++r)
    if (report.regions[r].gouge) report.regions[r].lines.assign(lines[r].begin(), lines[r].end());
}

}  // namespace lathesim::measure
