// The lathesim command itself, run as a user runs it: its exit status, what it prints, and
// the files it writes (or does not write). Every test works in its own temporary folder.

#include <gtest/gtest.h>

#include "tests/support/binary_stl.hpp"
#include "tests/support/golden_rows.hpp"
#include "tests/support/lathesim_process.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <toml++/toml.h>
#include <tuple>
#include <utility>
#include <vector>

#include "interp/control/control_preset.hpp"
#include "interp/text/text_lines.hpp"
#include "interp/output/toolpath_csv.hpp"
#include "sim/stock.hpp"

namespace lathesim::app {
namespace {

namespace fs = std::filesystem;
using interp::linesOf;

using test::kPartsDir;

using test::readFile;
using test::lathesim;
using test::writeFile;
using TempDir = test::ScratchDir;
using Outcome = test::ProcessOutcome;

/// The same bound as parts_test: 5 % of a voxel layer over the bar's whole surface.
double volumeToleranceMm3(double diameterMm, double lengthMm, double voxelMm) {
  const double r = diameterMm / 2.0;
  return sim::volumeToleranceMm3(2.0 * M_PI * r * r + 2.0 * M_PI * r * lengthMm, voxelMm);
}

double expectedFinalVolumeMm3(const std::string& part) {
  const toml::table table = toml::parse_file((kPartsDir / part / "expected.toml").string());
  return table["final_volume_mm3"].value<double>().value();
}

std::vector<interp::CsvRow> goldenToolpath(const std::string& part) {
  std::ifstream in(kPartsDir / part / "toolpath.csv");
  return interp::readToolpathCsv(in);
}


using test::noOutputs;

// ---------------------------------------------------------------------------------------
// `lathesim run` on seed001-taper-r24 at 0.25 mm: one run, shared by the tests below.

constexpr const char* kPart = "seed001-taper-r24";
constexpr double kCliVoxelMm = 0.25;
constexpr double kCsvRoundingMm = 5e-5;  // toolpath.csv writes 4 decimals (a dog-leg's corner has more)
// Seed 001's bar: Φ50 × 60 (parts/seed001-taper-r24/setup.toml).
const double kTolerance = volumeToleranceMm3(50.0, 60.0, kCliVoxelMm);

class RunSeed001 : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir("run");
    out_ = dir_->path() / "out";
    outcome_ = new Outcome(lathesim({"run", (kPartsDir / kPart / "program.nc").string(), "--setup",
                                     (kPartsDir / kPart / "setup.toml").string(), "--out", out_.string(),
                                     "--voxel", "0.25"},
                                    dir_->path()));
  }
  static void TearDownTestSuite() {
    delete outcome_;
    delete dir_;
  }
  void SetUp() override { ASSERT_EQ(outcome_->status, 0) << outcome_->err; }

  static nlohmann::json report() { return nlohmann::json::parse(readFile(out_ / "report.json")); }

  static TempDir* dir_;
  static fs::path out_;
  static Outcome* outcome_;
};

TempDir* RunSeed001::dir_ = nullptr;
fs::path RunSeed001::out_;
Outcome* RunSeed001::outcome_ = nullptr;

