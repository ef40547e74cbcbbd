// The pictures of `lathesim run` as a user gets them: part.png framed on the part whatever the
// toolpath does, the other views at the size asked, the cut as a video whose last frame is
// part.png's part, and report.html in headless Chromium with the network off.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <nlohmann/json.hpp>

#include "tests/render/png_pixels.hpp"
#include "tests/support/headless_chromium.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::app {
namespace {

namespace fs = std::filesystem;
using render::test::Png;
using render::test::PngColour;
using test::ScratchDir;

using test::kBinary;
using test::kPartsDir;

std::vector<std::string> partArgs(const std::string& part, const fs::path& out) {
  return {"run", (kPartsDir / part / "program.nc").string(), "--setup", (kPartsDir / part / "setup.toml").string(),
          "--out", out.string()};
}

/// How much of the picture's width the part covers: from the first to the last column with
/// the part's metal in at least 5 % of its rows (dimension lines may cross the part; a
/// stray pixel of metal grey elsewhere does not count).
int partWidthPx(const Png& png) {
  int first = -1, last = -1;
  for (int x = 0; x < png.width(); ++x)
    if (png.count(x, x + 1, 0, png.height(), [&png](int u, int v) { return render::test::partMetal(png, u, v); }) >=
        png.height() / 20) {
      if (first < 0) first = x;
      last = x;
    }
  return first < 0 ? 0 : last - first + 1;
}

using test::ffmpegInstalled;

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
  EXPECT_GT(partWidthPx(png), png.width() / 2);
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

// --thumbnail: part.png shrunk by a whole factor, each pixel the mean of its block of part.png.
TEST(PictureThumbnail, IsPartPngInBlockMeansAndAWidthOutOfRangeIsRefused) {
  ScratchDir dir("thumbnail");
  auto args = partArgs("g74-drill", dir.path() / "out");
  args.insert(args.end(), {"--voxel", "0.5", "--size", "640x480", "--thumbnail", "100", "--outputs", "png"});
  const auto outcome = test::runProcess(kBinary, args, dir.path());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const Png part(dir.path() / "out" / "part.png");
  const Png thumbnail(dir.path() / "out" / "thumbnail.png");
  constexpr int kFactor = 6;  // 640 / 100 rounded
  ASSERT_EQ(thumbnail.width(), 640 / kFactor);
  ASSERT_EQ(thumbnail.height(), 480 / kFactor);
  int differing = 0;
  for (int y = 0; y < thumbnail.height(); y += 7)
    for (int x = 0; x < thumbnail.width(); x += 5) {
      int sum[3] = {0, 0, 0};
      for (int v = 0; v < kFactor; ++v)
        for (int u = 0; u < kFactor; ++u) {
          const PngColour c = part.at(x * kFactor + u, y * kFactor + v);
          sum[0] += c.r, sum[1] += c.g, sum[2] += c.b;
        }
      const PngColour t = thumbnail.at(x, y);
      const double n = kFactor * kFactor;
      // The mean, truncated or rounded: within one level.
      if (std::abs(t.r - sum[0] / n) > 1 || std::abs(t.g - sum[1] / n) > 1 || std::abs(t.b - sum[2] / n) > 1)
        ++differing;
    }
  EXPECT_EQ(differing, 0);

  auto tiny = partArgs("g74-drill", dir.path() / "tiny");
  tiny.insert(tiny.end(), {"--thumbnail", "8"});
  const auto refused = test::runProcess(kBinary, tiny, dir.path());
  EXPECT_EQ(refused.status, 2) << refused.err;
  EXPECT_NE(refused.err.find("--thumbnail"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(dir.path() / "tiny"));
}

/// Where `name` is found on this process's PATH (empty if nowhere).
fs::path onPath(const std::string& name) {
  std::istringstream path(std::getenv("PATH") ? std::getenv("PATH") : "");
  for (std::string folder; std::getline(path, folder, ':');)
    if (!folder.empty() && fs::exists(fs::path(folder) / name)) return fs::path(folder) / name;
  return {};
}

// Without ffmpeg, --animate is refused, plainly, and nothing is written, not even the folder.
TEST(PictureAnimation, WithoutFfmpegIsAnErrorAndWritesNothing) {
  ScratchDir dir("no-ffmpeg");
  const fs::path bin = dir.path() / "bin";  // the X server the pictures may need, and no ffmpeg
  fs::create_directories(bin);
  for (const char* tool : {"Xvfb", "xauth"})
    if (const fs::path found = onPath(tool); !found.empty()) fs::create_symlink(found, bin / tool);
  auto args = partArgs("shop-g55-safety", dir.path() / "out");
  args.push_back("--animate");
  args.insert(args.begin(), {"PATH=" + bin.string(), kBinary.string()});
  const auto outcome = test::runProcess(onPath("env"), args, dir.path());
  EXPECT_EQ(outcome.status, 1);
  EXPECT_NE(outcome.err.find("install the ffmpeg package"), std::string::npos) << outcome.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

// ---------------------------------------------------------------------------------------
// Seed 000 animated, with exports: one run (at 0.5 mm voxels, to keep the suite fast: the
// frames and the report do not depend on the voxel), checked below.

constexpr int kFrames = 40;
constexpr int kVideoWidthPx = 800, kVideoHeightPx = 600;

void checkVideo(const fs::path& out) {
  const std::string probe = commandOutput("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                                          "stream=nb_read_frames,width,height,r_frame_rate -of json '" +
                                          (out / "cut.mp4").string() + "'");
  const auto stream = nlohmann::json::parse(probe).at("streams").at(0);
  EXPECT_EQ(stream.at("nb_read_frames"), std::to_string(kFrames));
  EXPECT_EQ(stream.at("width"), kVideoWidthPx);
  EXPECT_EQ(stream.at("height"), kVideoHeightPx);
  EXPECT_EQ(stream.at("r_frame_rate"), "15/1");
  EXPECT_GT(fs::file_size(out / "cut.gif"), 10000u);
  const auto report = nlohmann::json::parse(test::readFile(out / "report.json"));
  EXPECT_GT(report.at("timing_s").at("animate").get<double>(), 0.0);
  for (const char* name : {"part.glb", "part.ply"}) EXPECT_GT(fs::file_size(out / name), 1000u) << name;
}

/// The video's frame `index` (from 0) as a PNG.
Png videoFrame(const fs::path& video, int index, const fs::path& png) {
  const std::string command = "ffmpeg -v error -y -i '" + video.string() + "' -vf 'select=eq(n\\," +
                              std::to_string(index) + ")' -frames:v 1 '" + png.string() + "' 2>&1";
  EXPECT_EQ(commandOutput(command), "");
  return Png(png);
}

/// Pixels where the part is in one picture and not in the other, or is in both in colours
/// further apart than H.264 blurs them; part.png's dimension lines and figures (purple, and
/// their backed labels) are left out, with `inkMarginPx` around them.
struct PartMismatch {
  int partPixels = 0, mismatched = 0;
};
PartMismatch partMismatch(const Png& picture, const Png& frame, int inkMarginPx) {
  const int w = picture.width(), h = picture.height();
  std::vector<char> ink(static_cast<std::size_t>(w) * h, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const PngColour c = picture.at(x, y);
      if (c.r - c.g <= 40 || c.b - c.g <= 40) continue;
      for (int v = std::max(0, y - inkMarginPx); v <= std::min(h - 1, y + inkMarginPx); ++v)
        for (int u = std::max(0, x - inkMarginPx); u <= std::min(w - 1, x + inkMarginPx); ++u)
          ink[static_cast<std::size_t>(v) * w + u] = 1;
    }
  PartMismatch m;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (ink[static_cast<std::size_t>(y) * w + x]) continue;
      const bool inPicture = render::test::partMetal(picture, x, y), inFrame = render::test::partMetal(frame, x, y);
      m.partPixels += inPicture;
      const PngColour p = picture.at(x, y), f = frame.at(x, y);
      const bool apart = std::abs(p.r - f.r) + std::abs(p.g - f.g) + std::abs(p.b - f.b) > 45;
      m.mismatched += inPicture != inFrame || (inPicture && apart);
    }
  return m;
}

// The last frame is taken at the end of the program: the part in it is part.png's. The frame
// has no dimension lines, its part is meshed for the picture from the section (part.png's
// from the level set), and H.264 blurs colours and edges: about 3 % of the part's pixels
// differ. The frame before it (1/39 of the machine time earlier: the last taper pass not yet
// cut) differs in about 10 %, so 6 % tells them apart.
void checkLastFrame(const fs::path& out, const fs::path& scratch) {
  const Png picture(out / "part.png");
  const Png last = videoFrame(out / "cut.mp4", kFrames - 1, scratch / "last.png");
  ASSERT_EQ(last.width(), picture.width());
  ASSERT_EQ(last.height(), picture.height());
  const PartMismatch m = partMismatch(picture, last, 2);
  EXPECT_GT(m.partPixels, kVideoWidthPx * kVideoHeightPx / 8);
  EXPECT_LT(m.mismatched, m.partPixels * 6 / 100) << m.mismatched << " of " << m.partPixels;
  const Png before = videoFrame(out / "cut.mp4", kFrames - 2, scratch / "before.png");
  const PartMismatch earlier = partMismatch(picture, before, 2);
  EXPECT_GT(earlier.mismatched, earlier.partPixels * 6 / 100) << "the frame before the last already shows the part";
}

void checkReportInChromium(const fs::path& out) {
  ScratchDir browser("report");
  const bool networkOff = std::system("unshare --net true 2>/dev/null") == 0;  // root only
  EXPECT_TRUE(networkOff || std::getenv("CI") == nullptr) << "CI runs as root: the page must be opened offline";
  // WebGL on the CPU (SwiftShader): headless Chromium has no GPU here. Given virtual time to
  // load and draw; the 3D view stands under the summary, in the first screen.
  const std::string page = "file://" + (out / "report.html").string();
  const std::vector<std::string> flags{"--enable-unsafe-swiftshader", "--virtual-time-budget=15000"};
  const fs::path shot = browser.path() / "report.png";
  std::vector<std::string> withShot = flags;
  withShot.push_back("--screenshot=" + shot.string());
  const test::BrowserRun opened = test::openInChromium(browser, page, withShot, networkOff);
  // The page's own console says nothing but the software GL's performance notes (about reading
  // pixels back for the screenshot). Chromium's own pages (chrome://…) are not the report's.
  for (const std::string& line : opened.consoleLines)
    if (line.find("source: file://") != std::string::npos) {
      EXPECT_NE(line.find("GL Driver Message (OpenGL, Performance"), std::string::npos) << line;
    }
  ASSERT_TRUE(fs::exists(shot)) << opened.outcome.err;
  // The part's metal in the 3D view (its background #f4f6f9 and the page's are too light to
  // count; the pictures, which show metal too, are below the first screen).
  const Png png(shot);
  EXPECT_GT(png.count(0, png.width(), 0, png.height(), render::test::metal), 20000);

  std::vector<std::string> withDom = flags;
  withDom.push_back("--dump-dom");
  const test::BrowserRun dom = test::openInChromium(browser, page, withDom, networkOff);
  EXPECT_NE(dom.outcome.out.find("id=\"view3d\" data-state=\"drawn\""), std::string::npos);
  // Line 3 of seed 000 removes the most (G94 X120 Z-110 faces the Φ125 bar down to Φ120).
  EXPECT_NE(dom.outcome.out.find("<tr id=\"L3\""), std::string::npos);
  // Self-contained: nothing is fetched from anywhere.
  const std::string html = test::readFile(out / "report.html");
  // The run made a video: the page shows it and links it, beside the page.
  EXPECT_NE(html.find("<video controls preload=\"metadata\" src=\"cut.mp4\""), std::string::npos);
  EXPECT_NE(html.find("<a href=\"cut.mp4\">cut.mp4</a>"), std::string::npos);
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);
  EXPECT_EQ(html.find("href=\"http"), std::string::npos);
}

TEST(AnimatedSeed000, VideoAtItsPaceLastFrameIsPartPngAndReportOpensOfflineIn3D) {
  if (!ffmpegInstalled()) GTEST_SKIP() << "ffmpeg is not installed (scripts/setup.sh installs it)";
  ScratchDir dir("animated");
  const fs::path out = dir.path() / "out";
  auto args = partArgs("seed000-face-taper", out);
  const std::string size = std::to_string(kVideoWidthPx) + "x" + std::to_string(kVideoHeightPx);
  args.insert(args.end(), {"--voxel", "0.5", "--animate", "--gif", "--frames", std::to_string(kFrames), "--size", size,
                           "--video-size", size, "--export", "glb,ply"});
  const auto outcome = test::runProcess(kBinary, args, dir.path());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  {
    SCOPED_TRACE("the video");
    checkVideo(out);
  }
  {
    SCOPED_TRACE("the last frame");
    checkLastFrame(out, dir.path());
  }
  if (!fs::exists(test::kChromium)) GTEST_SKIP() << "chromium is not installed (scripts/setup.sh installs it)";
  SCOPED_TRACE("report.html");
  checkReportInChromium(out);
}

}  // namespace
}  // namespace lathesim::app
