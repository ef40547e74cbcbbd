// `lathesim check` run as a user runs it, on seed 001's pair and on a program that cuts
// 0.5 mm under a diameter on purpose. Every expected figure is worked out by hand below.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "tests/render/test_meshes.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::app {
namespace {

namespace fs = std::filesystem;
using test::ProcessOutcome;
using test::ScratchDir;

using test::kBinary;
using test::kPartsDir;
constexpr double kCheckVoxelMm = 0.25;

struct CheckRun {
  ProcessOutcome outcome;
  nlohmann::json check;  // report.json's "check"
};

CheckRun check(const ScratchDir& dir, const std::vector<std::string>& args) {
  std::vector<std::string> all{"check"};
  all.insert(all.end(), args.begin(), args.end());
  all.insert(all.end(), {"--out", (dir.path() / "out").string()});
  CheckRun run{test::runProcess(kBinary, all, dir.path()), {}};
  const fs::path report = dir.path() / "out" / "report.json";
  if (fs::exists(report)) run.check = nlohmann::json::parse(test::readFile(report)).at("check");
  return run;
}

std::vector<std::string> seed001(const std::string& part) {
  const fs::path dir = kPartsDir / ("seed001-taper-" + part);
  return {(dir / "program.nc").string(), "--setup", (dir / "setup.toml").string(), "--voxel", "0.25"};
}

std::vector<std::string> operator+(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// Seed 001's drawing (parts/seed001-taper-*/drawing.toml): the cone from (r 15, Z0) to
// (r 25, Z-20), i.e. the line 2r + z − 30 = 0, then r 25 to the bar's end at Z-60.
//
// R-24 cuts exactly that cone (parts/seed001-taper-r24/expected.toml), so every deviation
// is measurement noise, which must stay well inside the two-voxel tolerance.
TEST(CheckSeed001, CorrectTaperPassesAtTwoVoxels) {
  ScratchDir dir("check-r24");
  const auto target = (kPartsDir / "seed001-taper-r24" / "drawing.toml").string();
  const CheckRun run = check(dir, seed001("r24") + std::vector<std::string>{"--target", target, "--tol", "0.5"});
  ASSERT_EQ(run.outcome.status, 0) << run.outcome.out << run.outcome.err;
  EXPECT_NE(run.outcome.out.find("within tolerance"), std::string::npos) << run.outcome.out;
  EXPECT_EQ(run.check.at("within_tolerance"), true);
  EXPECT_LT(run.check.at("max_excess_mm").get<double>(), kCheckVoxelMm / 2);
  EXPECT_LT(run.check.at("max_gouge_mm").get<double>(), kCheckVoxelMm / 2);
  EXPECT_EQ(run.check.at("regions"), nlohmann::json::array());
  // The same output files as `run`, and the two deviation pictures.
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir.path() / "out")) names.insert(entry.path().filename().string());
  const std::set<std::string> expected{"part.stl",  "part.png",    "toolpath.csv",  "toolpath.vtp", "stock.vdb",
                                       "report.json", "report.html", "deviation.png", "section.png"};
  EXPECT_EQ(names, expected);
}