// A threaded part (parts/g76-m30x2) at 0.25 mm: report.json's threads, the terminal's line,
// and the close-up thread.png besides the seven outputs.
TEST(RunThread, ReportsTheThreadMeasuredAndWritesItsCloseUp) {
  TempDir dir("run-thread");
  const fs::path out = dir.path() / "out";
  const fs::path part = kPartsDir / "g76-m30x2";
  const Outcome outcome = lathesim({"run", (part / "program.nc").string(), "--setup", (part / "setup.toml").string(),
                                    "--out", out.string(), "--voxel", "0.25"},
                                   dir.path());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  EXPECT_TRUE(fs::exists(out / "thread.png"));
  const std::string html = readFile(out / "report.html");
  EXPECT_NE(html.find("thread.png: a close-up of the thread of line 13"), std::string::npos);
  EXPECT_NE(html.find("<h2>Threads</h2>"), std::string::npos);
  const nlohmann::json threads = nlohmann::json::parse(readFile(out / "report.json")).at("threads");
  ASSERT_EQ(threads.size(), 1u);
  const auto& t = threads[0];
  EXPECT_EQ(t.at("line"), 13);
  EXPECT_EQ(t.at("code"), "G76");
  EXPECT_EQ(t.at("kind"), "external");
  EXPECT_EQ(t.at("programmed").at("lead_mm"), 2.0);
  EXPECT_EQ(t.at("programmed").at("hand"), "right");
  EXPECT_NEAR(t.at("programmed").at("root_diameter_mm").get<double>(), 27.546, 1e-9);
  const auto& m = t.at("measured");
  EXPECT_EQ(m.at("angles_deg").size(), 12u);
  EXPECT_NEAR(m.at("lead_mm").at("min").get<double>(), 2.0, 0.025);  // a tenth of a voxel
  EXPECT_NEAR(m.at("lead_mm").at("max").get<double>(), 2.0, 0.025);
  EXPECT_EQ(m.at("starts"), 1);
  EXPECT_EQ(m.at("hand"), "right");
  EXPECT_NEAR(m.at("minor_diameter_mm").at("mean").get<double>() / 2, 27.546 / 2, 0.25);  // a voxel
  for (const char* key : {"major_diameter_mm", "pitch_diameter_mm", "pitch_mm"})
    EXPECT_TRUE(m.contains(key)) << key;
  EXPECT_NE(outcome.out.find("thread, line 13 (G76, external): programmed lead 2.0000 mm, 1 start, right-hand; "
                             "measured lead 2.0000 mm"),
            std::string::npos)
      << outcome.out;
}

TEST_F(RunSeed001, WritesExactlyTheSevenOutputs) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(out_)) names.insert(entry.path().filename().string());
  const std::set<std::string> expected{"part.stl", "part.png", "toolpath.csv", "toolpath.vtp", "stock.vdb",
                                       "report.json", "report.html"};
  EXPECT_EQ(names, expected);  // no staged .tmp-* file left behind
  for (const auto& name : expected) EXPECT_GT(fs::file_size(out_ / name), 0u) << name;
}

TEST_F(RunSeed001, ReportHasTheRunsFigures) {
  const nlohmann::json r = report();
  // The program as given on the command line (or its file name: either names it).
  EXPECT_EQ(fs::path(r.at("program").get<std::string>()).filename(), "program.nc");
  EXPECT_EQ(r.at("voxel_mm").get<double>(), 0.25);
  // The untouched Φ50 × 60 bar: 37500 π.
  EXPECT_NEAR(r.at("stock_volume_mm3").get<double>(), 37500.0 * M_PI, kTolerance);
  const double finalVolume = r.at("final_volume_mm3").get<double>();
  EXPECT_NEAR(finalVolume, expectedFinalVolumeMm3(kPart), kTolerance);
  EXPECT_NEAR(r.at("removed_volume_mm3").get<double>(), r.at("stock_volume_mm3").get<double>() - finalVolume,
              1e-6);
  EXPECT_NEAR(r.at("removed_volume_mm3").get<double>(), 13000.0 / 3.0 * M_PI, kTolerance);

  std::ifstream csv(out_ / "toolpath.csv");
  const auto csvRows = interp::readToolpathCsv(csv);
  EXPECT_EQ(r.at("moves").get<std::size_t>(), csvRows.size());
  EXPECT_EQ(r.at("moves").get<std::size_t>(), 6u);  // line 1's rapid is a dog-leg: two moves
  EXPECT_EQ(r.at("collisions"), nlohmann::json::array());

  const auto& blocks = r.at("blocks");
  ASSERT_TRUE(blocks.is_array());
  ASSERT_FALSE(blocks.empty());
  double blocksRemoved = 0;
  for (const auto& block : blocks) {
    EXPECT_TRUE(block.at("line").is_number_integer());
    blocksRemoved += block.at("removed_volume_mm3").get<double>();
  }
  // Line 2 (the G94) does all the cutting; the blocks' removals add up to the total.
  EXPECT_EQ(blocks.back().at("line"), 2);
  EXPECT_NEAR(blocksRemoved, r.at("removed_volume_mm3").get<double>(), kTolerance);

  const auto& timing = r.at("timing_s");
  for (const char* stage : {"parse", "simulate", "mesh", "render"}) {
    ASSERT_TRUE(timing.contains(stage)) << stage;
    EXPECT_GE(timing.at(stage).get<double>(), 0.0) << stage;
  }
}

