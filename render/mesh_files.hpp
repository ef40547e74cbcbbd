#pragma once
// Files other tools open: the part as binary STL (the toolpath as VTK PolyData: toolpath_vtp.hpp).

#include <filesystem>

#include "geometry/triangle_mesh.hpp"

namespace lathesim::render {

/// Binary STL with per-facet normals. Throws std::runtime_error on I/O failure.
void writeBinaryStl(const TriangleMesh& mesh, const std::filesystem::path& stl);

}  // namespace lathesim::render
