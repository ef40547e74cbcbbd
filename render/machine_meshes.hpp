#pragma once
// The machine beside the part as triangle meshes in part coordinates (mm, Z the spindle axis,
// the meridian plane y = 0): the chuck's jaws, the tailstock's centre, the tool's insert and
// holder — for the 3D view (scene_export.hpp) and the pictures' actors (scene_actors.hpp).

#include <vector>

#include "geometry/triangle_mesh.hpp"
#include "render/part_image.hpp"

namespace lathesim::render {

/// How wide a jaw is across, either side of its middle plane, per mm of the jaws' outer radius.
inline constexpr double kJawHalfWidthPerRadius = 0.18;

/// The three jaws (the first straight up, +X) as closed boxes, outward normals.
TriangleMesh jawsMesh(const ChuckPicture& chuck);

/// The tailstock's centre and quill, revolved, closed.
TriangleMesh tailstockMesh(const TailstockPicture& tailstock);

/// A convex outline of the meridian plane ([radial, axial] mm from `position`) extruded across
/// it from y = yLow to yHigh, closed.
TriangleMesh slabMesh(const std::vector<RZ>& outline, const RZ& position, double yLow, double yHigh);

}  // namespace lathesim::render