// Seed 001 at M03 S500 (parts/seed001-taper-r24/expected.toml): the rapid of line 1 takes
// 0.7125 s, line 2's G94 38.536879 s (its G99 feeds at 50 mm/min), 39.249379 s in all; nothing
// to warn about.
TEST_F(RunSeed001, ReportHasTheCycleTimePerBlockAndTheWarnings) {
  const nlohmann::json r = report();
  EXPECT_NEAR(r.at("cycle_time_s").get<double>(), 39.249379, 1e-6);
  const auto& blocks = r.at("blocks");
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_NEAR(blocks[0].at("time_s").get<double>(), 0.7125, 1e-9);
  EXPECT_NEAR(blocks[1].at("time_s").get<double>(), 38.536879, 1e-6);
  const auto& warnings = r.at("warnings");
  EXPECT_TRUE(warnings.empty()) << warnings.dump();
}

// The control in force, every parameter with its manual's reference, and the travel the moves
// were checked against: seed 001's setup keeps the default preset but sets G99 at power-on; its
// travel is derived from the start X100 Z100 (also the reference) and the Φ50 × 60 bar, face Z0.
TEST_F(RunSeed001, ReportNamesTheControlAndTheTravel) {
  const nlohmann::json r = report();
  const auto& control = r.at("control");
  EXPECT_EQ(control.at("preset"), "gsk980tdi");
  const auto& parameters = control.at("parameters");
  EXPECT_EQ(parameters.size(), interp::controlParameterKeys().size());  // every one
  EXPECT_EQ(parameters.at("power_on_feed_mode").at("value"), "G99");
  EXPECT_EQ(parameters.at("power_on_feed_mode").at("set_by"), "setup");
  EXPECT_EQ(parameters.at("rapid_positioning").at("value"), "nonlinear");
  EXPECT_EQ(parameters.at("rapid_positioning").at("set_by"), "preset");
  EXPECT_EQ(parameters.at("rapid_positioning").at("manual"), "GSK No.1#7 = 0 (§3.2; G28 legs §3.15 note 3)");
  EXPECT_EQ(parameters.at("rapid_positioning").at("verified"), true);
  EXPECT_EQ(parameters.at("least_increment").at("value"), 0.001);
  EXPECT_EQ(parameters.at("tool_word").at("value"), nlohmann::json::array({"2+2"}));
  const auto& travel = r.at("travel");
  EXPECT_EQ(travel.at("x_diameter_mm"), nlohmann::json::array({-50.0, 100.0}));
  EXPECT_EQ(travel.at("z_mm"), nlohmann::json::array({-120.0, 100.0}));
  EXPECT_EQ(travel.at("x_from"), "derived from [machine] reference and start and the bar");
  // What the setup did not say: only the travel (it states the bar, its face and the start).
  EXPECT_EQ(r.at("machine").at("assumed"),
            nlohmann::json::parse(R"({"travel_x": [-50.0, 100.0], "travel_z": [-120.0, 100.0]})"));
  EXPECT_NE(outcome_->out.find("  assumed, as " + (kPartsDir / kPart / "setup.toml").string() +
                               " does not say: X travel X-50 to X100, Z travel Z-120 to Z100\n"),
            std::string::npos)
      << outcome_->out;
  // The machine said aloud: the program (G94 with X and Z, read alike in systems A and B)
  // gives no mark of its dialect, so the default is taken and said so.
  EXPECT_NE(outcome_->out.find("program.nc (dialect fanuc-a, control gsk980tdi, read from the program (no code only "
                               "one G-code system reads (G94 with X/Z: a cycle in system A, a move in system B): the "
                               "default, fanuc-a)): 6 moves"),
            std::string::npos)
      << outcome_->out;
  const auto& machine = r.at("machine");
  EXPECT_EQ(machine.at("dialect"), "fanuc-a");
  EXPECT_EQ(machine.at("control"), "gsk980tdi");
  EXPECT_EQ(machine.at("inferred"), true);
  EXPECT_EQ(machine.at("because").size(), 1u);
  EXPECT_EQ(machine.at("conflicts"), nlohmann::json::array());
}

