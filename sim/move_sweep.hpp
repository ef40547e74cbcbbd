#pragma once
// The (r, z) region one move sweeps with its tool outline, as convex pieces whose union
// (revolved about Z) is what the move removes.

#include <vector>

#include "geometry/convex_polygon.hpp"
#include "interp/move.hpp"

namespace lathesim::sim {

/// Arcs are followed by chords of sub-arcs whose sagitta is at most this fraction of a
/// voxel (see sweptPieces for why that bounds the error).
inline constexpr double kArcSagittaVoxels = 1.0 / 20.0;

/// The pieces `tool` sweeps along `move`: one hull for a straight move (rapid or feed), one
/// per chord for an arc, none for a dwell (the tool stands still where it already was).
std::vector<ConvexPolygon> sweptPieces(const interp::Move& move, const ConvexPolygon& tool, double voxelMm);

}  // namespace lathesim::sim
