#include "render/scene_export.hpp"

#include <cerrno>
#include <cstdint>
#include <algorithm>
#include <array>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <nlohmann/json.hpp>
#include <vtkNew.h>
#include <vtkOBJWriter.h>
#include <vtkPLYWriter.h>

#include "render/picture_annotations.hpp"
#include "render/scene_actors.hpp"
#include "render/machine_meshes.hpp"
#include "render/move_points.hpp"
#include "render/tool_actor.hpp"
#include "render/vtk_scene.hpp"

namespace lathesim::render {
namespace {

using Json = nlohmann::json;

/// How a move is drawn, each in its own colour as in the pictures (picture_annotations.hpp).
enum class DrawnAs { Feed, Thread, Rapid };

DrawnAs drawnAs(const interp::Move& move) {
  if (move.kind == interp::MoveKind::Thread) return DrawnAs::Thread;
  return interp::isCutting(move.kind) ? DrawnAs::Feed : DrawnAs::Rapid;
}

/// The glTF scene's buffer and JSON, built straight from the mesh and the moves: each mesh's
/// positions (mm, float) and indices (uint32) appended to one binary buffer.
class GltfScene {
 public:
  /// A mesh of `mode` (4 triangles, 1 line segments) in `colour`, named "mesh<n>" unless
  /// `name` is given; `doubleSided`: drawn from both sides.
  void add(const std::vector<Eigen::Vector3f>& positions, const std::vector<std::uint32_t>& indices, int mode,
           const Rgb& colour, const std::string& name = "", bool doubleSided = false) {
    Eigen::Vector3f low = positions.front(), high = positions.front();
    for (const Eigen::Vector3f& p : positions) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
    static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float), "positions are three packed floats");
    const int position = view(positions.data(), positions.size() * sizeof(Eigen::Vector3f));
    accessors_.push_back({{"bufferView", position}, {"byteOffset", 0}, {"componentType", 5126},  // float
                          {"count", positions.size()}, {"type", "VEC3"},
                          {"min", {low.x(), low.y(), low.z()}}, {"max", {high.x(), high.y(), high.z()}}});
    const int index = view(indices.data(), indices.size() * sizeof(std::uint32_t));
    accessors_.push_back({{"bufferView", index}, {"byteOffset", 0}, {"componentType", 5125},  // uint32
                          {"count", indices.size()}, {"type", "SCALAR"}});
    // The look VTK's glTF exporter gave the pictures' actors (specular 0.3): kept as it was.
    materials_.push_back({{"pbrMetallicRoughness",
                           {{"baseColorFactor", {colour[0], colour[1], colour[2], 1.0}},
                            {"metallicFactor", 0.3},
                            {"roughnessFactor", 1.0 / 1.06}}}});
    if (doubleSided) materials_.back()["doubleSided"] = true;
    const auto n = meshes_.size();
    meshes_.push_back({{"name", name.empty() ? "mesh" + std::to_string(n) : name},
                       {"primitives", Json::array({{{"attributes", {{"POSITION", accessors_.size() - 2}}},
                                                    {"indices", accessors_.size() - 1},
                                                    {"material", n},
                                                    {"mode", mode}}})}});
  }

