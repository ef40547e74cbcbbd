#pragma once
// Reading an STL (binary or ASCII) into the plain triangle mesh, e.g. a design to check
// a part against.

#include <filesystem>
#include <optional>
#include <string>

#include "geometry/triangle_mesh.hpp"

namespace lathesim::render {

struct StlRead {
  std::optional<TriangleMesh> mesh;
  std::string problem;  // why not, when mesh is empty
};

/// The mesh with coincident vertices merged, or why it cannot be read (no file, not an
/// STL, no triangles).
StlRead readStl(const std::filesystem::path& stl);

}  // namespace lathesim::render