TEST_F(RunSeed001, ToolpathCsvIsTheGoldenToolpath) {
  std::ifstream in(out_ / "toolpath.csv");
  test::expectSameRows(interp::readToolpathCsv(in), goldenToolpath(kPart), "toolpath.csv", kCsvRoundingMm);
}

TEST_F(RunSeed001, PartStlIsClosedAndHoldsTheExpectedVolume) {
  const std::vector<test::StlTriangle> triangles = test::readBinaryStl(readFile(out_ / "part.stl"));
  ASSERT_GT(triangles.size(), 0u);
  const test::StlFacts facts = test::factsOf(triangles);
  EXPECT_EQ(facts.degenerate, 0);
  EXPECT_EQ(facts.badEdges, 0) << "of " << facts.directedEdges << " directed edges";
  EXPECT_NEAR(facts.volumeMm3, expectedFinalVolumeMm3(kPart), kTolerance);
}

std::uint32_t bigEndian32(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int i = 0; i < 4; ++i) value = (value << 8) | static_cast<unsigned char>(bytes[at + i]);
  return value;
}

TEST_F(RunSeed001, PartPngIs1600By1200) {
  const std::string bytes = readFile(out_ / "part.png");
  ASSERT_GE(bytes.size(), 24u);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(bytes.substr(12, 4), "IHDR");  // the first chunk
  EXPECT_EQ(bigEndian32(bytes, 16), 1600u);
  EXPECT_EQ(bigEndian32(bytes, 20), 1200u);
}

// --outputs writes exactly the files it names and report.json; each selection over the seven
// files a plain run writes, and an export named there as --export would write it.
TEST(Cli, OutputsWritesExactlyTheFilesNamedAndTheReport) {
  const fs::path part = kPartsDir / "g71-g70-shaft";
  const std::vector<std::pair<std::string, std::set<std::string>>> cases{
      {"report", {"report.json"}},
      {"stl,csv", {"part.stl", "toolpath.csv", "report.json"}},
      {"png,vdb,html", {"part.png", "stock.vdb", "report.html", "report.json"}},
      {"vtp,report,ply", {"toolpath.vtp", "part.ply", "report.json"}}};
  for (const auto& [outputs, expected] : cases) {
    TempDir dir("outputs");
    const fs::path out = dir.path() / "out";
    const Outcome outcome = lathesim({"run", (part / "program.nc").string(), "--setup", (part / "setup.toml").string(),
                                      "--voxel", "0.5", "--outputs", outputs, "--out", out.string()},
                                     dir.path());
    ASSERT_EQ(outcome.status, 0) << outcome.err;
    std::set<std::string> written;
    for (const auto& entry : fs::directory_iterator(out)) written.insert(entry.path().filename().string());
    EXPECT_EQ(written, expected) << "--outputs " << outputs;
  }
}

TEST(Cli, AssumptionsWithNoSetupSayTheDefaultSetupGaveThem) {
  // No --setup, and the program states no bar: the default setup's start, travel and bar
  // (setup/setup.cpp defaultSetup: X200 Z200, Φ125 × 112, face Z2) are what was assumed.
  TempDir dir("no-setup-assumed");
  writeFile(dir.path() / "plain.nc", "G99 M03 S800;\nG00 X130 Z5;\nG00 X60 Z5;\nM30;\n");
  const Outcome outcome = lathesim({"run", (dir.path() / "plain.nc").string(), "--voxel", "0.5", "--outputs", "report",
                                    "--out", (dir.path() / "out").string()},
                                   dir.path());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("\n  assumed, as no setup was given (--setup), so lathesim's default setup says: start "
                             "X200 Z200, X travel X-125 to X200, Z travel Z-222 to Z200, bar Φ125 × 112, bar face at "
                             "Z2\n"),
            std::string::npos)
      << outcome.out;
}

