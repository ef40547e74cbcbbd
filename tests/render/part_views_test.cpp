// The part pictures' views pinned by colours at known pixels: the part, the bar's ghost, the
// chuck's jaws, the section's cut face, the dimension text and the tool.

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/revolved_mesh.hpp"
#include "render/part_image.hpp"
#include "tests/render/png_pixels.hpp"
#include "tests/render/test_meshes.hpp"

namespace lathesim::render {
namespace {

using test::Png;
using test::PngColour;
using test::partMetal;

// Colour classes, loose enough for lighting and anti-aliasing, apart from one another; the
// part's metal is test::partMetal (png_pixels.hpp), which tells it from the background.
bool ghost(const PngColour& c) { return c.r > 180 && c.r - c.b > 25 && c.g > c.b; }  // amber over the background
bool jaw(const PngColour& c) { return c.b - c.r > 30 && c.b < 210 && c.r < 140; }     // blue steel, darker than a feed
bool cutFace(const PngColour& c) { return c.b > 170 && c.b - c.r > 30 && c.g > c.r; }
bool purple(const PngColour& c) { return c.r - c.g > 40 && c.b - c.g > 40; }
bool redLine(const PngColour& c) { return c.r > 150 && c.r > c.g + 80 && c.r > c.b + 80; }

/// A Φ40 × 60 part (Z−60..0) in a Φ60 bar, jaws from r 30 to 50 on Z−80..−60, the body behind
/// to Z−180; Ø40 and the 60 length dimensioned; a 10 mm square insert at (r 25, Z10); a rapid
/// in from X200 Z200 (out of the picture) and a feed along r 20.
struct Scene {
  TriangleMesh part = revolvedMesh({{{0, 0}, {20, 0}, {20, -60}, {0, -60}}}, 96);
  interp::Toolpath path;
  PartImageOptions options;

