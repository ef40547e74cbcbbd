#include "geometry/triangle_mesh.hpp"

#include <gtest/gtest.h>

#include <random>

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

// A face inside the cube, in both windings: every edge still has as many triangles each way,
// but the cube's edges it shares are used by four triangles.
TEST(TriangleMesh, AnInnerFaceBothWaysIsDetected) {
  TriangleMesh cube = unitCube(1.0);
  const auto inner = cube.triangles[0];
  cube.triangles.push_back(inner);
  cube.triangles.push_back({inner[0], inner[2], inner[1]});
  EXPECT_FALSE(isClosedAndOriented(cube));
  EXPECT_FALSE(isClosedAndOriented(TriangleMesh{}));
}

TEST(TriangleMesh, AreaOfACube) { EXPECT_NEAR(surfaceAreaMm2(unitCube(2.0)), 24.0, 1e-9); }

// Two cubes sharing an edge (0,0,0)–(0,0,1) but with vertices of their own, as volumeToMesh
// makes them where the surface passes through voxel centres: closed as indexed, but the
// STL, read by position, has that edge shared by four triangles.
TEST(TriangleMesh, WeldingShowsAnEdgeSharedByFourTriangles) {
  TriangleMesh two = unitCube(1.0);
  const TriangleMesh second = unitCube(1.0);
  const auto offset = static_cast<std::uint32_t>(two.vertices.size());
  for (const auto& v : second.vertices) two.vertices.push_back(v - Eigen::Vector3f(1, 1, 0));
  for (const auto& t : second.triangles) two.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  ASSERT_TRUE(isClosedAndOriented(two));
  weldCoincidentVertices(two);
  EXPECT_EQ(two.vertices.size(), 14u);  // 16 corners, two of them shared
  EXPECT_FALSE(isClosedAndOriented(two));
  EXPECT_NEAR(enclosedVolumeMm3(two), 2.0, 1e-9);
}

// A quad split into a real triangle and a sliver whose corners weld into one point: the
// sliver shows as degenerate until it is dropped.
TEST(TriangleMesh, CollapsedTrianglesAreSeenAndDropped) {
  TriangleMesh cube = unitCube(1.0);
  // Vertex 0 again, as a separate vertex, and a sliver from it along the edge 0–1.
  cube.vertices.push_back(cube.vertices[0]);
  cube.triangles.push_back({0, 8, 1});
  weldCoincidentVertices(cube);
  EXPECT_EQ(cube.vertices.size(), 8u);
  EXPECT_FALSE(isClosedAndOriented(cube));
  EXPECT_EQ(dropCollapsedTriangles(cube), 1u);
  EXPECT_TRUE(isClosedAndOriented(cube));
}

TEST(TriangleMesh, MinusZeroIsTheSamePositionAsZero) {
  TriangleMesh cube = unitCube(1.0);
  cube.vertices.push_back(Eigen::Vector3f(-0.0f, 0.0f, -0.0f));
  cube.triangles[0][0] = 8;  // was vertex 0 at (0, 0, 0)
  weldCoincidentVertices(cube);
  EXPECT_EQ(cube.vertices.size(), 8u);
  EXPECT_TRUE(isClosedAndOriented(cube));
}

// Welding against its definition, worked out the slow way: vertex v becomes the first vertex
// at its position, and those first vertices are kept in their order. Positions drawn from a
// small set so that most recur, some as -0.
TEST(TriangleMesh, WeldingKeepsTheFirstVertexAtEachPositionInOrder) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> coordinate(-2, 2);
  for (int round = 0; round < 20; ++round) {
    TriangleMesh mesh;
    const auto value = [&] { const int c = coordinate(random); return c == 0 && random() % 2 ? -0.0f : 0.5f * c; };
    for (int v = 0; v < 300; ++v) mesh.vertices.emplace_back(value(), value(), value());
    std::uniform_int_distribution<std::uint32_t> vertex(0, 299);
    for (int t = 0; t < 200; ++t) mesh.triangles.push_back({vertex(random), vertex(random), vertex(random)});
    std::vector<Eigen::Vector3f> expectedVertices;
    std::vector<std::uint32_t> expectedIndex(mesh.vertices.size());
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
      std::size_t first = 0;
      while (!(mesh.vertices[first] == mesh.vertices[v])) ++first;  // == takes -0 for +0
      if (first == v) {
        expectedIndex[v] = static_cast<std::uint32_t>(expectedVertices.size());
        expectedVertices.push_back(mesh.vertices[v]);
      } else {
        expectedIndex[v] = expectedIndex[first];
      }
    }
    auto expectedTriangles = mesh.triangles;
    for (auto& t : expectedTriangles)
      for (auto& corner : t) corner = expectedIndex[corner];
    weldCoincidentVertices(mesh);
    ASSERT_EQ(mesh.vertices.size(), expectedVertices.size());
    for (std::size_t v = 0; v < expectedVertices.size(); ++v) EXPECT_EQ(mesh.vertices[v], expectedVertices[v]);
    EXPECT_EQ(mesh.triangles, expectedTriangles);
  }
}

// Closure against its definition, checked the slow way: every directed edge once and its
// reverse once. Small random meshes over few vertices, so that every case occurs: closed
// ones (a cube's triangles with some reversed or repeated), open, doubled, degenerate.
TEST(TriangleMesh, ClosureIsEachDirectedEdgeOnceAndItsReverseOnce) {
  std::mt19937 random(11);
  const TriangleMesh cube = unitCube(1.0);
  int closedSeen = 0, openSeen = 0;
  for (int round = 0; round < 400; ++round) {
    TriangleMesh mesh = cube;
    mesh.triangles.clear();
    for (const auto& t : cube.triangles) {
      const unsigned change = random() % 40;
      if (change == 0) continue;                                                          // a hole
      if (change == 1) mesh.triangles.push_back({t[0], t[2], t[1]});                     // reversed
      else if (change == 2) mesh.triangles.push_back({t[0], t[0], t[1]});                 // degenerate
      else mesh.triangles.push_back(change == 3 ? std::array{t[1], t[2], t[0]} : t);      // the same, rotated or not
      if (change == 4) mesh.triangles.push_back(t);                                       // twice
    }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const auto& t : mesh.triangles)
      for (int i = 0; i < 3; ++i) edges.emplace_back(t[i], t[(i + 1) % 3]);
    bool expected = !mesh.triangles.empty();
    for (const auto& [a, b] : edges)
      expected = expected && a != b && std::count(edges.begin(), edges.end(), std::pair{a, b}) == 1 &&
                 std::count(edges.begin(), edges.end(), std::pair{b, a}) == 1;
    EXPECT_EQ(isClosedAndOriented(mesh), expected) << "round " << round;
    (expected ? closedSeen : openSeen)++;
  }
  EXPECT_GT(closedSeen, 10);
  EXPECT_GT(openSeen, 10);
}

}  // namespace
}  // namespace lathesim
