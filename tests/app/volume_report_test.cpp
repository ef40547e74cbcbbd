// Issue 10's bar through the command: a Φ100×80 bar with its face at 0.5 keeps every block
// of its interior, and its report says so with no warning.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "sim/stock.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::app {
namespace {

TEST(VolumeReport, IssueTensBarKeepsEveryBlockThroughTheCommand) {
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
