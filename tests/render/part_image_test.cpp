#include "render/part_image.hpp"

#include <gtest/gtest.h>

#include "tests/render/png_pixels.hpp"
#include "tests/render/test_meshes.hpp"

namespace lathesim::render {
namespace {

using test::Png;
using test::Rgb;

bool blue(const Rgb& c) { return c.b > 150 && c.b > c.r + 80 && c.b > c.g + 60; }
bool red(const Rgb& c) { return c.r > 150 && c.r > c.g + 80 && c.r > c.b + 80; }
int distance(const Rgb& a, const Rgb& b) {
  return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
}

TEST(PartImagePng, ShadedPartWithBlueFeedAndRedRapidWithoutDisplay) {
  ::unsetenv("DISPLAY");  // the private-Xvfb path, as under CI
  const TriangleMesh part = test::cylinder(30.0, 60.0, 96, 8);
  const interp::Toolpath path = test::rapidThenFeed();
  test::TempDir dir;
  const auto file = dir.path() / "part.png";
  writePartImagePng(part, path, PartImageOptions{1600, 1200, "cylinder.nc"}, file);

  Png png(file);
  ASSERT_EQ(png.width(), 1600);
  ASSERT_EQ(png.height(), 1200);
  // The part fills the middle; the corner shows background.
  const Rgb corner = png.at(1590, 1190);
  const Rgb centre = png.at(800, 600);
  EXPECT_GT(distance(centre, corner), 40)
      << "centre " << centre.r << "," << centre.g << "," << centre.b << " corner " << corner.r
      << "," << corner.g << "," << corner.b;
  // The path, away from the legend in the lower-left corner.
  EXPECT_GT(png.count(400, 1600, 0, 1200, blue), 500);
  EXPECT_GT(png.count(400, 1600, 0, 1200, red), 100);
}

TEST(PartImagePng, EmptyMeshStillShowsTheToolpath) {
  ::unsetenv("DISPLAY");
  test::TempDir dir;
  const auto file = dir.path() / "path-only.png";
  writePartImagePng(TriangleMesh{}, test::rapidThenFeed(), PartImageOptions{800, 600, "t"},
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
  writePartImagePng(TriangleMesh{}, path, PartImageOptions{800, 600, "t"}, file);
  Png png(file);
  EXPECT_GT(png.count(200, 800, 0, 600, blue), 500);
}

TEST(PartImagePng, UnwritablePathThrows) {
  test::TempDir dir;
  EXPECT_THROW(writePartImagePng(test::cylinder(30, 60, 16), test::rapidThenFeed(),
                                 PartImageOptions{320, 240, "t"}, dir.path() / "no" / "x.png"),
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