// the cut line runs from B (r 27, Z-20) to C (r 15, Z0), slope 12/20 in r per Z, so it
// meets the bar (r 25) at Z = −20 + 2·20/12 = −50/3. The part's cone is (15, 0)→(25, −50/3),
// flatter than drawn. Its corner (25, −50/3) is outside the drawing, at a distance normal to
// the drawn line of (2·25 − 50/3 − 30)/√5 = (10/3)/√5 = 2√5/3 ≈ 1.4907 mm. It is the largest:
// along the part's cone (r = 15 − 0.6z) the distance (−0.2z)/√5 grows towards that corner;
// along r 25 below it, (20 + z)/√5 falls to 0 at Z-20. (From the drawing's side the largest
// is smaller: a drawn point (15+10t, −20t) is min(10t/√34, 10(1−t)) from the part, at most
// 10/(1+√34) ≈ 1.464.) The excess is the triangle (15, 0), (25, −50/3), (25, −20): area
// ½·(10/3)·10 = 50/3 mm², centroid r = 65/3, volume by Pappus 2π·(65/3)·(50/3) = 6500π/9
// ≈ 2268.93 mm³ — the difference of the two parts' hand volumes (305000/9 π − 99500/3 π).
TEST(CheckSeed001, WrongTaperFailsWithTheHandWorkedExcess) {
  ScratchDir dir("check-r20");
  const auto target = (kPartsDir / "seed001-taper-r20" / "drawing.toml").string();
  const CheckRun run = check(dir, seed001("r20") + std::vector<std::string>{"--target", target, "--tol", "0.5"});
  ASSERT_EQ(run.outcome.status, 3) << run.outcome.out << run.outcome.err;
  EXPECT_NE(run.outcome.out.find("OUT OF tolerance"), std::string::npos) << run.outcome.out;
  const double handExcessMm = 2 * std::sqrt(5.0) / 3;
  EXPECT_NEAR(run.check.at("max_excess_mm").get<double>(), handExcessMm, kCheckVoxelMm / 2);
  EXPECT_NEAR(run.check.at("max_excess_at").at("z").get<double>(), -50.0 / 3, 2 * kCheckVoxelMm);
  EXPECT_NEAR(run.check.at("max_excess_at").at("diameter").get<double>(), 50.0, 2 * kCheckVoxelMm);
  EXPECT_LT(run.check.at("max_gouge_mm").get<double>(), kCheckVoxelMm / 2);
  // Volume: the ramp's error is a few percent of a voxel layer over the region's surfaces
  // (two cones of about 20 mm and the r 25 strip, around r 22): 0.05·h·2π·22·45 ≈ 78 mm³.
  EXPECT_NEAR(run.check.at("excess_volume_mm3").get<double>(), 6500 * M_PI / 9, 78);
  EXPECT_LT(run.check.at("gouge_volume_mm3").get<double>(), 1.0);
  ASSERT_EQ(run.check.at("regions").size(), 1u);
  const auto& region = run.check.at("regions")[0];
  EXPECT_EQ(region.at("kind"), "excess");
  // Beyond 0.5 mm: on the part's cone from −0.2z/√5 = 0.5 (Z−5.59) down to its corner, and on
  // r 25 until (20 + z)/√5 = 0.5 (Z−18.88); the drawn points opposite reach a little lower.
  EXPECT_NEAR(region.at("z_range")[1].get<double>(), -5.59, 2 * kCheckVoxelMm);
  EXPECT_LT(region.at("z_range")[0].get<double>(), -18.88 + 2 * kCheckVoxelMm);
  EXPECT_GT(region.at("z_range")[0].get<double>(), -20.0 - kCheckVoxelMm);
  // report.html carries the deviation pictures and the region, flagged, with its largest excess.
  const std::string html = test::readFile(dir.path() / "out" / "report.html");
  EXPECT_NE(html.find("deviation.png: the part coloured by its deviation"), std::string::npos);
  EXPECT_NE(html.find("section.png: the half-section against the drawing"), std::string::npos);
  char row[96];
  std::snprintf(row, sizeof row, "<tr class=\"problem-warning\"><td>excess</td><td class=\"num\">%.3f</td>",
                region.at("max_mm").get<double>());
  EXPECT_NE(html.find(row), std::string::npos) << row;
}

// The drawing may be another program's part, simulated with the same setup: R-20 against
// R-24 measures the same cone against cone, 2√5/3 (above).
TEST(CheckSeed001, AgainstAnotherProgramsPart) {
  ScratchDir dir("check-program");
  const auto target = (kPartsDir / "seed001-taper-r24" / "program.nc").string();
  const CheckRun run =
      check(dir, seed001("r20") + std::vector<std::string>{"--target-program", target, "--tol", "0.5"});
  ASSERT_EQ(run.outcome.status, 3) << run.outcome.out << run.outcome.err;
  EXPECT_EQ(run.check.at("target_kind"), "program");
  EXPECT_NEAR(run.check.at("max_excess_mm").get<double>(), 2 * std::sqrt(5.0) / 3, kCheckVoxelMm / 2);
  EXPECT_NEAR(run.check.at("excess_volume_mm3").get<double>(), 6500 * M_PI / 9, 78);
}

/// A binary STL of `mesh` (normals left zero: readers recompute them).
void writeStl(const TriangleMesh& mesh, const fs::path& file) {
  std::ofstream out(file, std::ios::binary);
  const std::string header(80, ' ');
  out.write(header.data(), 80);
  const auto count = static_cast<std::uint32_t>(mesh.triangles.size());
  out.write(reinterpret_cast<const char*>(&count), 4);
  for (const auto& t : mesh.triangles) {
    const float normal[3] = {0, 0, 0};
    out.write(reinterpret_cast<const char*>(normal), 12);
    for (std::uint32_t v : t) out.write(reinterpret_cast<const char*>(mesh.vertices[v].data()), 12);
    const std::uint16_t attributes = 0;
    out.write(reinterpret_cast<const char*>(&attributes), 2);
  }
}

