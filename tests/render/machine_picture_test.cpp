// The machine drawn beside the part: the chuck's jaws, the tailstock's centre and the tool's
// holder at hand-checked pixels of the front view (and nowhere else), and the same machine in
// the 3D view's GLB at the sizes the tool data gives.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>

#include "render/part_image.hpp"
#include "render/scene_export.hpp"
#include "tests/render/png_pixels.hpp"
#include "tests/render/test_meshes.hpp"

namespace lathesim::render {
namespace {

using test::Png;
using test::PngColour;

bool jaw(const PngColour& c) { return c.b - c.r > 30 && c.b < 210 && c.r < 140; }  // blue steel
bool tailstockGreen(const PngColour& c) { return c.g - c.r > 20 && c.g - c.b > 12 && c.g < 200; }  // the tailstock's steel green
bool holderGrey(const PngColour& c) {  // the holder's dark steel, darker than the background's lightest grey
  return std::abs(c.r - c.g) <= 16 && std::abs(c.b - c.r) <= 24 && c.r > 30 && c.r < 150 && c.b < 170;
}

/// A Φ60 bar Z−60..0 in jaws r 30..50 on Z−80..−60 (body to Z−180); a tailstock centre with its
/// point at Z0 and a Φ20 quill 40 long; a 10 mm square insert at (r 40, Z−30) in a holder
/// r 50..100, Z−30..−10 (relative: r 10..60, Z 0..20), 25 mm high, the insert 5 mm thick.
PartImageOptions machineScene() {
  PartImageOptions options;
  options.widthPx = 800;
  options.heightPx = 600;
  options.view = PartView::Front;
  options.title = "machine.nc";
  options.bar = BarOutline{30, -60, 0};
  options.chuck = ChuckPicture{30, 50, -80, -60, -180};
  options.tailstock = TailstockPicture{0, 10, 40};
  ToolPicture tool;
  tool.insert = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  tool.holder = {{10, 0}, {60, 0}, {60, 20}, {10, 20}};
  tool.position = RZ(40, -30);
  tool.holderHeightMm = 25;
  tool.insertThicknessMm = 5;
  options.tool = tool;
  return options;
}

// The front view frames, by hand (part_image.hpp; right = Z, up = X): the bar (Z−60..0, up
// ±30); the jaws' front ends, 0.2 of the bar's length behind their face (Z−72) and 0.25 of its
// radius past it (r 37.5; the lower jaws reach −0.5·37.5 − 0.866·9 = −26.5, inside the bar's
// −30); the tailstock's point (Z0) and its cone's foot, r 10 at Z 10/tan 30° = 17.32; the
// insert (up to r 50, Z−20), near enough to be framed, and with it its holder, whole (up to
// r 100, Z−30..−10). Across: Z−72..17.32, 89.32 mm; up: −30..100, 130 mm. 800 × 600 px with
// 6 % margins and 15 % more on top: 704 × 438 px usable, 438 / 130 = 3.3692 px/mm
// (< 704 / 89.32). Centre: Z−27.34 across; up, the band's middle is 255 px, so the picture's
// centre (300 px) is at 35 + 45 / 3.3692 = 48.356.
Eigen::Vector2i framePixel(double r, double z) {
  const double pxPerMm = 438.0 / 130.0;
  return {static_cast<int>(std::lround(400 + (z - (-72 + 10 / std::tan(M_PI / 6)) / 2) * pxPerMm)),
          static_cast<int>(std::lround(300 + (r - (35 + 45 / pxPerMm)) * pxPerMm))};
}

template <class Test>
int around(const Png& png, const Eigen::Vector2i& p, int half, Test test) {
  return png.count(p.x() - half, p.x() + half + 1, p.y() - half, p.y() + half + 1, test);
}

TEST(MachinePicture, JawsTailstockAndHolderStandWhereTheSetupPutsThem) {
  ::unsetenv("DISPLAY");
  test::TempDir dir;
  const interp::Toolpath none;
  writePartImagePng(TriangleMesh{}, none, machineScene(), dir.path() / "machine.png");
  const Png png(dir.path() / "machine.png");
  ASSERT_EQ(png.width(), 800);
  constexpr int kWindow = 3;  // 7 × 7 px
  EXPECT_EQ(around(png, framePixel(34, -66), kWindow, jaw), 49);         // the top jaw's front
  EXPECT_EQ(around(png, framePixel(0, 30), kWindow, tailstockGreen), 49);         // the quill, on the axis
  EXPECT_EQ(around(png, framePixel(0, 10), kWindow, tailstockGreen), 49);         // the cone: r 5.77 at Z10
  EXPECT_EQ(around(png, framePixel(60, -20), kWindow, holderGrey), 49);  // the holder
  EXPECT_EQ(around(png, framePixel(97, -12), kWindow, holderGrey), 49);  // its far corner, in the picture
  EXPECT_EQ(around(png, framePixel(45, -25), kWindow, test::insertGold), 49);        // the insert on it
  // Nowhere else: beside the cone (r 12 at Z8, the cone is r 4.6 there), beyond the quill
  // (r 14 at Z30), past the holder's end (r 60 at Z−5), beside the insert (r 45 at Z−15, below
  // the holder), and the bar's ghost in front of the jaws (r 20 at Z−40).
  EXPECT_EQ(around(png, framePixel(12, 8), kWindow, tailstockGreen), 0);
  EXPECT_EQ(around(png, framePixel(14, 30), kWindow, tailstockGreen), 0);
  EXPECT_EQ(around(png, framePixel(60, -5), kWindow, holderGrey), 0);
  EXPECT_EQ(around(png, framePixel(45, -15), kWindow, holderGrey), 0);
  EXPECT_EQ(around(png, framePixel(20, -40), kWindow, jaw), 0);
  EXPECT_EQ(around(png, framePixel(20, -40), kWindow, tailstockGreen), 0);
}

TEST(MachinePicture, TheViewFramesTheTailstocksCone) {
  PartImageOptions options = machineScene();
  const PictureFrame frame = partPictureFrame(options, interp::Toolpath{}, TriangleMesh{});
  EXPECT_NEAR(frame.pxPerMm, 438.0 / 130.0, 1e-9);
  EXPECT_NEAR(frame.centreMm.x(), (-72 + 10 / std::tan(M_PI / 6)) / 2, 1e-9);
  options.tailstock.reset();  // without it the frame ends at the bar's face
  EXPECT_NEAR(partPictureFrame(options, interp::Toolpath{}, TriangleMesh{}).centreMm.x(), -36.0, 1e-9);
}

std::uint32_t word(const std::string& bytes, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
}

// The 3D view's machine: each mesh named, at the sizes the pictures draw (part coordinates,
// mm: x the radius, y across the meridian plane, z the axis).
TEST(MachinePicture, TheGlbCarriesTheMachineAtItsSizes) {
  const PartImageOptions options = machineScene();
  const std::string glb = partGlb(test::cylinder(30, 60, 24), test::rapidThenFeed(), {},
                                  SceneMachine{options.chuck, options.tailstock, options.tool});
  const nlohmann::json gltf = nlohmann::json::parse(glb.substr(20, word(glb, 12)));
  const auto bounds = [&](const std::string& name) {
    for (const auto& mesh : gltf["meshes"])
      if (mesh["name"] == name) return gltf["accessors"][mesh["primitives"][0]["attributes"]["POSITION"].get<int>()];
    ADD_FAILURE() << "no mesh " << name;
    return nlohmann::json::object({{"min", {0, 0, 0}}, {"max", {0, 0, 0}}});
  };
  const auto expectBox = [&](const std::string& name, std::array<double, 3> low, std::array<double, 3> high) {
    const auto accessor = bounds(name);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(accessor["min"][i].get<double>(), low[i], 1e-3) << name << " axis " << i;
      EXPECT_NEAR(accessor["max"][i].get<double>(), high[i], 1e-3) << name << " axis " << i;
    }
  };
  // The holder: r 50..100, behind the plane by its 25 mm, Z−30..−10; the insert 5 mm thick,
  // its rake face 0.05 mm proud.
  expectBox("machine holder", {50, -25, -30}, {100, 0, -10});
  expectBox("machine insert", {40, -5, -30}, {50, 0.05, -20});
  // The tailstock: its point at Z0 out to the quill's end, 17.32 + 40; r 10 round.
  const auto tail = bounds("machine tailstock");
  EXPECT_NEAR(tail["min"][2].get<double>(), 0, 1e-3);
  EXPECT_NEAR(tail["max"][2].get<double>(), 10 / std::tan(M_PI / 6) + 40, 1e-3);
  EXPECT_NEAR(tail["max"][0].get<double>(), 10, 1e-3);
  // The jaws: the top one up to r 50, the lower ones down to −0.5·50 − 0.866·9; on Z−80..−60.
  const auto jaws = bounds("machine jaws");
  EXPECT_NEAR(jaws["max"][0].get<double>(), 50, 1e-3);
  EXPECT_NEAR(jaws["min"][0].get<double>(), -25 - std::sqrt(3.0) / 2 * 9, 1e-3);
  EXPECT_NEAR(jaws["min"][2].get<double>(), -80, 1e-3);
  EXPECT_NEAR(jaws["max"][2].get<double>(), -60, 1e-3);
  // Without a machine, the part and the toolpath alone, as before.
  const nlohmann::json plain = nlohmann::json::parse([&] {
    const std::string bare = partGlb(test::cylinder(30, 60, 24), test::rapidThenFeed());
    return bare.substr(20, word(bare, 12));
  }());
  EXPECT_EQ(plain["meshes"].size(), 3u);
}

}  // namespace
}  // namespace lathesim::render
