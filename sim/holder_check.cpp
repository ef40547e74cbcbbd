#include "sim/holder_check.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/convex_overlap.hpp"
#include "sim/simulate.hpp"

namespace lathesim::sim {
namespace {

/// Adds a collision, or grows the last one when it is the same line and kind.
void record(std::vector<Collision>& collisions, const interp::Move& move, const char* kind, double volumeMm3) {
  if (!collisions.empty()) {
    Collision& last = collisions.back();
    if (last.line == move.line && last.column == move.column && last.kind == kind) {
      last.volumeMm3 += volumeMm3;
      return;
    }
  }
  collisions.push_back({move.line, move.column, kind, volumeMm3});
}

/// The convex pieces `shape` sweeps along `move`: one hull for a straight move, one per chord
/// of at most 5° for an arc (the holder stands well clear of the cut, so chords this fine do
/// not change what it meets).
std::vector<ConvexPolygon> chordPieces(const interp::Move& move, const ConvexPolygon& shape) {
  if (!interp::isArc(move.kind)) return {shape.sweptAlong(move.from, move.to)};
  // Angles in the drawing view (Z right, X up), where G02 is clockwise.
  const RZ a = move.from - move.center, b = move.to - move.center;
  const double start = std::atan2(a.x(), a.y());
  double end = std::atan2(b.x(), b.y());
  const bool ccw = move.kind == interp::MoveKind::ArcCCW;
  if (ccw && end <= start) end += 2.0 * std::numbers::pi;
  if (!ccw && end >= start) end -= 2.0 * std::numbers::pi;
  const int chords = std::max(1, static_cast<int>(std::ceil(std::abs(end - start) / (5.0 * std::numbers::pi / 180.0))));
  const double radius = a.norm();
  std::vector<ConvexPolygon> pieces;
  RZ previous = move.from;
  for (int i = 1; i <= chords; ++i) {
    const double angle = start + (end - start) * i / chords;
    const RZ next = i == chords ? move.to : RZ(move.center.x() + radius * std::sin(angle), move.center.y() + radius * std::cos(angle));
    pieces.push_back(shape.sweptAlong(previous, next));
    previous = next;
  }
  return pieces;
}

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
    if (holder != checks.holders.end()) holderSwept = chordPieces(move, holder->second);
    if (!holderSwept.empty()) {
      const double inside = stock.materialInside(RevolvedRegion(holderSwept), h);
      if (inside > kCollisionVoxels * h * h * h) record(collisions, move, "holder_into_stock", inside);
    }
    if (checks.chuck.empty()) continue;
    double chuck = 0.0;
    if (const auto cutter = checks.cutters.find(move.tool); cutter != checks.cutters.end())
      chuck = chuckVolume(checks.chuck, chordPieces(move, cutter->second));
    chuck = std::max(chuck, chuckVolume(checks.chuck, holderSwept));
    if (chuck > 0.0) record(collisions, move, "into_chuck", chuck);
  }
}

}  // namespace lathesim::sim