// The drawing as an STL of the design: seed 001's profile revolved with 180 facets around,
// one ring of vertices in the plane y = 0, so its section is the drawn profile itself and the
// figures are those above.
TEST(CheckSeed001, AgainstAnStlOfTheDesign) {
  ScratchDir dir("check-stl");
  const fs::path design = dir.path() / "design.stl";
  writeStl(render::test::revolved({{0, 0}, {15, 0}, {25, -20}, {25, -60}, {0, -60}}, 180), design);
  const CheckRun wrong = check(dir, seed001("r20") + std::vector<std::string>{"--target", design.string(), "--tol", "0.5"});
  ASSERT_EQ(wrong.outcome.status, 3) << wrong.outcome.out << wrong.outcome.err;
  EXPECT_EQ(wrong.check.at("target_kind"), "stl");
  EXPECT_NEAR(wrong.check.at("max_excess_mm").get<double>(), 2 * std::sqrt(5.0) / 3, kCheckVoxelMm / 2);
  EXPECT_NEAR(wrong.check.at("excess_volume_mm3").get<double>(), 6500 * M_PI / 9, 78);
  const CheckRun right = check(dir, seed001("r24") + std::vector<std::string>{"--target", design.string(), "--tol", "0.5"});
  EXPECT_EQ(right.outcome.status, 0) << right.outcome.out << right.outcome.err;
}

// A Φ50 × 40 bar (face Z0). Drawn: Φ40 from Z0 to Z-30, a shoulder, Φ50 to Z-40. The program
// turns Φ40 but runs its first 10 mm at Φ39 — 0.5 mm under the radius — on line 3:
//   1 G00 X100 Z5 / 2 G00 X39 Z2 / 3 G01 Z-10 / 4 G01 X40 / 5 G01 Z-30 / 6 G01 X52 / 7 G00 X100 Z5
// The tool's body lies above and right of its tip (r ≥ tip, z ≥ tip, flanks 1 in 10), so it
// removes nothing below the tip's path: the part is r 19.5 for Z-10..0, r 20 for Z-30..-10.
// Gouge: 0.5 mm deep over Z-10..0, between Ø39 and Ø40, made by line 3 (the first move whose
// swept region reaches inside the drawing there); volume π(20² − 19.5²)·10 = 197.5π ≈ 620.5 mm³.
// The tolerance 0.1 mm is half a voxel: anything else would be reported too.
TEST(CheckGouge, HalfMillimetreUnderADiameterIsFoundOnItsLine) {
  ScratchDir dir("check-gouge");
  test::writeFile(dir.path() / "gouge.nc",
                  "G00 X100 Z5\nG00 X39 Z2\nG01 Z-10 F0.1\nG01 X40\nG01 Z-30\nG01 X52\nG00 X100 Z5\nM30\n");
  test::writeFile(dir.path() / "setup.toml", "[stock]\ndiameter = 50\nlength = 40\nface_z = 0\n");
  test::writeFile(dir.path() / "drawing.toml",
                  "profile = [{x = 40, z = 0}, {x = 40, z = -30}, {x = 50, z = -30}, {x = 50, z = -40}]\n");
  const double voxelMm = 0.2;
  const CheckRun run = check(dir, {(dir.path() / "gouge.nc").string(), "--setup", (dir.path() / "setup.toml").string(),
                                   "--target", (dir.path() / "drawing.toml").string(), "--voxel", "0.2", "--tol", "0.1"});
  ASSERT_EQ(run.outcome.status, 3) << run.outcome.out << run.outcome.err;
  EXPECT_NEAR(run.check.at("max_gouge_mm").get<double>(), 0.5, voxelMm / 2);
  EXPECT_LT(run.check.at("max_excess_mm").get<double>(), 0.1);
  EXPECT_NEAR(run.check.at("gouge_volume_mm3").get<double>(), 197.5 * M_PI, 0.05 * voxelMm * 2 * M_PI * 20 * 21);
  // The Φ40 is a size: measured Ø39 at its worst, 1 under, 0.8 beyond --tol's ±0.2 on the
  // diameter (0.1 on each radius), made by line 3 (its X from line 2); the same error is not
  // reported again by the profile at the line's ends.
  const nlohmann::json* d40 = nullptr;
  for (const auto& s : run.check.at("sizes"))
    if (s.at("kind") == "diameter" && s.at("nominal_mm") == 40) d40 = &s;
  ASSERT_NE(d40, nullptr) << run.check.dump(2);
  EXPECT_NEAR(d40->at("worst_mm").get<double>(), 39.0, 1e-3);
  EXPECT_NEAR(d40->at("beyond_mm").get<double>(), 0.8, 1e-3);
  EXPECT_EQ(d40->at("verdict"), "out");
  EXPECT_EQ(d40->at("lines"), nlohmann::json::array({3}));
  EXPECT_EQ(d40->at("value_line"), 2);
  EXPECT_EQ(run.check.at("regions"), nlohmann::json::array()) << run.check.at("regions").dump(2);
  EXPECT_NE(run.outcome.out.find("Ø39.000 ±0.025 measured at Z"), std::string::npos) << run.outcome.out;
  EXPECT_NE(run.outcome.out.find("made by line 3 `G01 Z-10 F0.1` (its X from line 2 `G00 X39 Z2`)"), std::string::npos)
      << run.outcome.out;
}

