#include "geometry/mesh_shells.hpp"

#include <gtest/gtest.h>

namespace lathesim {
namespace {

// A closed box [x0, x1] × [y0, y1] × [z0, z1], outward normals, appended to `mesh`.
void addBox(TriangleMesh& mesh, const Eigen::Vector3f& low, const Eigen::Vector3f& high) {
  const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
  for (int i = 0; i < 8; ++i)
    mesh.vertices.emplace_back(i & 1 ? high.x() : low.x(), i & 2 ? high.y() : low.y(), i & 4 ? high.z() : low.z());
  const std::array<std::array<std::uint32_t, 3>, 12> faces{{{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                                            {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}}};
  for (const auto& f : faces) mesh.triangles.push_back({first + f[0], first + f[1], first + f[2]});
}

TEST(MeshShells, SeparatePiecesAreSeparateShellsWithTheirVolumes) {
  TriangleMesh mesh;
  addBox(mesh, {0, 0, 0}, {10, 10, 10});
  addBox(mesh, {20, 0, 0}, {21, 2, 3});
  const std::vector<Shell> shells = shellsOf(mesh);
  ASSERT_EQ(shells.size(), 2u);
  EXPECT_NEAR(shells[0].volumeMm3, 1000.0, 1e-6);
  EXPECT_NEAR(shells[0].areaMm2, 600.0, 1e-6);
  EXPECT_NEAR(shells[1].volumeMm3, 6.0, 1e-6);
  EXPECT_NEAR(shells[1].areaMm2, 2 * (2 + 3 + 6), 1e-6);
  EXPECT_EQ(shells[1].triangles.size(), 12u);
}

// A voxel of 0.2 mm: a 0.1 mm sheet (2V/A just under 0.1) is a crumb, a 0.3 mm one is
// not, and the part itself stays however thin it is.
TEST(MeshShells, CrumbsThinnerThanAVoxelAreDroppedAndCounted) {
  TriangleMesh mesh;
  addBox(mesh, {0, 0, 0}, {0.15f, 30, 30});      // the part: the largest shell, thin as it is
  addBox(mesh, {10, 0, 0}, {10.1f, 5, 5});       // crumb: 2V/A = 2·2.5/(50 + 2) < 0.2
  addBox(mesh, {20, 0, 0}, {20.3f, 5, 5});       // a sheet thicker than a voxel: kept
  const double before = enclosedVolumeMm3(mesh);
  const DroppedCrumbs dropped = dropCrumbs(mesh, 0.2);
  EXPECT_EQ(dropped.count, 1u);
  EXPECT_NEAR(dropped.volumeMm3, 2.5, 1e-4);
  EXPECT_EQ(shellsOf(mesh).size(), 2u);
  EXPECT_NEAR(enclosedVolumeMm3(mesh), before - 2.5, 1e-4);
  EXPECT_TRUE(isClosedAndOriented(mesh));
}

TEST(MeshShells, ASinglePartIsNeverACrumb) {
  TriangleMesh mesh;
  addBox(mesh, {0, 0, 0}, {0.05f, 30, 30});
  EXPECT_EQ(dropCrumbs(mesh, 0.2).count, 0u);
  EXPECT_EQ(mesh.triangles.size(), 12u);
}

}  // namespace
}  // namespace lathesim