TEST(Cli, OutputsWithAnUnknownNameIsACommandLineErrorNamingTheValidOnes) {
  TempDir dir("outputs-bad");
  const fs::path part = kPartsDir / "g71-g70-shaft";
  const fs::path out = dir.path() / "out";
  const Outcome outcome = lathesim({"run", (part / "program.nc").string(), "--setup", (part / "setup.toml").string(),
                                    "--outputs", "stl,pdf", "--out", out.string()},
                                   dir.path());
  EXPECT_EQ(outcome.status, 2);
  EXPECT_NE(outcome.err.find("pdf not in {stl,png,vdb,vtp,csv,report,html,gltf,glb,ply,obj,video}"), std::string::npos)
      << outcome.err;
  EXPECT_TRUE(noOutputs(out));
}

TEST(Cli, ExpandPrintsExactlyTheGoldenToolpath) {
  TempDir dir("expand");
  const Outcome outcome = lathesim({"expand", (kPartsDir / kPart / "program.nc").string(), "--setup",
                                    (kPartsDir / kPart / "setup.toml").string()},
                                   dir.path());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const auto lines = linesOf(outcome.out);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines[0], "line,kind,x0,z0,x1,z1,feed,xc,zc,time_s,thread_deg,spindle");
  std::istringstream in(outcome.out);
  test::expectSameRows(interp::readToolpathCsv(in), goldenToolpath(kPart), "toolpath.csv", kCsvRoundingMm);
  EXPECT_EQ(lines.size(), 1 + goldenToolpath(kPart).size());  // nothing else on stdout
}

// expand streams its rows while the program runs, but stdout gets them only when the whole
// program has run: an error after many thousand moves prints the error, nothing on stdout,
// exit 1; the same program without the bad block prints every row.
TEST(Cli, ExpandPrintsNothingWhenTheProgramFailsLate) {
  TempDir dir("expand-late-error");
  constexpr int kBlocks = 30000;  // several of the interpreter's windows of moves
  std::string program = "G99 M03 S800\nG00 X40 Z2\n";
  for (int i = 0; i < kBlocks; ++i) program += (i % 2 ? "G01 X40 Z-" : "G01 X42 Z-") + std::to_string(i % 50) + " F0.1\n";
  writeFile(dir.path() / "good.nc", program + "M30\n");
  writeFile(dir.path() / "bad.nc", program + "G01 X40 Z-1 K3\nM30\n");

  const Outcome good = lathesim({"expand", (dir.path() / "good.nc").string()}, dir.path());
  ASSERT_EQ(good.status, 0) << good.err;
  EXPECT_EQ(linesOf(good.out).size(), 1u + 2u + kBlocks);  // the header, the rapid in two legs, the cuts

  const Outcome bad = lathesim({"expand", (dir.path() / "bad.nc").string()}, dir.path());
  EXPECT_EQ(bad.status, 1);
  EXPECT_TRUE(bad.out.empty()) << bad.out.substr(0, 200);
  EXPECT_NE(bad.err.find("bad.nc:" + std::to_string(kBlocks + 3) + ":"), std::string::npos) << bad.err;
}

