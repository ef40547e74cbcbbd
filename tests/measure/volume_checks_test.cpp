// The checks that keep a run from reporting volumes nobody should trust, each on hand-made
// figures: issue 10's lost block (Φ100×80, face at Z0.5, 0.2 mm) among them.

#include "measure/volume_checks.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/stock.hpp"

namespace lathesim::measure {
namespace {

TriangleMesh cube(float edge) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i) m.vertices.emplace_back(edge * (i & 1), edge * ((i >> 1) & 1), edge * ((i >> 2) & 1));
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

TEST(VolumeChecks, ABarWithinTheToleranceOfItsCylinderPassesAndOneBlockShortDoesNot) {
  const sim::StockSpec bar{100.0, 80.0, 0.5};
  const double exact = M_PI * 50 * 50 * 80;                                          // 628 318.5
  const double tolerance = sim::volumeToleranceMm3(2 * M_PI * 50 * (50 + 80), 0.2);  // 408.4
  EXPECT_FALSE(barVolumeProblem(bar, exact - 0.9 * tolerance, 0.2));
  EXPECT_FALSE(barVolumeProblem(bar, exact + 0.9 * tolerance, 0.2));
  const auto problem = barVolumeProblem(bar, 561201.3, 0.2);  // what issue 10 reported
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->find("561201.3 mm³"), std::string::npos) << *problem;
  EXPECT_NE(problem->find("628318.5 mm³"), std::string::npos) << *problem;
  EXPECT_NE(problem->find("not to be trusted"), std::string::npos) << *problem;
}

TEST(VolumeChecks, LevelSetAndMeshMustAgreeWithinTheToleranceOverTheMeshSurface) {
  const TriangleMesh box = cube(10.0f);  // 1000 mm³, 600 mm²: at 0.5 mm the tolerance is 15 mm³
  EXPECT_FALSE(meshVolumeProblem(1014.0, box, 0.5));
  EXPECT_FALSE(meshVolumeProblem(986.0, box, 0.5));
  const auto problem = meshVolumeProblem(1016.0, box, 0.5);
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->find("1016.0 mm³"), std::string::npos) << *problem;
  EXPECT_NE(problem->find("15.0 mm³ tolerance"), std::string::npos) << *problem;
}

// checkMesh must give what the separate checks give, to the last bit: on a real part's mesh
// (a bar's level set meshed, tens of thousands of triangles, the terms summed across many
// parallel chunks), with a crumb beside it, a second solid, a hole, and a level-set volume
// that disagrees, over voxel sizes that make the crumb one or not.
TEST(VolumeChecks, CheckMeshAgreesExactlyWithTheSeparateChecks) {
  // Written voxel by voxel, so that it is the level set's mesh, not the few facets of the
  // revolved profile's (sim/profile_mesh.cpp).
  const sim::Stock bar(sim::StockSpec{20.0, 30.0, 0.0}, 0.5, sim::RevolvedWrites::Voxels);
  const TriangleMesh barMesh = bar.mesh(0.0);
  ASSERT_GT(barMesh.triangles.size(), 20000u);
  const auto with = [&](const std::vector<std::pair<Eigen::Vector3f, float>>& cubes, bool hole) {
    TriangleMesh mesh = barMesh;
    for (const auto& [corner, edge] : cubes) {
      TriangleMesh c = cube(edge);
      const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
      for (const auto& v : c.vertices) mesh.vertices.push_back(v + corner);
      for (const auto& t : c.triangles) mesh.triangles.push_back({first + t[0], first + t[1], first + t[2]});
    }
    if (hole) mesh.triangles.erase(mesh.triangles.begin() + 1234);
    return mesh;
  };
  const Eigen::Vector3f far(40, 0, 0), farther(60, 0, 0);
  const std::vector<TriangleMesh> meshes{with({}, false), with({{far, 0.3f}}, false), with({{far, 8.0f}}, false),
                                         with({{far, 0.3f}, {farther, 6.0f}}, false), with({{far, 0.3f}}, true),
                                         with({}, true)};
  const double exact = M_PI * 10 * 10 * 30;
  for (const TriangleMesh& original : meshes)
    for (const double voxel : {0.05, 0.2, 0.5})
      for (const double levelSet : {exact, exact * 1.01}) {
        TriangleMesh separate = original, together = original;
        const auto volume = meshVolumeProblem(levelSet, separate, voxel, "stub");
        const DroppedCrumbs crumbs = dropCrumbs(separate, voxel);
        const auto closure = meshClosureProblem(separate, "stub");
        const MeshCheck check = checkMesh(together, levelSet, voxel, "stub");
        EXPECT_EQ(check.volumeProblem, volume);
        EXPECT_EQ(check.crumbs.count, crumbs.count);
        EXPECT_EQ(check.crumbs.volumeMm3, crumbs.volumeMm3);
        EXPECT_EQ(check.closureProblem, closure);
        EXPECT_EQ(check.volumeMm3, enclosedVolumeMm3(separate));
        EXPECT_EQ(check.areaMm2, surfaceAreaMm2(separate));
        EXPECT_EQ(together.triangles, separate.triangles);
      }
  // What each case is: the checks above must have seen crumbs, holes and volume problems.
  TriangleMesh crumbAndHole = meshes[4];
  const MeshCheck seen = checkMesh(crumbAndHole, exact * 1.01, 0.5);
  EXPECT_EQ(seen.crumbs.count, 1u);
  EXPECT_TRUE(seen.closureProblem);
  EXPECT_TRUE(seen.volumeProblem);
  TriangleMesh twoSolids = meshes[2];
  const MeshCheck both = checkMesh(twoSolids, exact + 512.0, 0.5);
  EXPECT_EQ(both.crumbs.count, 0u);
  EXPECT_FALSE(both.closureProblem);
  EXPECT_NEAR(both.volumeMm3, exact + 512.0, 0.05 * 0.5 * both.areaMm2);
}

TEST(VolumeChecks, AnOpenMeshIsReported) {
  TriangleMesh box = cube(1.0f);
  EXPECT_FALSE(meshClosureProblem(box));
  box.triangles.pop_back();
  EXPECT_TRUE(meshClosureProblem(box));
}

}  // namespace
}  // namespace lathesim::measure
