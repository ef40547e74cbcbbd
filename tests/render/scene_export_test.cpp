// The part's exports besides STL: glTF, GLB, PLY, OBJ.

#include "render/scene_export.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "render/picture_annotations.hpp"
#include "tests/render/test_meshes.hpp"

namespace lathesim::render {
namespace {

using Json = nlohmann::json;

std::string readAll(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

std::uint32_t word(const std::string& bytes, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
}

TEST(SceneExport, GlbHoldsThePartAndTheToolpathInMetresWithYUp) {
  ::unsetenv("DISPLAY");
  const TriangleMesh part = test::cylinder(30.0, 60.0, 48, 2);
  const std::string glb = partGlb(part, test::rapidThenFeed());
  ASSERT_GT(glb.size(), 20u);
  EXPECT_EQ(word(glb, 0), 0x46546C67u);  // "glTF"
  EXPECT_EQ(word(glb, 4), 2u);
  EXPECT_EQ(word(glb, 8), glb.size());
  const std::uint32_t jsonLength = word(glb, 12);
  EXPECT_EQ(word(glb, 16), 0x4E4F534Au);  // "JSON"
  const Json gltf = Json::parse(glb.substr(20, jsonLength));
  const std::size_t binAt = 20 + jsonLength;
  EXPECT_EQ(word(glb, binAt + 4), 0x004E4942u);  // "BIN"
  EXPECT_EQ(word(glb, binAt), gltf["buffers"][0]["byteLength"].get<std::uint32_t>());
  EXPECT_EQ(gltf["buffers"].size(), 1u);
  EXPECT_FALSE(gltf["buffers"][0].contains("uri"));
  for (const Json& view : gltf["bufferViews"]) {
    EXPECT_EQ(view["buffer"], 0);
    EXPECT_LE(view["byteOffset"].get<std::size_t>() + view["byteLength"].get<std::size_t>(), word(glb, binAt));
  }
  // Three meshes: the part (triangles) and the feeds and rapids (lines, mode 1).
  ASSERT_EQ(gltf["meshes"].size(), 3u);
  EXPECT_EQ(gltf["meshes"][0]["primitives"][0]["mode"], 4);
  EXPECT_EQ(gltf["meshes"][1]["primitives"][0]["mode"], 1);
  // The part's positions in mm, (±30, ±30, 0..60); the root scales them to metres and turns
  // the spindle axis (Z) onto glTF's X and the part's X onto glTF's Y.
  const Json& positions = gltf["accessors"][gltf["meshes"][0]["primitives"][0]["attributes"]["POSITION"].get<int>()];
  EXPECT_NEAR(positions["min"][0].get<double>(), -30, 1e-3);
  EXPECT_NEAR(positions["max"][2].get<double>(), 60, 1e-3);
  const Json& root = gltf["nodes"][gltf["scenes"][0]["nodes"][0].get<int>()];
  const std::vector<double> matrix = root["matrix"];
  // Column-major: part x → glTF y, part y → glTF z, part z → glTF x.
  EXPECT_EQ(matrix, (std::vector<double>{0, 0.001, 0, 0, 0, 0, 0.001, 0, 0.001, 0, 0, 0, 0, 0, 0, 1}));
  EXPECT_FALSE(gltf.contains("cameras"));
}

// The GLB's buffer holds the part's vertices and triangles exactly as the mesh has them, and
// each move as a segment from its start to its end at (r, 0, z): the feed X58 Z62 → Z10, the
// rapid X90 Z80 → X58 Z62 (radius 29 at X58). Its glTF twin carries the same buffer inline.
TEST(SceneExport, GlbHoldsThePartsVerticesAndTrianglesAsTheyAreAndEachMoveAsASegment) {
  const TriangleMesh part = test::cylinder(30.0, 60.0, 24, 3);
  const std::string glb = partGlb(part, test::rapidThenFeed());
  const std::uint32_t jsonLength = word(glb, 12);
  const Json gltf = Json::parse(glb.substr(20, jsonLength));
  const std::string binary = glb.substr(20 + jsonLength + 8);
  const auto data = [&](int accessor) {
    const Json& view = gltf["bufferViews"][gltf["accessors"][accessor]["bufferView"].get<int>()];
    return binary.substr(view["byteOffset"].get<std::size_t>(), view["byteLength"].get<std::size_t>());
  };
  const auto floats = [&](int accessor) {
    const std::string bytes = data(accessor);
    std::vector<float> values(bytes.size() / 4);
    std::memcpy(values.data(), bytes.data(), bytes.size());
    return values;
  };
  const Json& triangles = gltf["meshes"][0]["primitives"][0];
  const std::vector<float> positions = floats(triangles["attributes"]["POSITION"].get<int>());
  ASSERT_EQ(positions.size(), 3 * part.vertices.size());
  for (std::size_t v = 0; v < part.vertices.size(); ++v)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(positions[3 * v + c], part.vertices[v][c]);
  const std::string indices = data(triangles["indices"].get<int>());
  ASSERT_EQ(indices.size(), 12 * part.triangles.size());
  EXPECT_EQ(std::memcmp(indices.data(), part.triangles.data(), indices.size()), 0);
  const auto segment = [&](int mesh) {
    const Json& lines = gltf["meshes"][mesh]["primitives"][0];
    EXPECT_EQ(lines["mode"], 1);
    const std::vector<float> points = floats(lines["attributes"]["POSITION"].get<int>());
    const std::string pair = data(lines["indices"].get<int>());
    EXPECT_EQ(pair.size(), 8u);
    return points;
  };
  EXPECT_EQ(segment(1), (std::vector<float>{29, 0, 62, 29, 0, 10}));  // the feed
  EXPECT_EQ(segment(2), (std::vector<float>{45, 0, 80, 29, 0, 62}));  // the rapid
  const Json twin = Json::parse(partGltf(part, test::rapidThenFeed()));
  const std::string uri = twin["buffers"][0]["uri"];
  const std::string prefix = "data:application/octet-stream;base64,";
  ASSERT_EQ(uri.rfind(prefix, 0), 0u);
  EXPECT_EQ(uri.size() - prefix.size(), (binary.size() + 2) / 3 * 4);
  EXPECT_EQ(twin["meshes"], gltf["meshes"]);
  EXPECT_EQ(twin["accessors"], gltf["accessors"]);
}

// Each kind of move in its own mesh and colour, as the pictures draw them: feeds blue, thread
// passes green, rapids red (picture_annotations.hpp).
TEST(SceneExport, ThreadMovesAreGreenAsInThePictures) {
  ::unsetenv("DISPLAY");
  interp::Toolpath path = test::rapidThenFeed();
  path.moves.push_back(test::move(interp::MoveKind::Thread, 29, 10, 29, -20, 5, 1.5));
  const Json gltf = Json::parse(partGltf(test::cylinder(30.0, 60.0, 16), path));
  ASSERT_EQ(gltf["meshes"].size(), 4u);  // the part, feeds, threads, rapids
  std::vector<std::vector<double>> colours;
  for (const Json& mesh : gltf["meshes"]) {
    const Json& material = gltf["materials"][mesh["primitives"][0]["material"].get<int>()];
    const std::vector<double> rgba = material["pbrMetallicRoughness"]["baseColorFactor"];
    colours.push_back({rgba[0], rgba[1], rgba[2]});
  }
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(colours[1][c], kFeedColour[c], 1e-6);
    EXPECT_NEAR(colours[2][c], kThreadColour[c], 1e-6);
    EXPECT_NEAR(colours[3][c], kRapidColour[c], 1e-6);
  }
}

TEST(SceneExport, GltfCarriesItsBuffersInline) {
  ::unsetenv("DISPLAY");
  test::TempDir dir;
  writePartGltf(test::cylinder(10.0, 20.0, 16), interp::Toolpath{}, dir.path() / "part.gltf");
  const Json gltf = Json::parse(readAll(dir.path() / "part.gltf"));
  ASSERT_EQ(gltf["meshes"].size(), 1u);  // no toolpath, no lines
  for (const Json& buffer : gltf["buffers"])
    EXPECT_EQ(buffer["uri"].get<std::string>().rfind("data:application/octet-stream;base64,", 0), 0u);
}

TEST(SceneExport, PlyAndObjHoldEveryVertexAndTriangle) {
  const TriangleMesh part = test::cylinder(30.0, 60.0, 48, 2);
  test::TempDir dir;
  writePartPly(part, dir.path() / "part.ply");
  const std::string ply = readAll(dir.path() / "part.ply");
  EXPECT_EQ(ply.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
  EXPECT_NE(ply.find("element vertex " + std::to_string(part.vertices.size()) + "\n"), std::string::npos);
  EXPECT_NE(ply.find("element face " + std::to_string(part.triangles.size()) + "\n"), std::string::npos);

  writePartObj(part, dir.path() / "part.obj");
  std::istringstream obj(readAll(dir.path() / "part.obj"));
  std::size_t vertices = 0, faces = 0;
  for (std::string line; std::getline(obj, line);) vertices += line.rfind("v ", 0) == 0, faces += line.rfind("f ", 0) == 0;
  EXPECT_EQ(vertices, part.vertices.size());
  EXPECT_EQ(faces, part.triangles.size());
  EXPECT_THROW(writePartObj(part, dir.path() / "no" / "part.obj"), std::runtime_error);
}

}  // namespace
}  // namespace lathesim::render