// An endless Macro B loop stops at the step limit, which --max-steps sets over [macro]
// max_steps; the error names the loop's WHILE.
TEST(Cli, MaxStepsStopsAnEndlessLoopAtItsWhile) {
  TempDir dir("steps");
  const fs::path program = dir.path() / "endless.nc";
  writeFile(program, "G00 X50 Z2\nWHILE [#1 LT 1] DO 1\nG00 W0\nEND 1\nM30\n");
  const fs::path setup = dir.path() / "setup.toml";
  writeFile(setup, "[macro]\nmax_steps = 100\n");
  const Outcome fromSetup = lathesim({"expand", program.string(), "--setup", setup.string()}, dir.path());
  EXPECT_EQ(fromSetup.status, 1);
  EXPECT_EQ(fromSetup.err.rfind(program.string() + ":2:1: error: the program is still in this loop after 100 blocks "
                                                   "run again", 0),
            0u)
      << fromSetup.err;
  const Outcome fromCli =
      lathesim({"expand", program.string(), "--setup", setup.string(), "--max-steps", "7"}, dir.path());
  EXPECT_EQ(fromCli.status, 1);
  EXPECT_NE(fromCli.err.find("after 7 blocks run again"), std::string::npos) << fromCli.err;
  EXPECT_TRUE(fromCli.out.empty());
}

