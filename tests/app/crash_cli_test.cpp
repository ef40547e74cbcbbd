// A crash is a failure: a collision is an error at its block (the block quoted, a caret under
// it), `run` and `check` exit 4 with their outputs written, report.json locates it, and it is
// marked where it happened in every picture, the video and report.html's 3D view. --collisions
// warn and [sim] collisions = "warn" keep the old exit 0, the collision a located warning.
//
// The program: seed 001's bar (Φ50, Z-60..0) turning, the default tool (polygon (0,0) (10,1)
// (12,12) (1,10): its flanks lean 1 in 10) stands at X30 Z2 and rapids to Z-1, 1 mm into the
// face. At height z of the bar (−1 ≤ z ≤ 0) the outline's slices at axial 0 … z + 1 cover
// r 15 … 15 + 10 (z + 1), so the rapid takes π ∫₀¹ ((15 + 10u)² − 15²) du = π (150 + 100/3)
// = 550π/3 = 575.96 mm³. The same program stopping at Z0.5 cuts nothing.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/part_pictures.hpp"
#include "setup/job.hpp"
#include "render/part_image.hpp"
#include "tests/render/png_pixels.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::app {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using render::test::Png;
using render::test::PngColour;
using test::readFile;
using test::lathesim;
using test::ScratchDir;
using test::writeFile;

using test::kPartsDir;
const fs::path kTaperSetup = kPartsDir / "seed001-taper-r20" / "setup.toml";
const fs::path kDrawing = kPartsDir / "seed001-taper-r20" / "drawing.toml";
constexpr double kCrashMm3 = 550.0 * M_PI / 3.0;
const RZ kCrashAt(15.0, -1.0);  // where the tool ends: X30 Z-1

std::string program(const std::string& rapidZ) {
  return "M03 S500;\nG00 X54 Z5;\nG00 X30 Z2;\nG00 Z" + rapidZ + ";\nG00 X54 Z5;\nM30;\n";
}

std::vector<std::string> runArgs(const fs::path& nc, const fs::path& out, const fs::path& setup = kTaperSetup) {
  return {"run", nc.string(), "--setup", setup.string(), "--out", out.string(), "--voxel", "0.25"};
}

