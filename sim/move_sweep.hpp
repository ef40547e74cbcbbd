#pragma once
// The (r, z) region one move sweeps with its tool outline, as convex pieces whose union
// (revolved about Z) is what the move removes.

#include <utility>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "interp/base/move.hpp"

namespace lathesim::sim {

/// Arcs are followed by chords of sub-arcs whose sagitta is at most this fraction of a
/// voxel (see sweptPieces for why that bounds the error).
inline constexpr double kArcSagittaVoxels = 1.0 / 20.0;

/// The pieces `tool` sweeps along `move`: one hull for a straight move (rapid, feed or
/// thread), one per chord for an arc, none for a dwell (the tool stands still where it
/// already was).
std::vector<ConvexPolygon> sweptPieces(const interp::Move& move, const ConvexPolygon& tool, double voxelMm);

/// The straight segments the programmed point follows along `move`: the move itself, an
/// arc's chords (as sweptPieces), none for a dwell.
std::vector<std::pair<RZ, RZ>> sweptSegments(const interp::Move& move, double voxelMm);

}  // namespace lathesim::sim
