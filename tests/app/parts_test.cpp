// The bundled parts, end to end through the library: every directory in parts/ is read as
// the command would read it (setup.toml, program.nc), and its program either gives the
// diagnostic expected.toml states, or expands to the golden toolpath.csv and, simulated at
// two voxel sizes, leaves the volume expected.toml derives by hand, and takes the cycle time
// expected.toml works out by hand (when it states one). A new part directory is picked up
// without touching this file.

#include <gtest/gtest.h>

#include "tests/support/golden_rows.hpp"
#include "tests/support/volume_tolerance.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <toml++/toml.h>
#include <vector>

#include "setup/collision_checks.hpp"
#include "setup/job.hpp"
#include "setup/setup.hpp"
#include "interp/motion/cycle_time.hpp"
#include "interp/interpreter.hpp"
#include "interp/output/toolpath_csv.hpp"
#include "sim/simulate.hpp"
#include "sim/stock.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::app {
namespace {

namespace fs = std::filesystem;

using test::kPartsDir;

std::vector<std::string> partNames() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(kPartsDir))
    if (entry.is_directory()) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

using test::readFile;

/// A collision a part is meant to have (a crash worked out by hand), `[[collision]]`.
struct ExpectedCollision {
  int line = 0;
  std::string kind;
  double volumeMm3 = 0;
};

/// Where a part is meant to part off, `[parted_off]`: the block, the Z of the cut, the piece
/// that falls and the stub left in the chuck.
struct ExpectedPartOff {
  int line = 0;
  double zMm = 0;
  double volumeMm3 = 0;
  double stubVolumeMm3 = 0;
};

/// What expected.toml says: either the diagnostic, or both volumes (and the collisions and the
/// part-off, if any).
struct Expected {
  std::optional<std::string> diagnostic;
  double finalVolumeMm3 = 0;  // all the material left: after a part-off, the piece and the stub
  double removedVolumeMm3 = 0;
  std::optional<double> cycleTimeS;
  std::vector<ExpectedCollision> collisions;
  std::optional<ExpectedPartOff> partedOff;
};

Expected readExpected(const std::string& part) {
  const toml::table table = toml::parse_file((kPartsDir / part / "expected.toml").string());
  Expected expected;
  if (const auto diagnostic = table["diagnostic"].value<std::string>()) {
    expected.diagnostic = *diagnostic;
    return expected;
  }
  const auto finalVolume = table["final_volume_mm3"].value<double>();
  const auto removedVolume = table["removed_volume_mm3"].value<double>();
  if (!finalVolume || !removedVolume)
    throw std::runtime_error(part + "/expected.toml: needs diagnostic, or final_volume_mm3 and removed_volume_mm3");
  expected.finalVolumeMm3 = *finalVolume;
  expected.removedVolumeMm3 = *removedVolume;
  expected.cycleTimeS = table["cycle_time_s"].value<double>();
  if (const auto* collisions = table["collision"].as_array()) {
    for (const toml::node& node : *collisions) {
      const toml::table& c = *node.as_table();
      expected.collisions.push_back({c["line"].value<int>().value(), c["kind"].value<std::string>().value(),
                                     c["volume_mm3"].value<double>().value()});
    }
  }
  if (const auto* off = table["parted_off"].as_table()) {
    expected.partedOff = ExpectedPartOff{(*off)["line"].value<int>().value(), (*off)["z"].value<double>().value(),
                                         (*off)["volume_mm3"].value<double>().value(),
                                         (*off)["stub_volume_mm3"].value<double>().value()};
  }
  return expected;
}

setup::Setup loadPartSetup(const std::string& part) {
  const setup::SetupResult loaded = setup::loadSetup(kPartsDir / part / "setup.toml");
  if (!loaded.setup) throw std::runtime_error(part + "/setup.toml does not load");
  return *loaded.setup;
}

/// Interprets the part's program as loadJob does, naming the file "program.nc", and times
/// its moves.
interp::InterpretResult interpretPart(const std::string& part, const setup::Setup& setup) {
  interp::InterpretResult result =
      interp::interpret(readFile(kPartsDir / part / "program.nc"), "program.nc", setup::interpreterOptionsOf(setup));
  if (result.ok()) (void)interp::assignMoveTimes(result.toolpath, setup.machine);
  return result;
}

/// How far a cycle time may stray from the hand-worked one: 0.5 %.
constexpr double kCycleTimeTolerance = 0.005;

sim::ToolOutlines outlinesOf(const setup::Setup& setup) {
  sim::ToolOutlines tools;
  for (const auto& tool : setup.tools) tools.emplace(tool.number, tool.outline);
  return tools;
}

using test::volumeToleranceMm3;

struct Simulated {
  double stockVolumeMm3 = 0;
  double finalVolumeMm3 = 0;  // the stock left, and every piece that parted off
  double stubVolumeMm3 = 0;   // the stock left
  sim::SimulationResult result;
};