TEST(Cli, ControlAndBlockSkipOnTheCommandLineOverrideTheSetup) {
  TempDir dir("control");
  const fs::path program = dir.path() / "p.nc";
  writeFile(program, "/G00 X20. Z10.\nG00 X40\n");
  const auto expand = [&](std::vector<std::string> extra) {
    std::vector<std::string> args{"expand", program.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return lathesim(args, dir.path());
  };
  // gsk980tdi, block skip on: line 1 skipped, so X40 (40 mm) is reached from the start X200.
  Outcome outcome = expand({});
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  EXPECT_EQ(linesOf(outcome.out).back(), "2,rapid,200,200,40,200,0,,,0.8,,");  // 80 of radius at 6000 mm/min
  // fanuc-0i-t (DPI 0): X40 is 0.04 mm; --block-skip off runs line 1.
  outcome = expand({"--control", "fanuc-0i-t", "--block-skip", "off"});
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const auto lines = linesOf(outcome.out);
  EXPECT_EQ(lines[1].rfind("1,rapid,200,200,", 0), 0u) << outcome.out;
  EXPECT_EQ(lines.back().rfind("2,rapid,20,10,0.04,10,0", 0), 0u) << outcome.out;
  // An unknown preset is refused by name.
  outcome = expand({"--control", "fanuc-10t"});
  EXPECT_NE(outcome.status, 0);
  EXPECT_NE(outcome.err.find("fanuc-10t"), std::string::npos) << outcome.err;
}

// parts/g50-shift-twice stops at M01 on line 7: report.json lists it (not timed).
TEST(Cli, ReportListsTheProgramStops) {
  TempDir dir("stops");
  const fs::path part = kPartsDir / "g50-shift-twice";
  const fs::path out = dir.path() / "out";
  const Outcome outcome = lathesim({"run", (part / "program.nc").string(), "--setup", (part / "setup.toml").string(),
                                    "--out", out.string(), "--voxel", "0.5"},
                                   dir.path());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const nlohmann::json r = nlohmann::json::parse(readFile(out / "report.json"));
  EXPECT_EQ(r.at("stops"), nlohmann::json::parse(R"([{"line": 7, "column": 1, "code": "M01"}])"));
  EXPECT_NEAR(r.at("cycle_time_s").get<double>(), 13.205, 1e-9);  // the stop adds nothing
}

// Seed 001's bar (Φ50, face Z0), the spindle turning (stopped, the rapid would cut a slot,
// not a ring). The tool goes to X54 Z5, clear of the bar, then rapids
// straight to X30 Z-10. The default tool's body lies at r ≥ tip, z ≥ tip and contains the
// square [1, 10] × [1, 10] mm from the tip, so at the end of the rapid it alone fills the
// ring r 16..25, Z-9..0 of the bar: π (25² − 16²) · 9 ≈ 10433 mm³, and the sweep more.
TEST(Cli, RapidIntoTheBarIsACrashOnItsLine) {
  TempDir dir("rapid");
  const fs::path program = dir.path() / "rapid.nc";
  writeFile(program, "M03 S500;\nG00 X54 Z5;\nG00 X30 Z-10;\n");
  const fs::path out = dir.path() / "out";
  const Outcome outcome = lathesim({"run", program.string(), "--setup", (kPartsDir / kPart / "setup.toml").string(),
                                    "--out", out.string(), "--voxel", "0.5"},
                                   dir.path());
  ASSERT_EQ(outcome.status, 4) << outcome.err;  // a crash: the outputs are written (crash_cli_test.cpp)
  const nlohmann::json r = nlohmann::json::parse(readFile(out / "report.json"));
  const auto& collisions = r.at("collisions");
  ASSERT_EQ(collisions.size(), 1u) << collisions.dump();
  EXPECT_EQ(collisions[0].at("line"), 3);
  EXPECT_EQ(collisions[0].at("kind"), "rapid_into_stock");
  const double ringMm3 = M_PI * (25.0 * 25.0 - 16.0 * 16.0) * 9.0;
  EXPECT_GT(collisions[0].at("volume_mm3").get<double>(), ringMm3 - volumeToleranceMm3(50, 60, 0.5));
  EXPECT_NEAR(collisions[0].at("volume_mm3").get<double>(), r.at("removed_volume_mm3").get<double>(),
              volumeToleranceMm3(50, 60, 0.5));
}

// ---------------------------------------------------------------------------------------
// --at-line: the part as it was after a given line (parts/seed000-face-taper: a Φ125 bar,
// Z-110..2, the sharp default-style tool at r ≥ tip, z ≥ tip).

Outcome runSeed000AtLine(const TempDir& dir, const std::string& line, const fs::path& out) {
  const fs::path part = kPartsDir / "seed000-face-taper";
  return lathesim({"run", (part / "program.nc").string(), "--setup", (part / "setup.toml").string(), "--out",
                   out.string(), "--voxel", "0.5", "--at-line", line},
                  dir.path());
}

// Line 1 rapids to X130 Z5 (a dog-leg: two moves); line 2 (G94 X0 Z0) rapids to Z0, faces in
// to the axis, feeds back to Z5 and rapids out: 6 moves. The face pass takes the 2 mm allowance off the whole face,
// leaving the bar Φ125 from Z-110 to Z0: π·62.5²·110 = 1 349 897 mm³.
// Line 3 (G94 X120 Z-110) faces the left end at Z-110 down to r 60 and turns r 60 from Z-110
// back to Z5: the bar Φ120 from Z-110 to Z0, π·60²·110 = 1 244 071 mm³, after 10 moves.
TEST(Cli, AtLineSimulatesOnlyUpToThatLine) {
  TempDir dir("at-line");
  const double tolerance = volumeToleranceMm3(125.0, 112.0, 0.5);
  for (const auto& [line, moves, volumeMm3] :
       {std::tuple{2, 6, M_PI * 62.5 * 62.5 * 110.0}, std::tuple{3, 10, M_PI * 60.0 * 60.0 * 110.0}}) {
    const fs::path out = dir.path() / ("out" + std::to_string(line));
    const Outcome outcome = runSeed000AtLine(dir, std::to_string(line), out);
    ASSERT_EQ(outcome.status, 0) << outcome.err;
    const nlohmann::json r = nlohmann::json::parse(readFile(out / "report.json"));
    EXPECT_EQ(r.at("at_line"), line);
    EXPECT_EQ(r.at("moves"), moves);
    EXPECT_NEAR(r.at("final_volume_mm3").get<double>(), volumeMm3, tolerance) << "line " << line;
    EXPECT_TRUE(fs::exists(out / "part.png"));
    EXPECT_EQ(linesOf(readFile(out / "toolpath.csv")).size(), 1u + static_cast<std::size_t>(moves));
  }
}

// parts/m98-grooves calls O0200 (lines 9–11) three times. Line 10 (the retract) first runs
// after the rapid on line 4 (a dog-leg, two moves) and the first plunge on line 9, so --at-line
// 10 keeps 4 moves and
// one groove: the Φ40 × 50 bar less the annulus r 16..20, 3 wide:
// π·20²·50 − 3·π·(20² − 16²) = 20000π − 432π = 19568π mm³. The tool stands at X44 Z-10.
TEST(Cli, AtLineOfASubprogramStopsAfterItsFirstRun) {
  TempDir dir("at-line-m98");
  const fs::path part = kPartsDir / "m98-grooves";
  const fs::path out = dir.path() / "out";
  const Outcome outcome = lathesim({"run", (part / "program.nc").string(), "--setup", (part / "setup.toml").string(),
                                    "--out", out.string(), "--voxel", "0.25", "--at-line", "10"},
                                   dir.path());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const nlohmann::json r = nlohmann::json::parse(readFile(out / "report.json"));
  EXPECT_EQ(r.at("moves"), 4);
  EXPECT_NEAR(r.at("final_volume_mm3").get<double>(), 19568.0 * M_PI, volumeToleranceMm3(40.0, 50.0, 0.25));
}

}  // namespace
}  // namespace lathesim::app

