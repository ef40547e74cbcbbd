#pragma once
// The part for other programs besides STL: glTF (the part in its metal colour and the
// toolpath as coloured lines, as VTK's glTF exporter writes them), GLB (the same in one
// binary file: what report.html's 3D view reads), PLY and OBJ (the part's surface alone).

#include <filesystem>
#include <string>

#include "geometry/triangle_mesh.hpp"
#include "interp/move.hpp"

namespace lathesim::render {

/// The part and toolpath as glTF 2.0 JSON with its buffers inline (base64). The scene is in
/// metres with Y up, as glTF asks: the spindle axis (Z) along glTF's X, the part's X (the
/// radius, up in every picture) along glTF's Y.
std::string partGltf(const TriangleMesh& part, const interp::Toolpath& toolpath);

/// The same glTF as a GLB: its JSON chunk and one binary chunk holding every buffer.
std::string gltfToGlb(const std::string& gltf);

/// Each writes one file; throws std::runtime_error on failure.
void writePartGltf(const TriangleMesh& part, const interp::Toolpath& toolpath, const std::filesystem::path& file);
void writeFileBytes(const std::string& bytes, const std::filesystem::path& file);  // e.g. a GLB, as it is
void writePartPly(const TriangleMesh& part, const std::filesystem::path& file);  // binary, little-endian
void writePartObj(const TriangleMesh& part, const std::filesystem::path& file);

}  // namespace lathesim::render
