// The pictures of `lathesim run` as a user gets them: part.png framed on the part whatever the
// toolpath does, the other views at the size asked, the cut as a video whose last frame is
// part.png's part, and report.html in headless Chromium with the network off.

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "tests/render/png_pixels.hpp"
#include "tests/support/headless_chromium.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::app {
namespace {

namespace fs = std::filesystem;
using render::test::Png;
using render::test::Rgb;
using test::ScratchDir;

const fs::path kBinary = LATHESIM_BINARY;
const fs::path kPartsDir = LATHESIM_PARTS_DIR;

std::vector<std::string> partArgs(const std::string& part, const fs::path& out) {
  return {"run", (kPartsDir / part / "program.nc").string(), "--setup", (kPartsDir / part / "setup.toml").string(),
          "--out", out.string()};
}

// The shaded part: near grey, neither the white-to-blue background, the amber ghost nor the
// blue chuck.
bool metal(const Rgb& c) {
  return std::abs(c.r - c.g) <= 14 && std::abs(c.b - c.r) <= 16 && c.r > 40 && std::max({c.r, c.g, c.b}) < 228;
}

/// The longest horizontal run of pixels passing `test`, over every row.
template <class Test>
int widestRun(const Png& png, Test test) {
  int widest = 0;
  for (int y = 0; y < png.height(); ++y)
    for (int x = 0, run = 0; x < png.width(); ++x) {
      run = test(png.at(x, y)) ? run + 1 : 0;
      widest = std::max(widest, run);
    }
  return widest;
}

bool ffmpegInstalled() { return std::system("ffmpeg -version >/dev/null 2>&1") == 0; }

std::string commandOutput(const std::string& command) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  std::string text;
  char buffer[256];
  while (pipe && std::fgets(buffer, sizeof buffer, pipe.get())) text += buffer;
  return text;
}

// shop-g55-safety returns to G28 (X200 Z200) from a Φ40 × 50 bar: framed on the whole
// toolpath, the part would take a fifth of the width. Framed on the bar and its jaws, the
// part is more than half of it.
TEST(PictureFraming, PartFillsMoreThanHalfThePictureOnAProgramWithAG28Return) {
  ScratchDir dir("framing");
  const auto outcome = test::runProcess(kBinary, partArgs("shop-g55-safety", dir.path() / "out"), dir.path());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const Png png(dir.path() / "out" / "part.png");
  EXPECT_GT(widestRun(png, metal), png.width() / 2);
}

TEST(PictureViews, EachViewAtTheSizeAskedAndABadSizeWritesNothing) {
  ScratchDir dir("views");
  auto args = partArgs("seed001-taper-r24", dir.path() / "out");
  args.insert(args.end(), {"--voxel", "0.5", "--views", "front,section", "--size", "640x480"});
  const auto outcome = test::runProcess(kBinary, args, dir.path());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  for (const char* name : {"part.png", "part-front.png", "part-section.png"}) {
    const Png png(dir.path() / "out" / name);
    EXPECT_EQ(png.width(), 640) << name;
    EXPECT_EQ(png.height(), 480) << name;
  }
  auto bad = partArgs("seed001-taper-r24", dir.path() / "bad");
  bad.insert(bad.end(), {"--size", "640x"});
  const auto refused = test::runProcess(kBinary, bad, dir.path());
  EXPECT_NE(refused.status, 0);
  EXPECT_NE(refused.err.find("WIDTHxHEIGHT"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(dir.path() / "bad"));
}

// ---------------------------------------------------------------------------------------
// Seed 000 at the default voxel, animated and with every export: one run shared below.

constexpr int kFrames = 40;

class AnimatedSeed000 : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!ffmpegInstalled()) return;
    dir_ = new ScratchDir("animated");
    auto args = partArgs("seed000-face-taper", dir_->path() / "out");
    args.insert(args.end(), {"--animate", "--gif", "--frames", std::to_string(kFrames), "--size", "800x600",
                             "--video-size", "800x600", "--export", "glb,ply"});
    outcome_ = new test::ProcessOutcome(test::runProcess(kBinary, args, dir_->path()));
  }
  static void TearDownTestSuite() {
    delete outcome_;
    delete dir_;
  }
  void SetUp() override {
    if (!ffmpegInstalled()) GTEST_SKIP() << "ffmpeg is not installed (scripts/setup.sh installs it)";
    ASSERT_EQ(outcome_->status, 0) << outcome_->err;
  }
  static fs::path out() { return dir_->path() / "out"; }

  static ScratchDir* dir_;
  static test::ProcessOutcome* outcome_;
};

ScratchDir* AnimatedSeed000::dir_ = nullptr;
test::ProcessOutcome* AnimatedSeed000::outcome_ = nullptr;

