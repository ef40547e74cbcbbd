#include "geometry/triangle_mesh.hpp"

#include <gtest/gtest.h>

namespace lathesim {
namespace {

TriangleMesh unitCube(double edge) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back(float(edge * (i & 1)), float(edge * ((i >> 1) & 1)), float(edge * ((i >> 2) & 1)));
  // Outward-facing, counter-clockwise seen from outside.
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

TEST(TriangleMesh, CubeVolumeAndClosure) {
  const TriangleMesh cube = unitCube(2.0);
  EXPECT_NEAR(enclosedVolumeMm3(cube), 8.0, 1e-9);
  EXPECT_TRUE(isClosedAndOriented(cube));
}

TEST(TriangleMesh, OpenMeshIsDetected) {
  TriangleMesh cube = unitCube(1.0);
  cube.triangles.pop_back();
  EXPECT_FALSE(isClosedAndOriented(cube));
}

TEST(TriangleMesh, FlippedTriangleIsDetected) {
  TriangleMesh cube = unitCube(1.0);
  std::swap(cube.triangles[0][1], cube.triangles[0][2]);
  EXPECT_FALSE(isClosedAndOriented(cube));
}

}  // namespace
}  // namespace lathesim