std::vector<std::string> g76(double voxel) {
  const fs::path dir = kPartsDir / "g76-m30x2";
  return {(dir / "program.nc").string(), "--setup", (dir / "setup.toml").string(), "--voxel", std::to_string(voxel)};
}

// The M30×2 part against its drawing (parts/g76-m30x2/drawing.toml): the profile outside the
// thread's zone exactly as cut, the thread as called out (pitch 2, one start, right-hand,
// major Φ30, minor Φ27.4…28.0 around the programmed root Φ27.546: a sharp V's root reads up to a
// voxel shallow at 0.25 mm).
TEST(CheckThread, CalloutAsCutPasses) {
  ScratchDir dir("check-thread");
  const auto target = (kPartsDir / "g76-m30x2" / "drawing.toml").string();
  const CheckRun run = check(dir, g76(0.25) + std::vector<std::string>{"--target", target});
  EXPECT_EQ(run.outcome.status, 0) << run.outcome.out << run.outcome.err;
  ASSERT_TRUE(run.check.contains("threads"));
  ASSERT_EQ(run.check.at("threads").size(), 1u);
  const auto& thread = run.check.at("threads")[0];
  EXPECT_EQ(thread.at("line"), 13);
  EXPECT_TRUE(thread.at("within").get<bool>());
  EXPECT_EQ(thread.at("items").size(), 5u);  // pitch, starts, hand, major, minor
  EXPECT_NEAR(run.check.at("max_gouge_mm").get<double>(), 0.0, 0.125);  // the thread's zone is not the outline's
  EXPECT_NE(run.outcome.out.find("thread Z-30.000..Z0.000 (line 13): as called out"), std::string::npos) << run.outcome.out;
}

// The same part against a callout of a left-hand thread of pitch 1.5: out of tolerance (exit
// 3), each item saying what it found.
TEST(CheckThread, WrongHandAndPitchFail) {
  ScratchDir dir("check-thread-wrong");
  test::writeFile(dir.path() / "drawing.toml",
                  "profile = [{x = 30, z = 0}, {x = 30, z = -30}, {x = 27, z = -30}, {x = 27, z = -35.5}, {x = 30, z = "
                  "-35.5}, {x = 30, z = -50}]\n[[thread]]\nz_range = [-30, 0]\npitch = 1.5\nhand = \"left\"\n");
  const CheckRun run = check(dir, g76(0.25) + std::vector<std::string>{"--target", (dir.path() / "drawing.toml").string()});
  EXPECT_EQ(run.outcome.status, 3) << run.outcome.out << run.outcome.err;
  const auto& items = run.check.at("threads")[0].at("items");
  ASSERT_EQ(items.size(), 3u);
  EXPECT_EQ(items[0].at("name"), "pitch");
  EXPECT_FALSE(items[0].at("within").get<bool>());
  EXPECT_EQ(items[2].at("name"), "hand");
  EXPECT_EQ(items[2].at("measured"), "right");
  EXPECT_FALSE(items[2].at("within").get<bool>());
  EXPECT_FALSE(run.check.at("within_tolerance").get<bool>());
  EXPECT_NE(run.outcome.out.find("hand right (expected left)"), std::string::npos) << run.outcome.out;
}

}  // namespace
}  // namespace lathesim::app
