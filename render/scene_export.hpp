#pragma once
// The part for other programs besides STL: GLB (the part in its metal colour and the
// toolpath as coloured lines, in one binary file: what report.html's 3D view reads), glTF
// (the same as JSON), PLY and OBJ (the part's surface alone).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geometry/triangle_mesh.hpp"
#include "interp/base/move.hpp"
#include "render/crash_mark.hpp"
#include "render/part_image.hpp"

namespace lathesim::render {

/// The machine beside the part in the 3D view, as the pictures draw it (part_image.hpp): the
/// chuck's jaws, the tailstock's centre, the tool at the end with its holder at its size.
struct SceneMachine {
  std::optional<ChuckPicture> chuck;
  std::optional<TailstockPicture> tailstock;
  std::optional<ToolPicture> tool;
};

/// The part and toolpath as a GLB (glTF 2.0 binary): its JSON chunk and one binary chunk
/// holding the part's vertices and triangles as they are (no copy through VTK) and each kind
/// of move as line segments in the pictures' colours. The scene is in metres with Y up, as
/// glTF asks: the spindle axis (Z) along glTF's X, the part's X (the radius, up in every
/// picture) along glTF's Y. Each of `crashes` is a red octahedron (a twentieth of the part's
/// size across, at least 2 mm) centred where it happened, in the meridian plane. Then the
/// machine's meshes, each named "machine …" (the jaws, the tailstock, the holder, the insert)
/// in the pictures' colours and seen from both sides; report.html's view frames the rest.
/// Needs no display.
std::string partGlb(const TriangleMesh& part, const interp::Toolpath& toolpath,
                    const std::vector<CrashMark>& crashes = {}, const SceneMachine& machine = {});

/// The same scene as glTF 2.0 JSON with its buffer inline (base64).
std::string partGltf(const TriangleMesh& part, const interp::Toolpath& toolpath);

/// Each writes one file; throws std::runtime_error on failure.
void writePartGltf(const TriangleMesh& part, const interp::Toolpath& toolpath, const std::filesystem::path& file);
void writeFileBytes(const std::string& bytes, const std::filesystem::path& file);  // e.g. a GLB, as it is
void writePartPly(const TriangleMesh& part, const std::filesystem::path& file);  // binary, little-endian
void writePartObj(const TriangleMesh& part, const std::filesystem::path& file);

}  // namespace lathesim::render
