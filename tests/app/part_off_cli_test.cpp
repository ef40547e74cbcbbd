// Tube stock and part-off through the command: --stock with a bore, report.json's parted_off,
// part.stl as the piece that fell and stub.stl as what stays in the chuck (each closed, each
// holding its volume worked out by hand), and bad tubes refused before anything is written.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/binary_stl.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::app {
namespace {

namespace fs = std::filesystem;

constexpr double kPartOffVoxelMm = 0.4;

// 5 % of a voxel layer over a tube's surface (outside, bore and both ends), as the README states.
double tolerance(double outer, double inner, double length) {
  const double surface = 2 * M_PI * (outer + inner) * length + 2 * M_PI * (outer * outer - inner * inner);
  return 0.05 * kPartOffVoxelMm * surface;
}

// A 3 mm blade programmed at its +Z corner, as the parts' setups give it.
constexpr const char* kBladeSetup =
    "[machine]\nstart = [100, 50]\n[[tool]]\nnumber = 1\npolygon = [[0, 0], [15, 0], [15, -3], [0, -3]]\n";

struct CommandRun {
  test::ProcessOutcome outcome;
  fs::path out;
};

CommandRun lathesim(const test::ScratchDir& scratch, const std::string& program, const std::string& stock,
             const std::string& setup = kBladeSetup) {
  test::writeFile(scratch.path() / "setup.toml", setup);
  test::writeFile(scratch.path() / "part.nc", program);
  CommandRun run{{}, scratch.path() / "out"};
  run.outcome = test::runProcess(LATHESIM_BINARY,
                                 {"run", (scratch.path() / "part.nc").string(), "--setup",
                                  (scratch.path() / "setup.toml").string(), "--stock", stock, "--voxel", "0.4",
                                  "--out", run.out.string()},
                                 scratch.path());
  return run;
}

// A tube Φ40 with a Φ20 bore, 50 long (Z-50..0), parted at Z-20 by G01 X18 — through the wall
// into the bore — with the Haas parts catcher on: the piece Z-20..0 falls, π(20² − 10²)·20 =
// 6000π; the stub Z-50..-23 stays, 300π·27 = 8100π; the kerf takes 300π·3 = 900π.
TEST(PartOffCli, ATubePartedOffGivesThePieceAndTheStub) {
  test::ScratchDir scratch("partoff");
  const CommandRun run = lathesim(scratch,
                           "G99 G97 S500 M03\nM36 (PARTS CATCHER ON)\nG00 X44. Z-20.\nG01 X18. F0.05\nG00 X60.\n"
                           "M37\nM30\n",
                           "D40xd20xL50");
  ASSERT_EQ(run.outcome.status, 0) << run.outcome.err;
  EXPECT_NE(run.outcome.out.find("parted off at line 4, Z-20"), std::string::npos) << run.outcome.out;
  EXPECT_TRUE(fs::exists(run.out / "stub.stl"));

  const auto report = nlohmann::json::parse(test::readFile(run.out / "report.json"));
  EXPECT_NEAR(report["stock_volume_mm3"].get<double>(), 15000 * M_PI, tolerance(20, 10, 50));
  const auto& off = report["parted_off"];
  ASSERT_TRUE(off.is_object()) << report.dump(2);
  EXPECT_EQ(off["line"], 4);
  EXPECT_EQ(off["column"], 1);
  EXPECT_EQ(off["z"], -20.0);
  EXPECT_NEAR(off["volume_mm3"].get<double>(), 6000 * M_PI, tolerance(20, 10, 20));
  EXPECT_NEAR(off["stub_volume_mm3"].get<double>(), 8100 * M_PI, tolerance(20, 10, 27));
  EXPECT_EQ(off["parts_catcher"]["code"], "M36");
  EXPECT_EQ(off["parts_catcher"]["line"], 2);
  EXPECT_EQ(off["parts_catcher"]["in_place"], true);
  // What is left is the piece and the stub; what the blade took is the kerf.
  EXPECT_NEAR(report["final_volume_mm3"].get<double>(), 14100 * M_PI, tolerance(20, 10, 50));
  EXPECT_NEAR(report["removed_volume_mm3"].get<double>(), 900 * M_PI, 0.05 * kPartOffVoxelMm * (600 + 180) * M_PI);
  EXPECT_TRUE(report["warnings"].empty()) << report["warnings"].dump(2);

  // Each STL as a reader sees it: closed, consistently oriented, and holding its own piece.
  const test::StlFacts part = test::factsOf(test::readBinaryStl(test::readFile(run.out / "part.stl")));
  EXPECT_EQ(part.degenerate, 0);
  EXPECT_EQ(part.badEdges, 0) << "of " << part.directedEdges;
  EXPECT_NEAR(part.volumeMm3, 6000 * M_PI, tolerance(20, 10, 20));
  EXPECT_NEAR(report["mesh_volume_mm3"].get<double>(), part.volumeMm3, 1e-3 * part.volumeMm3);
  const test::StlFacts stub = test::factsOf(test::readBinaryStl(test::readFile(run.out / "stub.stl")));
  EXPECT_EQ(stub.degenerate, 0);
  EXPECT_EQ(stub.badEdges, 0) << "of " << stub.directedEdges;
  EXPECT_NEAR(stub.volumeMm3, 8100 * M_PI, tolerance(20, 10, 27));
  EXPECT_NEAR(off["stub_mesh_volume_mm3"].get<double>(), stub.volumeMm3, 1e-3 * stub.volumeMm3);
}

// A groove that leaves the wall 1 mm thick parts nothing: no parted_off, no stub.stl.
TEST(PartOffCli, AGrooveThatDoesNotPartReportsNone) {
  test::ScratchDir scratch("groove");
  const CommandRun run = lathesim(scratch, "G99 G97 S500 M03\nG00 X44. Z-20.\nG01 X22. F0.05\nG00 X60.\nM30\n", "D40xd20xL50");
  ASSERT_EQ(run.outcome.status, 0) << run.outcome.err;
  EXPECT_FALSE(fs::exists(run.out / "stub.stl"));
  const auto report = nlohmann::json::parse(test::readFile(run.out / "report.json"));
  EXPECT_TRUE(report["parted_off"].is_null());
  EXPECT_NEAR(report["final_volume_mm3"].get<double>(), 15000 * M_PI - 279 * 3 * M_PI, tolerance(20, 10, 50));
}

// A finishing pass run on a full bar with a 1 mm insert sets the skin r 19…20 loose at line 5
// (tests/sim/part_off_test.cpp works it out: 955.667π mm³): no part-off. The shaft stays the
// part (part.stl holds it, no stub.stl), the skin is a located warning and a loose piece.
TEST(PartOffCli, ASkinSetLooseIsAWarningAndTheShaftStaysThePart) {
  test::ScratchDir scratch("skin");
  const CommandRun run =
      lathesim(scratch, "G99 G97 S500 M03\nT0101\nG00 X36. Z2.\nG01 Z-25. F0.1\nG01 X42. Z-28.\nG00 X60.\nM30\n",
               "D40xL50", "[machine]\nstart = [100, 50]\n[[tool]]\nnumber = 1\npolygon = [[0, 0], [1, 0], [1, 1], [0, 1]]\n");
  ASSERT_EQ(run.outcome.status, 0) << run.outcome.err;
  EXPECT_EQ(run.outcome.out.find("parted off"), std::string::npos) << run.outcome.out;
  EXPECT_NE(run.outcome.err.find("part.nc:5:1: warning: a 1.0 mm ring (Φ38.0 to Φ40.0, Z-2"), std::string::npos)
      << run.outcome.err;
  EXPECT_NE(run.outcome.err.find("comes loose at line 5"), std::string::npos) << run.outcome.err;
  EXPECT_FALSE(fs::exists(run.out / "stub.stl"));
  const auto report = nlohmann::json::parse(test::readFile(run.out / "report.json"));
  EXPECT_TRUE(report["parted_off"].is_null());
  ASSERT_EQ(report["loose_pieces"].size(), 1u) << report["loose_pieces"].dump();
  EXPECT_EQ(report["loose_pieces"][0]["line"], 5);
  const double skinMm3 = 955.667 * M_PI;
  EXPECT_NEAR(report["loose_pieces"][0]["volume_mm3"].get<double>(), skinMm3, tolerance(20, 19, 25));
  // part.stl is the shaft: the bar less what was cut and the skin.
  const test::StlFacts part = test::factsOf(test::readBinaryStl(test::readFile(run.out / "part.stl")));
  EXPECT_EQ(part.badEdges, 0);
  EXPECT_NEAR(part.volumeMm3, report["final_volume_mm3"].get<double>(), tolerance(20, 0, 50));
  EXPECT_GT(part.volumeMm3, 400 * M_PI * 50 - 3 * skinMm3);
}

// A bore as wide as the bar stops the run with nothing written: on the command line it is a bad
// command line (exit 2), in the setup a bad setup (exit 1) with the place.
TEST(PartOffCli, ABoreNotInsideTheBarIsRefused) {
  test::ScratchDir scratch("bore");
  const std::string program = "G00 X44. Z5.\nM30\n";
  const CommandRun option = lathesim(scratch, program, "D40xd40xL50");
  EXPECT_EQ(option.outcome.status, 2);
  EXPECT_NE(option.outcome.err.find("D40xd40xL50: the bore d40 must be smaller than the diameter D40"),
            std::string::npos)
      << option.outcome.err;
  EXPECT_FALSE(fs::exists(option.out));

  test::writeFile(scratch.path() / "tube.toml", "[stock]\ndiameter = 40\nbore = 45\nlength = 50\n");
  test::writeFile(scratch.path() / "part.nc", program);
  const test::ProcessOutcome setup = test::runProcess(
      LATHESIM_BINARY,
      {"run", (scratch.path() / "part.nc").string(), "--setup", (scratch.path() / "tube.toml").string(), "--out",
       (scratch.path() / "out2").string()},
      scratch.path());
  EXPECT_EQ(setup.status, 1);
  EXPECT_NE(setup.err.find("tube.toml:3:8: error: stock.bore (the tube's inside diameter, 45.0 mm) must be smaller "
                           "than stock.diameter (40.0 mm)"),
            std::string::npos)
      << setup.err;
  EXPECT_FALSE(fs::exists(scratch.path() / "out2"));
}

}  // namespace
}  // namespace lathesim::app