TEST_F(AnimatedSeed000, VideoHasTheFramesAskedAtTheirPace) {
  const std::string probe = commandOutput("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                                          "stream=nb_read_frames,width,height,r_frame_rate -of json '" +
                                          (out() / "cut.mp4").string() + "'");
  const auto stream = nlohmann::json::parse(probe).at("streams").at(0);
  EXPECT_EQ(stream.at("nb_read_frames"), std::to_string(kFrames));
  EXPECT_EQ(stream.at("width"), 800);
  EXPECT_EQ(stream.at("r_frame_rate"), "15/1");
  EXPECT_GT(fs::file_size(out() / "cut.gif"), 10000u);
  const auto report = nlohmann::json::parse(test::readFile(out() / "report.json"));
  EXPECT_GT(report.at("timing_s").at("animate").get<double>(), 0.0);
  for (const char* name : {"part.glb", "part.ply"}) EXPECT_GT(fs::file_size(out() / name), 1000u) << name;
}

// The last frame is taken at the end of the program: the part in it is part.png's (the frame
// has no dimension lines, and its part is meshed for the picture from the section, part.png's
// from the level set; H.264 blurs colours a little).
TEST_F(AnimatedSeed000, LastFrameShowsThePartOfPartPng) {
  const fs::path last = dir_->path() / "last.png";
  const std::string command = "ffmpeg -v error -y -sseof -0.5 -i '" + (out() / "cut.mp4").string() +
                              "' -update 1 -frames:v 1 '" + last.string() + "' 2>&1";
  ASSERT_EQ(commandOutput(command), "");
  const Png frame(last), picture(out() / "part.png");
  ASSERT_EQ(frame.width(), picture.width());
  ASSERT_EQ(frame.height(), picture.height());
  int partPixels = 0, matching = 0;
  for (int y = 0; y < picture.height(); ++y)
    for (int x = 0; x < picture.width(); ++x) {
      const Rgb p = picture.at(x, y);
      if (!metal(p)) continue;
      ++partPixels;
      const Rgb f = frame.at(x, y);
      matching += std::abs(p.r - f.r) + std::abs(p.g - f.g) + std::abs(p.b - f.b) <= 45;
    }
  EXPECT_GT(partPixels, 800 * 600 / 8);
  EXPECT_GT(matching, partPixels * 95 / 100) << matching << " of " << partPixels;
}

TEST_F(AnimatedSeed000, ReportOpensOfflineWithoutConsoleErrorsAndDrawsThePartIn3D) {
  if (!fs::exists(test::kChromium)) GTEST_SKIP() << "chromium is not installed (scripts/setup.sh installs it)";
  ScratchDir browser("report");
  const bool networkOff = std::system("unshare --net true 2>/dev/null") == 0;  // root only
  // WebGL on the CPU (SwiftShader): headless Chromium has no GPU here. Scrolled to the 3D
  // view, given virtual time to load and draw it.
  const std::string page = "file://" + (out() / "report.html").string() + "#view3d";
  const std::vector<std::string> flags{"--enable-unsafe-swiftshader", "--virtual-time-budget=15000"};
  const fs::path shot = browser.path() / "report.png";
  std::vector<std::string> withShot = flags;
  withShot.push_back("--screenshot=" + shot.string());
  const test::BrowserRun opened = test::openInChromium(browser, page, withShot, networkOff);
  // Only the software GL's performance notes (about reading pixels back for the screenshot).
  for (const std::string& line : opened.consoleLines)
    EXPECT_NE(line.find("GL Driver Message (OpenGL, Performance"), std::string::npos) << line;
  ASSERT_TRUE(fs::exists(shot)) << opened.outcome.err;
  const Png png(shot);
  // The view fills the top of the window: the part's metal there (the view's background is
  // #f4f6f9, too light to count).
  EXPECT_GT(png.count(0, png.width(), png.height() - 500, png.height(), metal), 3000);

  std::vector<std::string> withDom = flags;
  withDom.push_back("--dump-dom");
  const test::BrowserRun dom = test::openInChromium(browser, page, withDom, networkOff);
  EXPECT_NE(dom.outcome.out.find("id=\"view3d\" data-state=\"drawn\""), std::string::npos);
  // Line 3 of seed 000 removes the most (G94 X120 Z-110 faces the Φ125 bar down to Φ120).
  EXPECT_NE(dom.outcome.out.find("<tr id=\"L3\""), std::string::npos);
  // Self-contained: nothing is fetched from anywhere.
  const std::string html = test::readFile(out() / "report.html");
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);
  EXPECT_EQ(html.find("href=\"http"), std::string::npos);
}

}  // namespace
}  // namespace lathesim::app
