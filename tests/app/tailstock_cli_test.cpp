// [machine] tailstock through the command: a facing cut to the axis at the bar's face runs
// into the centre (a crash, "into_tailstock", at its line); turning the outside clear of it
// does not; a tailstock without its keys is an error at its line.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/lathesim_process.hpp"

namespace lathesim::app {
namespace {

using Json = nlohmann::json;

// A Φ40 × 60 bar, its face at Z0, a Φ20 quill whose centre's point is at Z0: the cone is r 0
// at Z0 and r 10 at Z17.32, the quill r 10 from there to Z77.32.
constexpr const char* kTailstockSetup = "[stock]\ndiameter = 40.0\nlength = 60.0\n[machine]\ntailstock = { z = 0.0, diameter = 20.0 }\n";

test::ProcessOutcome run(const test::ScratchDir& scratch, const std::string& program) {
  test::writeFile(scratch.path() / "setup.toml", kTailstockSetup);
  test::writeFile(scratch.path() / "part.nc", program);
  return test::lathesim({"run", (scratch.path() / "part.nc").string(), "--setup", (scratch.path() / "setup.toml").string(),
                         "--out", (scratch.path() / "out").string(), "--outputs", "report"},
                        scratch.path());
}

TEST(TailstockCli, FacingToTheAxisRunsIntoTheCentre) {
  test::ScratchDir scratch("tailstock-crash");
  // The default tool reaches 12 mm from its programmed point towards +X and +Z: at Z1 down to
  // X-1 it sweeps r −0.5 .. 11.5, Z1 .. 13, where the cone is r 0.58 .. 7.5 wide.
  const auto outcome = run(scratch, "G21 G99\nT0101\nG97 S1000 M03\nG00 X44 Z1\nG01 X-1 F0.1\nG00 X44\nM30\n");
  EXPECT_EQ(outcome.status, 4) << outcome.err;  // a crash
  EXPECT_NE(outcome.err.find(":5:1: error: tool 1 runs into the tailstock's centre or quill"), std::string::npos)
      << outcome.err;
  const Json report = Json::parse(test::readFile(scratch.path() / "out" / "report.json"));
  ASSERT_FALSE(report.at("collisions").empty());
  EXPECT_EQ(report.at("collisions")[0].at("kind"), "into_tailstock");
  EXPECT_EQ(report.at("collisions")[0].at("line"), 5);
  EXPECT_GT(report.at("collisions")[0].at("volume_mm3").get<double>(), 0.0);
}

TEST(TailstockCli, TurningTheOutsideStaysClearOfIt) {
  test::ScratchDir scratch("tailstock-clear");
  // r 18 .. 30 and Z1 .. 13 at the most: the cone is r ≤ 7.5 there, the quill r ≤ 10.
  // (Out at a feed: the sharp tool's lower flank leaves a sliver a rapid would hit.)
  const auto outcome = run(scratch, "G21 G99\nT0101\nG97 S1000 M03\nG00 X44 Z1\nG01 X36 F0.1\nG01 Z-20\nG01 X44\nM30\n");
  EXPECT_EQ(outcome.status, 0) << outcome.err;
  const Json report = Json::parse(test::readFile(scratch.path() / "out" / "report.json"));
  EXPECT_TRUE(report.at("collisions").empty()) << report.at("collisions").dump();
}

TEST(TailstockCli, ATailstockWithoutItsDiameterIsAnErrorAtItsLine) {
  test::ScratchDir scratch("tailstock-bad");
  test::writeFile(scratch.path() / "setup.toml", "[machine]\ntailstock = { z = 0.0 }\n");
  test::writeFile(scratch.path() / "part.nc", "G00 X100 Z100\nM30\n");
  const auto outcome = test::lathesim({"run", (scratch.path() / "part.nc").string(), "--setup",
                                       (scratch.path() / "setup.toml").string(), "--out", (scratch.path() / "out").string()},
                                      scratch.path());
  EXPECT_EQ(outcome.status, 1) << outcome.err;  // bad input
  EXPECT_NE(outcome.err.find("setup.toml:2:13: error: machine.tailstock needs diameter"), std::string::npos) << outcome.err;
  EXPECT_FALSE(std::filesystem::exists(scratch.path() / "out"));
  test::writeFile(scratch.path() / "setup.toml", "[machine]\ntailstock = { z = 0.0, diameter = -3.0, length = 5 }\n");
  const auto both = test::lathesim({"run", (scratch.path() / "part.nc").string(), "--setup",
                                    (scratch.path() / "setup.toml").string(), "--out", (scratch.path() / "out").string()},
                                   scratch.path());
  EXPECT_EQ(both.status, 1);
  EXPECT_NE(both.err.find("unknown key 'machine.tailstock.length' (expected z, diameter)"), std::string::npos) << both.err;
  EXPECT_NE(both.err.find("machine.tailstock.diameter must be a positive number of mm"), std::string::npos) << both.err;
}

}  // namespace
}  // namespace lathesim::app