  /// The GLB: its JSON chunk, then the binary chunk. One root in metres, glTF's Y up: part
  /// (x, y, z) mm → glTF (z, x, y) / 1000.
  std::string glb() const {
    Json nodes = Json::array();
    for (std::size_t n = 0; n < meshes_.size(); ++n) nodes.push_back({{"mesh", n}, {"name", meshes_[n]["name"]}});
    Json children = Json::array();
    for (std::size_t n = 0; n < meshes_.size(); ++n) children.push_back(n);
    nodes.push_back({{"name", "lathesim part"},
                     {"matrix", {0, 0.001, 0, 0, 0, 0, 0.001, 0, 0.001, 0, 0, 0, 0, 0, 0, 1}},  // column-major
                     {"children", children}});
    const Json gltf = {{"asset", {{"version", "2.0"}, {"generator", "lathesim"}}},
                       {"scene", 0},
                       {"scenes", Json::array({{{"name", "lathesim"}, {"nodes", {meshes_.size()}}}})},
                       {"nodes", nodes},
                       {"meshes", meshes_},
                       {"materials", materials_},
                       {"accessors", accessors_},
                       {"bufferViews", views_},
                       {"buffers", Json::array({{{"byteLength", binary_.size()}}})}};
    std::string json = gltf.dump();
    while (json.size() % 4) json.push_back(' ');
    std::string glb;
    auto put32 = [&glb](std::uint32_t v) {
      char bytes[4];
      std::memcpy(bytes, &v, 4);  // GLB is little-endian, as this machine
      glb.append(bytes, 4);
    };
    glb.reserve(28 + json.size() + binary_.size());
    put32(0x46546C67);  // "glTF"
    put32(2);
    put32(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + binary_.size()));
    put32(static_cast<std::uint32_t>(json.size()));
    put32(0x4E4F534A);  // "JSON"
    glb += json;
    put32(static_cast<std::uint32_t>(binary_.size()));
    put32(0x004E4942);  // "BIN\0"
    glb += binary_;
    return glb;
  }

 private:
  int view(const void* data, std::size_t bytes) {  // every view's data is of 4-byte values: aligned
    views_.push_back({{"buffer", 0}, {"byteOffset", binary_.size()}, {"byteLength", bytes}});
    binary_.append(static_cast<const char*>(data), bytes);
    return static_cast<int>(views_.size() - 1);
  }

  std::string binary_;
  Json accessors_ = Json::array(), views_ = Json::array(), materials_ = Json::array(), meshes_ = Json::array();
};

/// The moves drawn as `kind` as line segments at (r, 0, z) into `scene`, if there are any.
void addMoves(GltfScene& scene, const interp::Toolpath& toolpath, DrawnAs kind, const Rgb& colour) {
  std::vector<Eigen::Vector3f> points;
  std::vector<std::uint32_t> segments;
  for (const interp::Move& move : toolpath.moves) {
    if (drawnAs(move) != kind || move.kind == interp::MoveKind::Dwell) continue;
    const std::vector<RZ> drawn = movePoints(move);
    for (std::size_t i = 0; i < drawn.size(); ++i) {
      if (i > 0) segments.insert(segments.end(), {static_cast<std::uint32_t>(points.size() - 1),
                                                  static_cast<std::uint32_t>(points.size())});
      points.emplace_back(static_cast<float>(drawn[i].x()), 0.0f, static_cast<float>(drawn[i].y()));
    }
  }
  if (!segments.empty()) scene.add(points, segments, 1, colour);
}

void addMesh(GltfScene& scene, const TriangleMesh& mesh, const Rgb& colour, const std::string& name) {
  if (mesh.triangles.empty()) return;
  const auto* first = mesh.triangles.front().data();
  scene.add(mesh.vertices, std::vector<std::uint32_t>(first, first + 3 * mesh.triangles.size()), 4, colour, name, true);
}

void addMachine(GltfScene& scene, const SceneMachine& machine) {
  if (machine.chuck) addMesh(scene, jawsMesh(*machine.chuck), kJawColour, "machine jaws");
  if (machine.tailstock) addMesh(scene, tailstockMesh(*machine.tailstock), kTailstockColour, "machine tailstock");
  if (machine.tool) {
    const ToolPicture& t = *machine.tool;
    // As the pictures draw a tool of known size (tool_actor.hpp): behind the plane, the rake
    // face a hair in front of the holder's.
    addMesh(scene, slabMesh(t.holder, t.position, -t.holderHeightMm, 0.0), kHolderColour, "machine holder");
    addMesh(scene, slabMesh(t.insert, t.position, -t.insertThicknessMm, kRakeFaceProudMm), kInsertColour,
            "machine insert");
  }
}

std::string encodeBase64(const std::string& bytes) {
  static constexpr char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  text.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const auto at = [&](std::size_t k) { return k < bytes.size() ? static_cast<unsigned char>(bytes[k]) : 0u; };
    const unsigned triple = (at(i) << 16) | (at(i + 1) << 8) | at(i + 2);
    text.push_back(alphabet[(triple >> 18) & 63]);
    text.push_back(alphabet[(triple >> 12) & 63]);
    text.push_back(i + 1 < bytes.size() ? alphabet[(triple >> 6) & 63] : '=');
    text.push_back(i + 2 < bytes.size() ? alphabet[triple & 63] : '=');
  }
  return text;
}

