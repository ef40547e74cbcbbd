#include "sim/move_sweep.hpp"

#include "geometry/arc.hpp"

namespace lathesim::sim {

std::vector<ConvexPolygon> sweptPieces(const interp::Move& move, const ConvexPolygon& tool, double voxelMm) {
  std::vector<ConvexPolygon> pieces;
  for (const auto& [from, to] : sweptSegments(move, voxelMm)) pieces.push_back(tool.sweptAlong(from, to));
  return pieces;
}

std::vector<std::pair<RZ, RZ>> sweptSegments(const interp::Move& move, double voxelMm) {
  if (move.kind == interp::MoveKind::Dwell) return {};
  if (!interp::isArc(move.kind)) return {{move.from, move.to}};
  // An arc swept by a convex outline is not convex, so it is followed by chords: the
  // outline's hull along each chord of sub-arcs with sagitta s ≤ voxel/20. Every chord lies
  // within s of its sub-arc (on the arc's concave side) and every point of the arc within s
  // of its chord, so the union of the hulls — the outline's Minkowski sum with the polyline
  // — is within s of the exact swept region (the sum with the arc): it cuts at most s deeper
  // on the concave side and leaves at most s on the convex side. A twentieth of a voxel is
  // below what the level set resolves, so the arc is swept exactly at this resolution.
  const Arc arc(move.from, move.to, move.center, move.kind == interp::MoveKind::ArcCW);
  std::vector<std::pair<RZ, RZ>> segments;
  for (const Arc& piece : arc.split(kArcSagittaVoxels * voxelMm)) segments.emplace_back(piece.start(), piece.end());
  return segments;
}

}  // namespace lathesim::sim
