#include "sim/holder_check.hpp"

#include <algorithm>

#include "geometry/convex_overlap.hpp"
#include "sim/move_sweep.hpp"
#include "sim/cut_rules.hpp"

namespace lathesim::sim {
namespace {

/// The largest revolved volume one piece of a sweep has inside `regions` (the chuck's, the tailstock's).
double volumeInside(const std::vector<ConvexPolygon>& regions, const std::vector<ConvexPolygon>& swept) {
  double largest = 0.0;
  for (const ConvexPolygon& piece : swept) {
    double volume = 0.0;
    for (const ConvexPolygon& part : regions) volume += revolvedVolumeMm3(overlapOf(piece, part));
    largest = std::max(largest, volume);
  }
  return largest;
}

}  // namespace

std::vector<ConvexPolygon> chuckRegions(const ChuckSpec& chuck, const StockSpec& stock) {
  const double bar = stock.diameterMm / 2.0;
  const double jaw = chuck.jawDiameterMm.value_or(stock.diameterMm + 40.0) / 2.0;
  const double face = chuck.faceZMm.value_or(stock.faceZMm - stock.lengthMm);
  const double back = face - chuck.gripLengthMm;
  const std::vector<RZ> jaws{{bar, back}, {jaw, back}, {jaw, face}, {bar, face}};
  const std::vector<RZ> body{{0.0, back - 100.0}, {jaw, back - 100.0}, {jaw, back}, {0.0, back}};
  return {ConvexPolygon::hullOf(jaws), ConvexPolygon::hullOf(body)};
}

void checkMoves(const CollisionChecks& checks, std::span<const interp::Move> moves, const Stock& stock,
                std::vector<Collision>& collisions) {
  const double h = stock.voxelMm();
  for (const interp::Move& move : moves) {
    if (move.kind == interp::MoveKind::Dwell) continue;
    const auto holder = checks.holders.find(move.tool);
    std::vector<ConvexPolygon> holderSwept;
    if (holder != checks.holders.end()) holderSwept = sweptPieces(move, holder->second, h);
    if (!holderSwept.empty()) {
      const double inside = stock.materialInside(RevolvedRegion(holderSwept), h);
      if (inside > kCollisionVoxels * h * h * h) recordCollision(collisions, move, "holder_into_stock", inside);
    }
    if (checks.chuck.empty() && checks.tailstock.empty()) continue;
    std::vector<ConvexPolygon> cutterSwept;
    if (const auto cutter = checks.cutters.find(move.tool); cutter != checks.cutters.end())
      cutterSwept = sweptPieces(move, cutter->second, h);
    for (const auto& [regions, kind] : {std::pair{&checks.chuck, "into_chuck"}, std::pair{&checks.tailstock, "into_tailstock"}}) {
      if (regions->empty()) continue;
      const double inside = std::max(volumeInside(*regions, cutterSwept), volumeInside(*regions, holderSwept));
      if (inside > 0.0) recordCollision(collisions, move, kind, inside);
    }
  }
}

}  // namespace lathesim::sim