Simulated simulatePart(const setup::Setup& setup, const interp::Toolpath& toolpath, double voxelMm) {
  sim::Stock stock(setup.stock, voxelMm);
  Simulated out;
  out.stockVolumeMm3 = stock.volumeMm3();
  const sim::CollisionChecks checks = setup::collisionChecksOf(setup);  // holders and the chuck too
  out.result = sim::simulate(toolpath, outlinesOf(setup), stock, {{}, &checks, {}, {}});
  out.stubVolumeMm3 = out.finalVolumeMm3 = stock.volumeMm3();
  for (const auto& off : out.result.partOffs) out.finalVolumeMm3 += off.volumeMm3;
  return out;
}

class Part : public testing::TestWithParam<std::string> {};

TEST_P(Part, GivesItsExpectedDiagnosticOrToolpathAndVolume) {
  const std::string part = GetParam();
  const setup::Setup setup = loadPartSetup(part);
  const Expected expected = readExpected(part);
  const interp::InterpretResult result = interpretPart(part, setup);

  if (expected.diagnostic) {
    EXPECT_FALSE(fs::exists(kPartsDir / part / "toolpath.csv")) << part << ": an alarm part has no golden toolpath";
    ASSERT_FALSE(result.ok()) << part << ": expected " << *expected.diagnostic;
    const auto firstError = std::find_if(result.diagnostics.begin(), result.diagnostics.end(),
                                         [](const auto& d) { return d.severity == interp::Severity::Error; });
    ASSERT_NE(firstError, result.diagnostics.end());
    const std::string shown = interp::format(*firstError);
    EXPECT_EQ(shown.substr(0, shown.find('\n')), *expected.diagnostic) << part;
    return;
  }

  ASSERT_TRUE(result.ok()) << part << ": "
                           << (result.diagnostics.empty() ? "" : interp::format(result.diagnostics[0]));

  // (1) The golden toolpath, row by row.
  std::ifstream csv(kPartsDir / part / "toolpath.csv");
  ASSERT_TRUE(csv) << part << ": no toolpath.csv";
  test::expectSameRows(test::rowsOf(result.toolpath), interp::readToolpathCsv(csv), part + "/toolpath.csv");

  // (2) The cycle time, when expected.toml works it out.
  if (expected.cycleTimeS) {
    EXPECT_NEAR(interp::cycleTimeS(result.toolpath), *expected.cycleTimeS, kCycleTimeTolerance * *expected.cycleTimeS)
        << part;
  }

  // (3) The volume left and removed, at two voxel sizes.
  for (const double voxel : {0.5, 0.25}) {
    SCOPED_TRACE(testing::Message() << part << " at " << voxel << " mm voxels");
    const Simulated simulated = simulatePart(setup, result.toolpath, voxel);
    const double tolerance = volumeToleranceMm3(setup.stock, voxel);
    EXPECT_NEAR(simulated.finalVolumeMm3, expected.finalVolumeMm3, tolerance);
    EXPECT_NEAR(simulated.stockVolumeMm3 - simulated.finalVolumeMm3, expected.removedVolumeMm3, tolerance);
    // The collisions the part means to have, each within 5 % of its hand-worked volume (a crash's
    // sliver is small against the bar, so the bar's bound above would say little), and no other.
    const auto& collisions = simulated.result.collisions;
    ASSERT_EQ(collisions.size(), expected.collisions.size())
        << collisions.size() << " collision(s)" << (collisions.empty() ? "" : ", the first on line ")
        << (collisions.empty() ? "" : std::to_string(collisions[0].line));
    for (std::size_t i = 0; i < collisions.size(); ++i) {
      EXPECT_EQ(collisions[i].line, expected.collisions[i].line);
      EXPECT_EQ(collisions[i].kind, expected.collisions[i].kind);
      EXPECT_NEAR(collisions[i].volumeMm3, expected.collisions[i].volumeMm3, 0.05 * expected.collisions[i].volumeMm3);
    }
    // The part-off the part is meant to have, the piece and the stub by hand; any other part
    // keeps its material together.
    const auto& offs = simulated.result.partOffs;
    ASSERT_EQ(offs.size(), expected.partedOff ? 1u : 0u)
        << offs.size() << " part-off(s)" << (offs.empty() ? "" : ", the first on line " + std::to_string(offs[0].line));
    if (expected.partedOff) {
      EXPECT_EQ(offs[0].line, expected.partedOff->line);
      EXPECT_NEAR(offs[0].zMm, expected.partedOff->zMm, 1e-9);
      EXPECT_NEAR(offs[0].volumeMm3, expected.partedOff->volumeMm3, tolerance);
      EXPECT_NEAR(simulated.stubVolumeMm3, expected.partedOff->stubVolumeMm3, tolerance);
    }
  }
}