TEST(Crash, ARapidIntoTheFaceIsAnErrorAtItsBlockExitsFourAndStillWritesTheOutputs) {
  ScratchDir dir("crash-run");
  const fs::path nc = dir.path() / "rapid.nc", out = dir.path() / "out";
  writeFile(nc, program("-1"));
  const auto outcome = lathesim(runArgs(nc, out), dir.path());
  EXPECT_EQ(outcome.status, 4) << outcome.err;
  // The interpreter's diagnostic form: file:line:col, the block, a caret under its start.
  const std::string located = nc.string() + ":4:1: error: rapid into the stock removes ";
  const auto at = outcome.err.find(located);
  ASSERT_NE(at, std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("mm³ (the tool ends at X30 Z-1)\nG00 Z-1;\n^", at), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.out.find("1 collision(s)"), std::string::npos) << outcome.out;
  for (const char* file : {"part.stl", "part.png", "toolpath.csv", "report.json", "report.html"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
  const Json report = Json::parse(readFile(out / "report.json"));
  ASSERT_EQ(report.at("collisions").size(), 1u) << report.at("collisions").dump();
  const Json& c = report.at("collisions")[0];
  EXPECT_EQ(c.at("file"), nc.string());
  EXPECT_EQ(c.at("line"), 4);
  EXPECT_EQ(c.at("column"), 1);
  EXPECT_EQ(c.at("block"), "G00 Z-1;");
  EXPECT_EQ(c.at("kind"), "rapid_into_stock");
  EXPECT_EQ(c.at("severity"), "error");
  EXPECT_EQ(c.at("tool"), 1);
  EXPECT_NEAR(c.at("volume_mm3").get<double>(), kCrashMm3, 0.05 * kCrashMm3);
  EXPECT_NEAR(c.at("position").at("x_diameter_mm").get<double>(), 30.0, 1e-9);
  EXPECT_NEAR(c.at("position").at("z_mm").get<double>(), -1.0, 1e-9);
  // The crash is the removal: nothing else cut.
  EXPECT_NEAR(report.at("removed_volume_mm3").get<double>(), c.at("volume_mm3").get<double>(), 1e-6);
  const std::string html = readFile(out / "report.html");
  EXPECT_NE(html.find("crash, line 4: the red marker at X30.000 Z-1.000"), std::string::npos);
}

TEST(Crash, CollisionsWarnKeepsExitZeroWithALocatedWarning) {
  ScratchDir dir("crash-warn");
  const fs::path nc = dir.path() / "rapid.nc";
  writeFile(nc, program("-1"));
  auto args = runArgs(nc, dir.path() / "out");
  args.insert(args.end(), {"--collisions", "warn"});
  const auto warned = lathesim(args, dir.path());
  EXPECT_EQ(warned.status, 0) << warned.err;
  EXPECT_NE(warned.err.find(nc.string() + ":4:1: warning: rapid into the stock removes "), std::string::npos)
      << warned.err;
  const Json report = Json::parse(readFile(dir.path() / "out" / "report.json"));
  ASSERT_EQ(report.at("collisions").size(), 1u);
  EXPECT_EQ(report.at("collisions")[0].at("severity"), "warning");

  // The setup's [sim] collisions says the same; the command line overrides it.
  const fs::path setup = dir.path() / "setup.toml";
  writeFile(setup, readFile(kTaperSetup) + "\n[sim]\ncollisions = \"warn\"\n");
  EXPECT_EQ(lathesim(runArgs(nc, dir.path() / "setup-warn", setup), dir.path()).status, 0);
  auto error = runArgs(nc, dir.path() / "setup-error", setup);
  error.insert(error.end(), {"--collisions", "error"});
  EXPECT_EQ(lathesim(error, dir.path()).status, 4);

  const fs::path bad = dir.path() / "bad.toml";
  writeFile(bad, readFile(kTaperSetup) + "\n[sim]\ncollisions = \"maybe\"\n");
  const auto refused = lathesim(runArgs(nc, dir.path() / "bad-out", bad), dir.path());
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.err.find("sim.collisions must be \"error\""), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(dir.path() / "bad-out"));
  auto badOption = runArgs(nc, dir.path() / "bad-option");
  badOption.insert(badOption.end(), {"--collisions", "ignore"});
  EXPECT_EQ(lathesim(badOption, dir.path()).status, 2);
}

// check exits 4 for a crash, over 3 (the part is out of tolerance too: the taper was never cut).
TEST(Crash, CheckExitsFourForACrashOverOutOfTolerance) {
  ScratchDir dir("crash-check");
  const fs::path nc = dir.path() / "rapid.nc";
  writeFile(nc, program("-1"));
  const auto crashed = lathesim({"check", nc.string(), "--setup", kTaperSetup.string(), "--target", kDrawing.string(),
                                      "--out", (dir.path() / "out").string(), "--voxel", "0.5"}, dir.path());
  EXPECT_EQ(crashed.status, 4) << crashed.err;
  EXPECT_TRUE(fs::exists(dir.path() / "out" / "report.json"));
  const auto warned = lathesim({"check", nc.string(), "--setup", kTaperSetup.string(), "--target", kDrawing.string(),
                                     "--out", (dir.path() / "warn").string(), "--voxel", "0.5", "--collisions", "warn"}, dir.path());
  EXPECT_EQ(warned.status, 3) << warned.err;
}

// ---------------------------------------------------------------------------------------
// The marker, by pixels: pure red (the rapids' dashes are 229, 20, 20), a disc centred where
// the picture's own frame projects X30 Z-1.

bool crashRed(const PngColour& c) { return c.r >= 240 && c.g <= 25 && c.b <= 25; }
bool videoRed(const PngColour& c) { return c.r >= 180 && c.g <= 90 && c.b <= 90; }  // H.264 blurs it

constexpr int kWidthPx = 800, kHeightPx = 600;

/// The pixel of the crash point in the picture of `view` the run draws.
Eigen::Vector2i crashPixel(const fs::path& nc, render::PartView view) {
  setup::JobRequest request;
  request.program = nc;
  request.setup = kTaperSetup;
  const std::optional<setup::Job> loaded = setup::loadJob(request).value;
  EXPECT_TRUE(loaded);
  if (!loaded) return {0, 0};
  render::PartImageOptions options = partPictureOptions(loaded->setup, loaded->toolpath, "", kWidthPx, kHeightPx);
  options.view = view;
  const Eigen::Vector2d at = render::partPictureFrame(options, loaded->toolpath, {}).pixelOf(kCrashAt);
  return {static_cast<int>(std::lround(at.x())), static_cast<int>(std::lround(at.y()))};
}

template <class Test>
int around(const Png& png, const Eigen::Vector2i& p, int half, Test test) {
  return png.count(p.x() - half, p.x() + half + 1, p.y() - half, p.y() + half + 1, test);
}

using test::ffmpegInstalled;

TEST(Crash, EveryPictureAndTheVideoMarkTheCrashWhereItHappened) {
  ScratchDir dir("crash-pictures");
  const bool video = ffmpegInstalled();
  const int half = static_cast<int>(render::crashMarkRadiusPx(kHeightPx) / 2);
  const int window = (2 * half + 1) * (2 * half + 1);
  for (const std::string z : {"-1", "0.5"}) {
    const bool crash = z == "-1";
    SCOPED_TRACE(crash ? "a rapid 1 mm into the face" : "the rapid stopping short of it");
    const fs::path nc = dir.path() / (crash ? "crash.nc" : "clear.nc"), out = dir.path() / (crash ? "crash" : "clear");
    writeFile(nc, program(z));
    auto args = runArgs(nc, out);
    args.insert(args.end(), {"--views", "front,section", "--size", "800x600", "--export", "glb"});
    if (video) args.insert(args.end(), {"--animate", "--frames", "8", "--video-size", "800x600"});
    const auto outcome = lathesim(args, dir.path());
    ASSERT_EQ(outcome.status, crash ? 4 : 0) << outcome.err;
    for (const auto& [file, view] : {std::pair{"part.png", render::PartView::Iso},
                                     std::pair{"part-front.png", render::PartView::Front},
                                     std::pair{"part-section.png", render::PartView::Section}}) {
      SCOPED_TRACE(file);
      const Png png(out / file);
      const Eigen::Vector2i at = crashPixel(nc, view);
      EXPECT_EQ(around(png, at, half, crashRed), crash ? window : 0);
      if (!crash) EXPECT_EQ(png.count(0, png.width(), 0, png.height(), crashRed), 0);
    }
    if (video) {
      SCOPED_TRACE("the video's last frame");
      const fs::path last = dir.path() / (std::string(crash ? "crash" : "clear") + "-last.png");
      const std::string command = "ffmpeg -v error -y -sseof -0.1 -i '" + (out / "cut.mp4").string() +
                                  "' -frames:v 1 -update 1 '" + last.string() + "' 2>&1";
      ASSERT_EQ(std::system(command.c_str()), 0);
      const Png frame(last);
      const int red = around(frame, crashPixel(nc, render::PartView::Iso), half, videoRed);
      if (crash) EXPECT_GT(red, window * 8 / 10);
      else EXPECT_LT(red, window / 4);
    }
    // The 3D view's model: a red mesh centred on the crash, in the part's millimetres.
    const std::string glb = readFile(out / "part.glb");
    std::uint32_t jsonBytes = 0;
    std::memcpy(&jsonBytes, glb.data() + 12, 4);
    const Json gltf = Json::parse(glb.substr(20, jsonBytes));
    int redMeshes = 0;
    for (const Json& mesh : gltf.at("meshes")) {
      const Json& primitive = mesh.at("primitives")[0];
      const Json& colour = gltf.at("materials")[primitive.at("material").get<int>()].at("pbrMetallicRoughness").at(
          "baseColorFactor");
      if (colour != Json::parse("[1.0, 0.0, 0.0, 1.0]")) continue;
      ++redMeshes;
      const Json& positions = gltf.at("accessors")[primitive.at("attributes").at("POSITION").get<int>()];
      const auto middle = [&](int axis) {
        return 0.5 * (positions.at("min")[axis].get<double>() + positions.at("max")[axis].get<double>());
      };
      EXPECT_NEAR(middle(0), 15.0, 1e-4);
      EXPECT_NEAR(middle(1), 0.0, 1e-4);
      EXPECT_NEAR(middle(2), -1.0, 1e-4);
    }
    EXPECT_EQ(redMeshes, crash ? 1 : 0);
  }
}

}  // namespace
}  // namespace lathesim::app
