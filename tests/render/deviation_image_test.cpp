// The drawing-check pictures, read back pixel by pixel at places worked out from their
// framing: gouge blue, within tolerance withinToleranceGreen, excess red, on the part and on the colour bar.

#include "render/deviation_image.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/render/png_pixels.hpp"
#include "tests/render/test_meshes.hpp"

namespace lathesim::render {
namespace {

using test::Png;
using test::PngColour;

bool blue(const PngColour& c) { return c.b > 120 && c.b > c.r + 60 && c.b > c.g + 30; }
bool withinToleranceGreen(const PngColour& c) { return c.g > 100 && c.g > c.r + 40 && c.g > c.b + 40; }
bool red(const PngColour& c) { return c.r > 120 && c.r > c.g + 60 && c.r > c.b + 60; }
bool dark(const PngColour& c) { return c.r + c.g + c.b < 200; }

std::string describe(const PngColour& c) {
  return std::to_string(c.r) + "," + std::to_string(c.g) + "," + std::to_string(c.b);
}

// A cylinder r 30, Z0..60, its vertices' deviations: −1 mm (gouge) for Z < 20, 0 for
// 20 ≤ Z ≤ 40, +1 (excess) beyond; tolerance 0.2.
//
// Where Z lands: the camera looks along (0, cos 22°, sin 22°) with X up, so a point's
// horizontal coordinate is −y·sin 22° + z·cos 22°. The part spans −11.24 … 66.86 across
// (the far rim of the Z60 end face reaches 60·0.927 + 30·0.375) and −30 … 30 up. The part's
// viewport is 74 % × 88 % of 1600 × 1200 = 1184 × 1056 px (aspect 1.121); the framing is
// 1.05·max(30, 39.05/1.121) = 36.58 mm per half-height, 528/36.58 = 14.43 px/mm, centred on
// 27.81 mm at x = 592. At mid-height (y = 528) the visible surface is the front line y = 30:
// horizontal −11.24 + 0.927·Z. Z10 → x ≈ 592 + (−1.97 − 27.81)·14.43 ≈ 162; Z30 → 430;
// Z50 → 698.
TEST(DeviationImagePng, PartColouredByDeviationWithLabelledBar) {
  ::unsetenv("DISPLAY");
  const TriangleMesh part = test::cylinder(30.0, 60.0, 96, 12);
  std::vector<float> deviation;
  for (const auto& v : part.vertices) deviation.push_back(v.z() < 19.9f ? -1.0f : v.z() > 40.1f ? 1.0f : 0.0f);
  test::TempDir dir;
  const auto file = dir.path() / "deviation.png";
  DeviationImageOptions options;
  options.title = "cylinder.nc against drawing.toml";
  options.toleranceMm = 0.2;
  writeDeviationImagePng(part, deviation, options, file);

  Png png(file);
  ASSERT_EQ(png.width(), 1600);
  ASSERT_EQ(png.height(), 1200);
  EXPECT_TRUE(blue(png.at(162, 528))) << describe(png.at(162, 528));
  EXPECT_TRUE(withinToleranceGreen(png.at(430, 528))) << describe(png.at(430, 528));
  EXPECT_TRUE(red(png.at(698, 528))) << describe(png.at(698, 528));
  // The colour bar: its box starts at 87 % of the width, from 8 % to 86 % of the height,
  // the bar itself at the box's left; red at the top, withinToleranceGreen across the middle, blue below.
  const int barX0 = static_cast<int>(0.87 * 1600), barX1 = barX0 + 60;
  EXPECT_GT(png.count(barX0, barX1, 950, 1000, red), 500);
  EXPECT_GT(png.count(barX0, barX1, 560, 600, withinToleranceGreen), 500);
  EXPECT_GT(png.count(barX0, barX1, 130, 180, blue), 500);
  // Its labels in dark text left of the bar, at their values' heights (the bar maps −1 … +1
  // onto y 96 … 1032): "excess" at +0.75 (y 915), "within tolerance" at 0 (564), "gouge" at
  // −0.75 (213); and nothing dark between them.
  EXPECT_GT(png.count(barX0 - 200, barX0, 895, 935, dark), 30);
  EXPECT_GT(png.count(barX0 - 200, barX0, 544, 584, dark), 30);
  EXPECT_GT(png.count(barX0 - 200, barX0, 193, 233, dark), 30);
  EXPECT_EQ(png.count(barX0 - 200, barX0, 300, 500, dark), 0);
}

TEST(DeviationImagePng, OneDeviationPerVertex) {
  test::TempDir dir;
  EXPECT_THROW(writeDeviationImagePng(test::cylinder(30, 60, 16), {1.0f}, {}, dir.path() / "x.png"),
               std::runtime_error);
}

// A Φ40 shaft drawn Z-30..0 with a gouge (r 19..20, Z-10..0) and an excess (r 20..21, Z-25..-20).
TEST(SectionImagePng, ProfileAgainstDrawingWithFilledDeviations) {
  ::unsetenv("DISPLAY");
  SectionImage image;
  image.title = "shaft.nc against drawing.toml, half-section";
  image.drawing = {{RZ(0, 0), RZ(20, 0)}, {RZ(20, 0), RZ(20, -30)}, {RZ(20, -30), RZ(0, -30)}};
  image.part = {{RZ(0, 0), RZ(19, 0)},      {RZ(19, 0), RZ(19, -10)},   {RZ(19, -10), RZ(20, -10)},
                {RZ(20, -10), RZ(20, -20)}, {RZ(20, -20), RZ(21, -20)}, {RZ(21, -20), RZ(21, -25)},
                {RZ(21, -25), RZ(20, -25)}, {RZ(20, -25), RZ(20, -30)}, {RZ(20, -30), RZ(0, -30)}};
  image.cellMm = 0.5;
  for (double z = -9.75; z < 0; z += 0.5) image.gougeCells.insert(image.gougeCells.end(), {RZ(19.25, z), RZ(19.75, z)});
  for (double z = -24.75; z < -20; z += 0.5) image.excessCells.insert(image.excessCells.end(), {RZ(20.25, z), RZ(20.75, z)});
  image.labels = {{RZ(19, -5), "gouge 1.000 mm", true}};
  test::TempDir dir;
  const auto file = dir.path() / "section.png";
  writeSectionImagePng(image, file);

  Png png(file);
  ASSERT_EQ(png.width(), 1600);
  ASSERT_EQ(png.height(), 900);
  // The frame: 30 mm across at most 86 % of 1600 px (45.9 px/mm), 21 mm up at most 62 % of
  // 900 px (26.6 px/mm): 26.57 px/mm, the axis at 15 % of the height.
  const SectionFrame f = sectionFrame(image);
  EXPECT_NEAR(f.pxPerMm, 0.62 * 900 / 21, 1e-9);
  EXPECT_NEAR(f.pixelOf(RZ(0, -15)).y(), 0.15 * 900 - 0.5 * 0, 1.0);
  const auto at = [&](double r, double z) {
    const Eigen::Vector2d p = f.pixelOf(RZ(r, z));
    return png.at(static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y())));
  };
  EXPECT_TRUE(blue(at(19.5, -2.5))) << describe(at(19.5, -2.5));  // gouge fill, between the lines
  EXPECT_TRUE(red(at(20.5, -22.5))) << describe(at(20.5, -22.5));  // excess fill
  EXPECT_FALSE(blue(at(10, -15)) || red(at(10, -15)));            // the section's inside is plain
  // The drawing's line r 20 over Z-20..-10 (dark, drawn over the part's blue line).
  const Eigen::Vector2d line = f.pixelOf(RZ(20, -15));
  EXPECT_GT(png.count(static_cast<int>(line.x()) - 20, static_cast<int>(line.x()) + 20,
                      static_cast<int>(line.y()) - 3, static_cast<int>(line.y()) + 4, dark), 20);
  // The label, above the profile, in the gouge's colour.
  EXPECT_GT(png.count(0, 1600, static_cast<int>(f.pixelOf(RZ(21, 0)).y()), 900 - 100, blue), 100);
}

