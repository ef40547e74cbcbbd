// The checks that keep a run from reporting volumes nobody should trust, and issue 10's bar
// through the command: Φ100×80 with its face at Z0.5, at 0.2 mm, once lost a 128³ block.

#include "app/volume_checks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "sim/stock.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::app {
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

TEST(VolumeChecks, AnOpenMeshIsReported) {
  TriangleMesh box = cube(1.0f);
  EXPECT_FALSE(meshClosureProblem(box));
  box.triangles.pop_back();
  EXPECT_TRUE(meshClosureProblem(box));
}

TEST(VolumeChecks, IssueTensBarKeepsEveryBlockThroughTheCommand) {
  test::ScratchDir scratch("issue10");
  test::writeFile(scratch.path() / "bar.toml", "[stock]\ndiameter = 100.0\nlength = 80.0\nface_z = 0.5\n");
  test::writeFile(scratch.path() / "air.nc", "G00 X150 Z150\nM30\n");
  const test::ProcessOutcome outcome = test::runProcess(
      LATHESIM_BINARY,
      {"run", (scratch.path() / "air.nc").string(), "--setup", (scratch.path() / "bar.toml").string(), "--voxel", "0.2",
       "--out", (scratch.path() / "out").string()},
      scratch.path());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  EXPECT_EQ(outcome.err.find("warning"), std::string::npos) << outcome.err;
  const auto report = nlohmann::json::parse(test::readFile(scratch.path() / "out" / "report.json"));
  const double exact = M_PI * 50 * 50 * 80;
  const double barTolerance = sim::volumeToleranceMm3(2 * M_PI * 50 * (50 + 80), 0.2);
  EXPECT_NEAR(report["stock_volume_mm3"].get<double>(), exact, barTolerance);
  EXPECT_NEAR(report["final_volume_mm3"].get<double>(), exact, barTolerance);
  EXPECT_NEAR(report["mesh_volume_mm3"].get<double>(), exact, report["volume_tolerance_mm3"].get<double>());
  EXPECT_NEAR(report["volume_tolerance_mm3"].get<double>(), barTolerance, 0.01 * barTolerance);  // the STL's surface is the bar's
  EXPECT_EQ(report["mesh_crumbs"]["count"].get<int>(), 0);
  EXPECT_TRUE(report["warnings"].empty());
}

}  // namespace
}  // namespace lathesim::app
