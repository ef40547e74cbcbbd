#pragma once
// A solid of revolution as triangles, from its section: what the animation draws each frame,
// a mesh sized for the picture rather than for the part's voxels.

#include <vector>

#include "geometry/rz.hpp"
#include "geometry/triangle_mesh.hpp"

namespace lathesim {

/// The surface each polyline (r, z) sweeps turning once about the Z axis in `angularSteps`
/// equal steps, the material on the polyline's right (r across, z up; as profilePolylines
/// gives them) so that the triangles face outwards. A point on the axis (r ≤ 1e-9 mm) is one
/// vertex, not a ring. Polylines that close the section (loops, or ends on the axis) give a
/// closed mesh.
TriangleMesh revolvedMesh(const std::vector<std::vector<RZ>>& polylines, int angularSteps);

/// The fewest steps (at least 12) for which a circle of `radiusMm` drawn as chords strays
/// at most `toleranceMm` from the true circle.
int angularStepsFor(double radiusMm, double toleranceMm);

}  // namespace lathesim