namespace lathesim::app {
namespace {

// A shop program whose tools are named in its comments runs with no setup at all: the bar from
// --stock, the turning tool and the parting blade from their T blocks' comments, a subprogram
// from --programs. Face Φ40 to Φ36 over 20 mm: removed π(20² − 18²)·20 = 1520π mm³. Its
// subprogram's G00 X42 retracts up the shoulder at rapid, and the CNMG's nose sweeps 6.6 mm³ of
// the shoulder's corner: a crash, exit 4, the outputs written (this test once expected 0), located
// in the subprogram's file.
TEST(Cli, ShopProgramRunsWithoutASetupFile) {
  TempDir dir("shop");
  const fs::path programs = dir.path() / "control";
  fs::create_directories(programs);
  writeFile(programs / "O7615.nc", "O7615 (TURN)\nM41\nG01 Z-20 F0.2\nG00 X42\nM99\n");
  const fs::path program = dir.path() / "shaft.nc";
  writeFile(program,
            "\x12%\nO0100 (SHAFT)\nG21 G40 G80 G99\nG54\nT0101 (CNMG 120408)\nG97 S1000 M03\n"
            "G00 X36 Z2\nM98 P7615\nG28 U0.\nG28 W0.\nM30\n%\n");
  const fs::path out = dir.path() / "out";
  const Outcome outcome = lathesim({"run", program.string(), "--stock", "D40xL60", "--programs", programs.string(),
                                    "--out", out.string(), "--voxel", "0.5"},
                                   dir.path());
  ASSERT_EQ(outcome.status, 4) << outcome.err;
  // In the subprogram's file, at its G00 X42 (line 4), with the M98 (line 8) that called it.
  EXPECT_NE(outcome.err.find((programs / "O7615.nc").string() + ":4:1: error: rapid into the stock removes"),
            std::string::npos)
      << outcome.err;
  EXPECT_NE(outcome.err.find("(called from " + program.string() + ":8)\nG00 X42\n^"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("warning: tool 1 is mounted from the comment '(CNMG 120408)'"), std::string::npos)
      << outcome.err;
  const nlohmann::json report = nlohmann::json::parse(readFile(out / "report.json"));
  EXPECT_NEAR(report["removed_volume_mm3"].get<double>(), 1520.0 * M_PI, volumeToleranceMm3(40, 60, 0.5));
  ASSERT_EQ(report["notes"].size(), 2u);  // the DC2 before the program, the subprogram file's M41
  EXPECT_NE(report["notes"][0]["message"].get<std::string>().find("DC2"), std::string::npos);
  EXPECT_FALSE(report["notes"][0].contains("file"));  // the program's own
  EXPECT_NE(report["notes"][1]["message"].get<std::string>().find("M41"), std::string::npos);
  EXPECT_EQ(report["notes"][1]["file"], (programs / "O7615.nc").string());
  EXPECT_EQ(report["notes"][1]["line"], 2);
}

}  // namespace
}  // namespace lathesim::app
