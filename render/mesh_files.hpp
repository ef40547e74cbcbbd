#pragma once
// Files other tools open: the part as binary STL, the toolpath as VTK PolyData.

#include <filesystem>

#include "geometry/triangle_mesh.hpp"
#include "interp/move.hpp"

namespace lathesim::render {

/// Binary STL with per-facet normals. Throws std::runtime_error on I/O failure.
void writeBinaryStl(const TriangleMesh& mesh, const std::filesystem::path& stl);

/// One polyline cell per primitive move (X as radius, in part coordinates, Y = 0), with
/// cell data "line" (int), "kind" (0 rapid, 1 feed) and "feed". Throws on I/O failure.
void writeToolpathVtp(const interp::Toolpath& toolpath, const std::filesystem::path& vtp);

}  // namespace lathesim::render
