#include "sim/holder_check.hpp"

#include <algorithm>

#include "geometry/convex_overlap.hpp"
#include "sim/move_sweep.hpp"
#include "sim/cut_rules.hpp"

namespace lathesim::sim {
namespace {

/// The largest revolved volume one piece of a sweep has inside the chuck.
double chuckVolume(const std::vector<ConvexPolygon>& chuck, const std::vector<ConvexPolygon>& swept) {
  double largest = 0.0;
  for (const ConvexPolygon& piece : swept) {
    double volume = 0.0;
    for (const ConvexPolygon& part : chuck) volume += revolvedVolumeMm3(overlapOf(piece, part));
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
    if (checks.chuck.empty()) continue;
    double chuck = 0.0;
    if (const auto cutter = checks.cutters.find(move.tool); cutter != checks.cutters.end())
      chuck = chuckVolume(checks.chuck, sweptPieces(move, cutter->second, h));
    chuck = std::max(chuck, chuckVolume(checks.chuck, holderSwept));
    if (chuck > 0.0) recordCollision(collisions, move, "into_chuck", chuck);
  }
}

}  // namespace lathesim::sim