  Scene() {
    path.programName = "views.nc";
    path.moves.push_back(test::move(interp::MoveKind::Rapid, 100, 200, 20, 5, 1, 0));
    path.moves.push_back(test::move(interp::MoveKind::Feed, 20, 5, 20, -40, 2, 0.2));
    options.widthPx = 800;
    options.heightPx = 600;
    options.title = "views.nc";
    options.bar = BarOutline{30, -60, 0};
    options.chuck = ChuckPicture{30, 50, -80, -60, -180};
    options.dimensions.diameters.push_back({40, -60, 0, false});
    options.dimensions.lengths.push_back({-60, 0, 20, 20});
    ToolPicture tool;
    tool.insert = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    tool.position = RZ(25, 10);
    options.tool = tool;
  }
};

// The front view frames, by hand: the bar, the insert (it stands within a quarter of the frame,
// so it is framed) and the jaws' front ends — 0.2 of the bar's length behind their face
// (Z−72) and 0.25 of its radius out past it (r 37.5). Across (Z): Z−72 to the insert's Z20,
// 92 mm. Up (X): the bar's −30 (below the lower jaws' −0.5·37.5 − 0.866·9 = −26.54; 9 mm =
// 0.18·50 either side of a jaw) to the top jaw's 37.5: 67.5 mm. With 6 % margins and 15 %
// more on top, 800 × 600 px leaves 704 × 438 px: 438 / 67.5 = 6.4889 px/mm (< 704 / 92).
// Centre: Z−26 across; up, the extent's middle 3.75 sits at 255 px, so the picture's centre
// (300 px) is at 3.75 + 45 / 6.4889 = 10.685. A point (r, z):
// x = 400 + (z + 26)·6.4889, y = 300 + (r − 10.685)·6.4889.
Eigen::Vector2i frontPixel(double r, double z) {
  const double pxPerMm = 438.0 / 67.5;
  return {static_cast<int>(std::lround(400 + (z + 26) * pxPerMm)),
          static_cast<int>(std::lround(300 + (r - (3.75 + 45 / pxPerMm)) * pxPerMm))};
}

/// How many pixels of a (2·half+1)² window about p pass `test`.
template <class Test>
int around(const Png& png, const Eigen::Vector2i& p, int half, Test test) {
  return png.count(p.x() - half, p.x() + half + 1, p.y() - half, p.y() + half + 1, test);
}

TEST(PartViews, FrontViewShowsPartGhostJawToolAndDimensionsWhereTheyStand) {
  ::unsetenv("DISPLAY");
  Scene scene;
  scene.options.view = PartView::Front;
  test::TempDir dir;
  writePartImagePng(scene.part, scene.path, scene.options, dir.path() / "front.png");
  const Png png(dir.path() / "front.png");
  const auto metal = [&png](int x, int y) { return partMetal(png, x, y); };
  ASSERT_EQ(png.width(), 800);
  constexpr int kWindow = 4;  // 9 × 9 px
  // Z−45, clear of the Ø40 dimension line, which stands at the middle of its face (Z−30).
  EXPECT_EQ(around(png, frontPixel(-10, -45), kWindow, metal), 81);  // the part, below its axis
  EXPECT_EQ(around(png, frontPixel(-25, -30), kWindow, ghost), 81);  // the bar's removed ring
  EXPECT_EQ(around(png, frontPixel(40, -70), kWindow, jaw), 81);     // the top jaw
  EXPECT_GT(around(png, frontPixel(30, 15), kWindow, test::insertGold), 70);     // the insert's middle: r 25–35, Z10–20
  EXPECT_EQ(around(png, frontPixel(40, 5), kWindow, ghost), 0);      // beyond the bar: background
  // The 60 length: its line 0.8 of a spacing (27 px) above the dimension band's foot (474 px),
  // from Z−60 to Z0, and its figure centred above it.
  const int lineY = static_cast<int>(474 + 0.8 * 27);
  EXPECT_GT(png.count(frontPixel(0, -55).x(), frontPixel(0, -5).x(), lineY - 1, lineY + 2, purple), 200);
  const int figureX = frontPixel(0, -30).x();  // "60.0", centred on the length
  EXPECT_GT(png.count(figureX - 20, figureX + 20, lineY + 4, lineY + 20, purple), 15);
  // The rapid from X200 Z200 comes in at the picture's right or top edge: red there.
  EXPECT_GT(png.count(560, 800, 300, 600, redLine), 40);
}

TEST(PartViews, SectionViewCutsTheUpperHalfAndKeepsTheLowerAsSeen) {
  ::unsetenv("DISPLAY");
  Scene scene;
  scene.options.view = PartView::Section;
  // The part's section, sampled every 0.5 mm: inside r < 20, −60 < z < 0.
  SampledSection section;
  section.stepMm = 0.5;
  section.zFirstMm = -70;
  section.rCount = 70;
  section.zCount = 160;
  section.clampMm = 1.5;
  for (int k = 0; k < section.zCount; ++k)
    for (int i = 0; i < section.rCount; ++i) {
      const double r = i * 0.5, z = -70 + k * 0.5;
      const double outside = std::max({r - 20, z, -60 - z});
      section.phi.push_back(static_cast<float>(std::clamp(outside, -1.5, 1.5)));
    }
  scene.options.section = section;
  test::TempDir dir;
  writePartImagePng(scene.part, scene.path, scene.options, dir.path() / "section.png");
  const Png png(dir.path() / "section.png");
  const auto metal = [&png](int x, int y) { return partMetal(png, x, y); };
  constexpr int kWindow = 4;
  // Z−45, clear of the Ø40 dimension line at Z−30.
  EXPECT_EQ(around(png, frontPixel(10, -45), kWindow, cutFace), 81);  // the cut, above the axis
  EXPECT_EQ(around(png, frontPixel(-10, -45), kWindow, metal), 81);   // the part as seen, below
  EXPECT_EQ(around(png, frontPixel(25, -30), kWindow, ghost), 81);    // removed, above
  EXPECT_EQ(around(png, frontPixel(-25, -30), kWindow, ghost), 81);   // and below
  EXPECT_EQ(around(png, frontPixel(40, -70), kWindow, jaw), 81);      // the jaw, cut
  EXPECT_EQ(around(png, frontPixel(10, -45), kWindow, metal), 0);
}

TEST(PartViews, IsoViewFramesTheBarNotTheRapidAndMarksWhereItGoes) {
  ::unsetenv("DISPLAY");
  Scene scene;
  test::TempDir dir;
  writePartImagePng(scene.part, scene.path, scene.options, dir.path() / "iso.png");
  const Png png(dir.path() / "iso.png");
  // The bar (and the part in it) fills the middle: the rapid's far end, X200 Z200, does not
  // push it into a corner. Its row of pixels through the axis is mostly part.
  int widest = 0;
  for (int y = 0; y < 600; y += 2) {
    int run = 0;
    for (int x = 0; x < 800; ++x) {
      run = partMetal(png, x, y) ? run + 1 : 0;
      widest = std::max(widest, run);
    }
  }
  EXPECT_GT(widest, 800 / 4);  // the part, Φ40 × 60 beside jaws reaching Z−80: about a third
  EXPECT_GT(png.count(0, 800, 0, 600, ghost), 3000);
  EXPECT_GT(png.count(0, 800, 0, 600, jaw), 3000);
  EXPECT_GT(png.count(0, 800, 400, 600, purple), 150);  // the length, above the bar
  // The rapid enters at the edge with an arrowhead: red near the right or top border.
  EXPECT_GT(png.count(700, 800, 0, 600, redLine) + png.count(0, 800, 540, 600, redLine), 20);
}

// A crash is marked where it happened: a red disc (redder than the rapids' dashes) centred on
// the point the frame projects it to, in every view, with its label; nothing of that red
// without one. The front view's projection is the one worked by hand above (frontPixel).
bool crashRed(const PngColour& c) { return c.r >= 240 && c.g <= 25 && c.b <= 25; }

TEST(PartViews, ACrashIsARedDiscWhereItHappenedInEveryView) {
  ::unsetenv("DISPLAY");
  const RZ crash(20, -20);  // on the part's surface, under the feed
  for (const PartView view : {PartView::Iso, PartView::Front, PartView::Section}) {
    SCOPED_TRACE(viewName(view));
    Scene scene;
    scene.options.view = view;
    const PictureFrame frame = partPictureFrame(scene.options, scene.path, scene.part);
    const Eigen::Vector2d at = frame.pixelOf(crash);
    if (view == PartView::Front) {
      EXPECT_NEAR(at.x(), frontPixel(20, -20).x(), 1.0);
      EXPECT_NEAR(at.y(), frontPixel(20, -20).y(), 1.0);
    }
    const Eigen::Vector2i centre(static_cast<int>(std::lround(at.x())), static_cast<int>(std::lround(at.y())));
    const int half = static_cast<int>(crashMarkRadiusPx(scene.options.heightPx) / 2);  // well inside the disc
    const int window = (2 * half + 1) * (2 * half + 1);
    test::TempDir dir;
    writePartImagePng(scene.part, scene.path, scene.options, dir.path() / "plain.png");
    const Png plain(dir.path() / "plain.png");
    EXPECT_EQ(plain.count(0, plain.width(), 0, plain.height(), crashRed), 0);
    scene.options.crashes.push_back({crash, "crash, line 8"});
    writePartImagePng(scene.part, scene.path, scene.options, dir.path() / "crash.png");
    const Png png(dir.path() / "crash.png");
    EXPECT_EQ(around(png, centre, half, crashRed), window);
    // The label, to the right of the disc.
    const int right = centre.x() + static_cast<int>(1.6 * crashMarkRadiusPx(scene.options.heightPx));
    EXPECT_GT(png.count(right, right + 120, centre.y() - 10, centre.y() + 30,
                        [](const PngColour& c) { return c.r > 200 && c.g < 120 && c.b < 120; }),
              20);
  }
}

TEST(PartViews, ViewsAreNamed) {
  for (PartView v : {PartView::Iso, PartView::Front, PartView::Section}) EXPECT_EQ(viewNamed(viewName(v)), v);
  EXPECT_FALSE(viewNamed("top"));
}

}  // namespace
}  // namespace lathesim::render