std::uint32_t littleEndianWord(const std::string& bytes, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
}

}  // namespace

std::string partGlb(const TriangleMesh& part, const interp::Toolpath& toolpath, const std::vector<CrashMark>& crashes,
                    const SceneMachine& machine) {
  GltfScene scene;
  if (!part.triangles.empty()) {
    static_assert(sizeof(part.triangles.front()) == 3 * sizeof(std::uint32_t), "triangles are three packed indices");
    const auto* first = part.triangles.front().data();
    scene.add(part.vertices, std::vector<std::uint32_t>(first, first + 3 * part.triangles.size()), 4, kMetalColour);
  }
  for (const auto& [kind, colour] : {std::pair{DrawnAs::Feed, kFeedColour}, std::pair{DrawnAs::Thread, kThreadColour},
                                      std::pair{DrawnAs::Rapid, kRapidColour}})
    addMoves(scene, toolpath, kind, colour);
  if (!crashes.empty()) {
    Eigen::Vector3f low = Eigen::Vector3f::Zero(), high = Eigen::Vector3f::Zero();
    if (!part.vertices.empty()) low = high = part.vertices.front();
    for (const Eigen::Vector3f& v : part.vertices) low = low.cwiseMin(v), high = high.cwiseMax(v);
    const float half = std::max(1.0f, (high - low).norm() / 40.0f);
    std::vector<Eigen::Vector3f> points;
    std::vector<std::uint32_t> triangles;
    for (const CrashMark& crash : crashes) {
      const Eigen::Vector3f centre(static_cast<float>(crash.at.x()), 0.0f, static_cast<float>(crash.at.y()));
      const auto first = static_cast<std::uint32_t>(points.size());
      for (int axis = 0; axis < 3; ++axis)
        for (const float side : {half, -half}) points.push_back(centre + side * Eigen::Vector3f::Unit(axis));
      // Corners +x 0, −x 1, +y 2, −y 3, +z 4, −z 5: eight faces, counter-clockwise seen from outside.
      for (const auto& [x, y, z] : {std::array{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5},
                                    {3, 1, 5}, {0, 3, 5}})
        for (const int corner : {x, y, z}) triangles.push_back(first + static_cast<std::uint32_t>(corner));
    }
    scene.add(points, triangles, 4, kCrashColour);
  }
  addMachine(scene, machine);
  return scene.glb();
}

std::string partGltf(const TriangleMesh& part, const interp::Toolpath& toolpath) {
  // The GLB's JSON with its binary chunk inline as a data URI.
  const std::string glb = partGlb(part, toolpath);
  const std::uint32_t jsonBytes = littleEndianWord(glb, 12);
  Json gltf = Json::parse(glb.substr(20, jsonBytes));
  const std::size_t binaryAt = 20 + jsonBytes + 8;
  gltf["buffers"][0]["uri"] =
      "data:application/octet-stream;base64," + encodeBase64(glb.substr(binaryAt, littleEndianWord(glb, 20 + jsonBytes)));
  return gltf.dump();
}

void writeFileBytes(const std::string& bytes, const std::filesystem::path& file) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  // With the system's reason (a full disk: "No space left on device").
  if (!out) throw std::runtime_error("cannot write " + file.string() + ": " + std::strerror(errno));
}

void writePartGltf(const TriangleMesh& part, const interp::Toolpath& toolpath, const std::filesystem::path& file) {
  writeFileBytes(partGltf(part, toolpath), file);
}

void writePartPly(const TriangleMesh& part, const std::filesystem::path& file) {
  const std::string name = file.string();
  vtkNew<vtkPLYWriter> writer;
  writer->SetInputData(toPolyData(part));
  writer->SetFileName(name.c_str());
  writer->SetFileTypeToBinary();
  writer->SetDataByteOrderToLittleEndian();
  if (writer->Write() != 1) throw std::runtime_error("cannot write " + name);
}

void writePartObj(const TriangleMesh& part, const std::filesystem::path& file) {
  const std::string name = file.string();
  vtkNew<vtkOBJWriter> writer;
  writer->SetInputData(toPolyData(part));
  writer->SetFileName(name.c_str());
  if (writer->Write() != 1) throw std::runtime_error("cannot write " + name);
}

}  // namespace lathesim::render
