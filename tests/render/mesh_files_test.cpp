#include "render/mesh_files.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "tests/render/test_meshes.hpp"

namespace lathesim::render {
namespace {

std::vector<char> readBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

Eigen::Vector3f floatsAt(const std::vector<char>& bytes, std::size_t offset) {
  float f[3];
  std::memcpy(f, bytes.data() + offset, sizeof f);
  return {f[0], f[1], f[2]};
}

TEST(BinaryStl, SizeCountAndOutwardNormals) {
  const TriangleMesh mesh = test::cylinder(30.0, 60.0, 48, 3);
  ASSERT_TRUE(isClosedAndOriented(mesh));
  test::TempDir dir;
  const auto file = dir.path() / "part.stl";
  writeBinaryStl(mesh, file);

  const std::vector<char> bytes = readBytes(file);
  const std::size_t n = mesh.triangles.size();
  ASSERT_EQ(bytes.size(), 84 + 50 * n);
  EXPECT_NE(std::string(bytes.data(), 5), "solid");  // not mistaken for ASCII STL
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  EXPECT_EQ(count, n);

  // Facet 0 is the side triangle at angles 0 and 2π/48: its normal points radially outward,
  // at half that angle.
  const Eigen::Vector3f normal0 = floatsAt(bytes, 84);
  const double half = M_PI / 48;
  EXPECT_NEAR(normal0.x(), std::cos(half), 1e-5);
  EXPECT_NEAR(normal0.y(), std::sin(half), 1e-5);
  EXPECT_NEAR(normal0.z(), 0.0, 1e-6);
  // Its first vertex is (30, 0, 0), stored after the normal.
  const Eigen::Vector3f v0 = floatsAt(bytes, 84 + 12);
  EXPECT_FLOAT_EQ(v0.x(), 30.0f);
  EXPECT_FLOAT_EQ(v0.y(), 0.0f);
  EXPECT_FLOAT_EQ(v0.z(), 0.0f);
  // The last facet is on the z = 60 cap: +Z; the one before on the z = 0 cap: −Z.
  const Eigen::Vector3f last = floatsAt(bytes, 84 + 50 * (n - 1));
  EXPECT_NEAR(last.z(), 1.0, 1e-6);
  const Eigen::Vector3f beforeLast = floatsAt(bytes, 84 + 50 * (n - 2));
  EXPECT_NEAR(beforeLast.z(), -1.0, 1e-6);
  // Attribute byte count is zero.
  EXPECT_EQ(bytes[84 + 48], 0);
  EXPECT_EQ(bytes[84 + 49], 0);
}

TEST(BinaryStl, EmptyMeshIsAValidEmptyFile) {
  test::TempDir dir;
  const auto file = dir.path() / "empty.stl";
  writeBinaryStl(TriangleMesh{}, file);
  EXPECT_EQ(std::filesystem::file_size(file), 84u);
}

TEST(BinaryStl, UnwritablePathThrows) {
  test::TempDir dir;
  EXPECT_THROW(writeBinaryStl(test::cylinder(1, 1, 8), dir.path() / "missing" / "part.stl"),
               std::runtime_error);
}

}  // namespace
}  // namespace lathesim::render