// Every label gets a box, none overprints another, and each stays in the picture — however
// many findings crowd one place (twenty on one shoulder) or spread along the part.
TEST(SectionLabels, BoxesNeverIntersect) {
  for (const int count : {1, 2, 7, 20}) {
    for (const bool crowded : {true, false}) {
      SectionImage image;
      image.drawing = {{RZ(0, 0), RZ(20, 0)}, {RZ(20, 0), RZ(20, -30)}, {RZ(20, -30), RZ(0, -30)}};
      for (int n = 0; n < count; ++n)
        image.labels.push_back({crowded ? RZ(20, -10) : RZ(20, -30.0 * n / count), "gouge " + std::to_string(n) + "\nZ-10", n % 2 == 0});
      const SectionFrame f = sectionFrame(image);
      const std::vector<LabelBox> boxes = sectionLabelBoxes(image, f);
      ASSERT_EQ(boxes.size(), image.labels.size()) << count;
      for (std::size_t a = 0; a < boxes.size(); ++a) {
        EXPECT_GE(boxes[a].left, 0);
        EXPECT_LE(boxes[a].right, image.widthPx);
        EXPECT_GE(boxes[a].bottom, 0);
        EXPECT_LE(boxes[a].top, image.heightPx);
        for (std::size_t b = a + 1; b < boxes.size(); ++b)
          EXPECT_FALSE(boxes[a].intersects(boxes[b])) << count << " labels, " << a << " and " << b;
      }
    }
  }
}

}  // namespace
}  // namespace lathesim::render
