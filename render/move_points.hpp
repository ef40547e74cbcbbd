#pragma once
// The points a move is drawn through, shared by the PNG overlay and toolpath.vtp.

#include <vector>

#include "geometry/rz.hpp"
#include "interp/base/move.hpp"

namespace lathesim::render {

/// Arcs are drawn as chords whose sagitta is at most this fraction of the radius:
/// 1/1000 gives chords of at most 2·acos(0.999) = 5.1°, 71 to a full circle, which
/// looks round at any size the image shows it.
inline constexpr double kArcDrawingSagittaPerRadius = 1e-3;

/// (radius mm, Z mm) in order: a straight move's two ends (the same point twice for a
/// dwell); for an arc its start and the end of every chord.
std::vector<RZ> movePoints(const interp::Move& move);

}  // namespace lathesim::render