// The toolpath streamed is the toolpath held (interp/execution/move_pipeline.hpp): passed on
// in pieces as small as the pipeline may cut (after every move it can) or held whole, the
// part gives the same CSV byte for byte, the same parts catcher commands and the same
// diagnostics; and the job that hands its moves to a sink as loadJob makes them gives the
// same CSV as the job that collects them.
TEST_P(Part, StreamsTheSameToolpathAsItHolds) {
  const std::string part = GetParam();
  const setup::Setup setup = loadPartSetup(part);
  const std::string text = readFile(kPartsDir / part / "program.nc");
  const auto interpretIn = [&](std::size_t window) {
    interp::InterpreterOptions options = setup::interpreterOptionsOf(setup);
    options.moveWindow = window;
    interp::InterpretResult result = interp::interpret(text, "program.nc", options);
    if (result.ok()) (void)interp::assignMoveTimes(result.toolpath, setup.machine);
    return result;
  };
  const auto csvOf = [](const interp::Toolpath& toolpath) {
    std::ostringstream csv;
    interp::writeToolpathCsv(toolpath, csv);
    return csv.str();
  };
  const interp::InterpretResult whole = interpretIn(std::numeric_limits<std::size_t>::max());
  for (const std::size_t window : {std::size_t{1}, std::size_t{4}}) {
    SCOPED_TRACE(testing::Message() << part << " in pieces of " << window);
    const interp::InterpretResult pieces = interpretIn(window);
    ASSERT_EQ(pieces.diagnostics.size(), whole.diagnostics.size());
    for (std::size_t i = 0; i < whole.diagnostics.size(); ++i)
      EXPECT_EQ(interp::format(pieces.diagnostics[i]), interp::format(whole.diagnostics[i]));
    if (!whole.ok()) continue;
    EXPECT_EQ(csvOf(pieces.toolpath), csvOf(whole.toolpath));
    ASSERT_EQ(pieces.toolpath.partsCatcher.size(), whole.toolpath.partsCatcher.size());
    for (std::size_t i = 0; i < whole.toolpath.partsCatcher.size(); ++i)
      EXPECT_EQ(pieces.toolpath.partsCatcher[i].movesBefore, whole.toolpath.partsCatcher[i].movesBefore);
  }

  const setup::JobRequest request{kPartsDir / part / "program.nc", kPartsDir / part / "setup.toml", {}, {}, {}};
  const setup::Reported<std::optional<setup::Job>> heldJob = setup::loadJob(request);
  std::vector<interp::Move> streamedMoves;
  interp::MoveCollector sink(streamedMoves);
  const setup::Reported<std::optional<setup::Job>> streamedJob = setup::loadJob(request, sink);
  const std::optional<setup::Job>& held = heldJob.value;
  const std::optional<setup::Job>& streamed = streamedJob.value;
  ASSERT_EQ(held.has_value(), streamed.has_value());
  ASSERT_EQ(heldJob.diagnostics.size(), streamedJob.diagnostics.size());
  for (std::size_t i = 0; i < heldJob.diagnostics.size(); ++i)
    EXPECT_EQ(interp::format(heldJob.diagnostics[i]), interp::format(streamedJob.diagnostics[i]));
  if (!held) return;
  EXPECT_TRUE(streamed->toolpath.moves.empty());
  interp::Toolpath fromSink = streamed->toolpath;
  fromSink.moves = std::move(streamedMoves);
  EXPECT_EQ(csvOf(fromSink), csvOf(held->toolpath));
}

std::string testName(const testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(Bundled, Part, testing::ValuesIn(partNames()), testName);

TEST(Parts, IncludeTheSeedPartsAndTheDefault) {
  const std::vector<std::string> names = partNames();
  for (const char* name : {"seed000-face-taper", "seed001-taper-r20", "seed001-taper-r24", "seed004-o0003",
                           "seed004-o0006", "seed004-o0007", "seed004-o7234"})
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
}

// Seed 001's point: R taken at the blank makes a visibly different part from R taken
// at the start X. The difference must stand well clear of the volume tolerance, both
// in the hand derivations and in the simulation.
TEST(Parts, Seed001TapersDifferByMoreThanTheTolerance) {
  constexpr double kVoxelMm = 0.5;
  std::map<std::string, double> simulatedMm3;
  for (const std::string part : {"seed001-taper-r20", "seed001-taper-r24"}) {
    const setup::Setup setup = loadPartSetup(part);
    const interp::InterpretResult result = interpretPart(part, setup);
    ASSERT_TRUE(result.ok()) << part;
    simulatedMm3[part] = simulatePart(setup, result.toolpath, kVoxelMm).finalVolumeMm3;
  }
  const setup::Setup setup = loadPartSetup("seed001-taper-r24");
  const double tolerance = volumeToleranceMm3(setup.stock, kVoxelMm);
  const double expectedDifference = readExpected("seed001-taper-r20").finalVolumeMm3 -
                                    readExpected("seed001-taper-r24").finalVolumeMm3;
  // 305000/9 π − 99500/3 π = 6500/9 π ≈ 2268.9 mm³: the R-20 cone is flatter, so more is left.
  EXPECT_NEAR(expectedDifference, 6500.0 / 9.0 * M_PI, 1e-3);
  EXPECT_GT(expectedDifference, 4.0 * tolerance);
  EXPECT_GT(simulatedMm3["seed001-taper-r20"] - simulatedMm3["seed001-taper-r24"], 4.0 * tolerance);
}

}  // namespace
}  // namespace lathesim::app
