#include "render/part_image.hpp"

#include <gtest/gtest.h>

#include "tests/render/png_pixels.hpp"
#include "tests/render/test_meshes.hpp"

namespace lathesim::render {
namespace {

using test::Png;
using test::PngColour;

bool blue(const PngColour& c) { return c.b > 150 && c.b > c.r + 80 && c.b > c.g + 60; }
bool red(const PngColour& c) { return c.r > 150 && c.r > c.g + 80 && c.r > c.b + 80; }
bool green(const PngColour& c) { return c.g > 110 && c.g > c.r + 60 && c.g > c.b + 40; }
// The holder's dark steel grey: dark, and nearly neutral.
bool steel(const PngColour& c) {
  return c.r < 110 && c.g < 110 && c.b < 120 && c.r > 30 && std::abs(c.r - c.b) < 30;
}
int distance(const PngColour& a, const PngColour& b) {
  return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
}

TEST(PartImagePng, ShadedPartWithBlueFeedAndRedRapidWithoutDisplay) {
  ::unsetenv("DISPLAY");  // the private-Xvfb path, as under CI
  const TriangleMesh part = test::cylinder(30.0, 60.0, 96, 8);
  const interp::Toolpath path = test::rapidThenFeed();
  test::TempDir dir;
  const auto file = dir.path() / "part.png";
  writePartImagePng(part, path, PartImageOptions{1600, 1200, "cylinder.nc", {}}, file);

  Png png(file);
  ASSERT_EQ(png.width(), 1600);
  ASSERT_EQ(png.height(), 1200);
  // The part fills the middle; the corner shows background.
  const PngColour corner = png.at(1590, 1190);
  const PngColour centre = png.at(800, 600);
  EXPECT_GT(distance(centre, corner), 40)
      << "centre " << centre.r << "," << centre.g << "," << centre.b << " corner " << corner.r
      << "," << corner.g << "," << corner.b;
  // The path, away from the legend in the lower-left corner.
  EXPECT_GT(png.count(400, 1600, 0, 1200, blue), 500);
  EXPECT_GT(png.count(400, 1600, 0, 1200, red), 100);
}

// Thread moves are drawn green (with their legend line); none are without them.
TEST(PartImagePng, ThreadMovesAreGreen) {
  ::unsetenv("DISPLAY");
  interp::Toolpath path = test::rapidThenFeed();
  interp::Move thread = path.moves.back();
  thread.kind = interp::MoveKind::Thread;
  thread.thread = {2.0, true, 0.0, 1};
  thread.from = RZ(28, 10);
  thread.to = RZ(28, -50);
  path.moves.push_back(thread);
  test::TempDir dir;
  writePartImagePng(TriangleMesh{}, path, PartImageOptions{800, 600, "t", {}, {}}, dir.path() / "thread.png");
  EXPECT_GT(Png(dir.path() / "thread.png").count(200, 800, 0, 600, green), 200);
  writePartImagePng(TriangleMesh{}, test::rapidThenFeed(), PartImageOptions{800, 600, "t", {}, {}}, dir.path() / "none.png");
  EXPECT_EQ(Png(dir.path() / "none.png").count(0, 800, 0, 600, green), 0);
}

// A close-up frames its box, straight from the side, without the toolpath: the box Z-10…10,
// r 20…40 of a Φ60 cylinder fills the picture's width, the cylinder's top edge (r 30) across
// its middle, and no path colour shows.
TEST(PartImagePng, CloseUpFramesItsBoxWithoutTheToolpath) {
  ::unsetenv("DISPLAY");
  test::TempDir dir;
  PartImageOptions options{800, 600, "close", {}};
  options.view = PartView::Front;
  options.closeUp = CloseUp{-10, 10, 20, 40};
  writePartImagePng(test::cylinder(30.0, 60.0, 96, 8), test::rapidThenFeed(), options, dir.path() / "close.png");
  Png png(dir.path() / "close.png");
  EXPECT_EQ(png.count(0, 800, 0, 600, blue) + png.count(0, 800, 0, 600, red), 0);
  // The part below the edge, background above it.
  const PngColour below = png.at(400, 150), above = png.at(400, 450);
  EXPECT_GT(distance(below, above), 40);
}

TEST(PartImagePng, EmptyMeshStillShowsTheToolpath) {
  ::unsetenv("DISPLAY");
  test::TempDir dir;
  const auto file = dir.path() / "path-only.png";
  writePartImagePng(TriangleMesh{}, test::rapidThenFeed(), PartImageOptions{800, 600, "t", {}},
                    file);
  Png png(file);
  ASSERT_EQ(png.width(), 800);
  EXPECT_GT(png.count(200, 800, 0, 600, blue), 200);
  EXPECT_GT(png.count(200, 800, 0, 600, red), 50);
}

TEST(PartImagePng, ArcsAreDrawnRoundInTheFeedColour) {
  ::unsetenv("DISPLAY");
  // Only a rapid and a full circle (G02 with I/K, end = start) of radius 20 about (40, 30):
  // drawn as 71 chords in blue. As a straight move it would be a point and nothing blue.
  interp::Toolpath path;
  path.moves.push_back(test::move(interp::MoveKind::Rapid, 80, 80, 60, 30, 1, 0.0));
  auto circle = test::move(interp::MoveKind::ArcCW, 60, 30, 60, 30, 2, 0.1);
  circle.center = RZ(40, 30);
  path.moves.push_back(circle);
  test::TempDir dir;
  const auto file = dir.path() / "circle.png";
  writePartImagePng(TriangleMesh{}, path, PartImageOptions{800, 600, "t", {}}, file);
  Png png(file);
  EXPECT_GT(png.count(200, 800, 0, 600, blue), 500);
}

// A Φ60 × 60 cylinder (z 0..60) and a 10 mm square insert at r 40, Z 70 (so r 40..50,
// Z 70..80) on a shank r 42..48 up to Z 130, no toolpath, no bar, 800 × 600 px. By hand, in
// the view's axes (22° turn about X):
//   right = −y·sin22° + z·cos22°: the cylinder gives −30·0.374607 = −11.238 (y = 30, z = 0);
//   the tool, standing within a quarter of that of the part, is framed too, with its holder:
//   its shank's end reaches 130·0.927184 = 120.534. So right ∈ [−11.238, 120.534], 131.772
//   wide, centre 54.648.
//   up = r: −30 (the cylinder's underside) to 50 (the insert), centre 10.
//   6 % margins and 15 % more on top leave 704 × 438 px: 704 / 131.772 = 5.3425 px/mm
//   (< 438 / 80); the extent's middle sits at 255 px, so the picture's centre (300 px) is
//   up = 10 + 45/5.3425 = 18.423.
// The insert's centre (r 45, y 0, Z 75): right = 75·0.927184 = 69.539, so
//   x = 400 + (69.539 − 54.648)·5.3425 = 479.6 px; y = 300 + (45 − 18.423)·5.3425 = 442.0 px (from below).
// The insert spans ±5 mm = ±26.7 px up and ±5·0.927 mm = ±24.8 px across there. The shank
// (Z 80..130, r 42..48) runs from x 494 to 752 px, y 426 to 458 px.
TEST(PartImagePng, ToolIsDrawnGoldWhereItStandsAndNotWithoutOne) {
  ::unsetenv("DISPLAY");
  const TriangleMesh part = test::cylinder(30.0, 60.0, 96, 8);
  interp::Toolpath none;
  ToolPicture tool;
  tool.insert = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  tool.holder = {{2, 8}, {8, 8}, {8, 60}, {2, 60}};  // a shank up the Z axis, behind the insert
  tool.position = RZ(40, 70);
  test::TempDir dir;
  PartImageOptions options{800, 600, "t", {}};
  options.tool = tool;
  writePartImagePng(part, none, options, dir.path() / "tool.png");
  Png withTool(dir.path() / "tool.png");
  // A 31 × 31 px window about the insert's centre is gold (its edge lines lie outside it).
  EXPECT_GT(withTool.count(464, 495, 427, 458, test::insertGold), 31 * 31 * 9 / 10);
  // Gold only there: nothing below the insert (y < 442 − 27 − 10 px, the part and background).
  EXPECT_EQ(withTool.count(0, 800, 0, 405, test::insertGold), 0);
  // The holder's shank to the right of the insert, whole in the picture: steel along it, none
  // past its end.
  EXPECT_GT(withTool.count(520, 740, 432, 452, steel), 200 * 18);
  EXPECT_EQ(withTool.count(765, 800, 420, 465, steel), 0);

  PartImageOptions plain{800, 600, "t", {}};
  writePartImagePng(part, none, plain, dir.path() / "plain.png");
  Png without(dir.path() / "plain.png");
  EXPECT_EQ(without.count(0, 800, 0, 600, test::insertGold), 0);
}

TEST(PartImagePng, UnwritablePathThrows) {
  test::TempDir dir;
  EXPECT_THROW(writePartImagePng(test::cylinder(30, 60, 16), test::rapidThenFeed(),
                                 PartImageOptions{320, 240, "t", {}}, dir.path() / "no" / "x.png"),
               std::runtime_error);
}

TEST(PartImagePng, RevolvedProfileIsClosed) {  // the test helper that draws shafts
  const TriangleMesh shaft =
      test::revolved({{0, 0}, {30, 0}, {30, 20}, {22, 25}, {22, 45}, {15, 50}, {15, 60}, {0, 60}},
                     64, 3);
  EXPECT_TRUE(isClosedAndOriented(shaft));
  EXPECT_GT(enclosedVolumeMm3(shaft), 0.0);
}

}  // namespace
}  // namespace lathesim::render
