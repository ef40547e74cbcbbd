// thumbnail.png from the picture's pixels in memory against the route it replaced: the
// picture's PNG file read back, decoded and shrunk by the same block mean. Pixel for pixel.

#include "render/thumbnail.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <random>

#include <vtkImageShrink3D.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>

#include "render/part_image.hpp"
#include "tests/render/png_pixels.hpp"
#include "tests/render/test_meshes.hpp"

namespace lathesim::render {
namespace {

using test::Png;
using test::PngColour;

void writeBytes(const std::string& bytes, const std::filesystem::path& file) {
  std::ofstream(file, std::ios::binary) << bytes;
}

/// The route before: `picture` as its PNG file, read back and shrunk by vtkImageShrink3D's
/// block mean, written as the PNG `thumbnail`.
void thumbnailFromFile(const RgbImage& picture, int widthPx, const std::filesystem::path& dir,
                       const std::filesystem::path& thumbnail) {
  const std::string source = (dir / "picture.png").string(), target = thumbnail.string();
  writeBytes(encodePng(picture), source);
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(source.c_str());
  const int factor = static_cast<int>(std::lround(static_cast<double>(picture.widthPx) / widthPx));
  vtkNew<vtkImageShrink3D> shrink;
  shrink->SetInputConnection(reader->GetOutputPort());
  shrink->SetShrinkFactors(factor, factor, 1);
  shrink->AveragingOn();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(shrink->GetOutputPort());
  writer->SetFileName(target.c_str());
  writer->Write();
}

/// The number of pixels in which the two PNGs differ (-1 if their sizes differ).
int differingPixels(const Png& a, const Png& b) {
  if (a.width() != b.width() || a.height() != b.height()) return -1;
  int differing = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const PngColour p = a.at(x, y), q = b.at(x, y);
      differing += p.r != q.r || p.g != q.g || p.b != q.b;
    }
  return differing;
}

// Noise, so that a block taken one row or column off, or rows counted from the other end,
// would show; 1600 × 1200 for 240 leaves 4 columns and 3 rows over (7 × 7 blocks).
TEST(ThumbnailPng, NoiseShrunkAsFromTheFileReadBack) {
  RgbImage noise{1600, 1200, std::vector<unsigned char>(1600 * 1200 * 3)};
  std::mt19937 random(17);
  for (unsigned char& byte : noise.rgb) byte = static_cast<unsigned char>(random() & 0xff);
  test::TempDir dir;
  writeBytes(thumbnailPng(noise, 240), dir.path() / "new.png");
  thumbnailFromFile(noise, 240, dir.path(), dir.path() / "old.png");
  const Png fresh(dir.path() / "new.png"), old(dir.path() / "old.png");
  EXPECT_EQ(fresh.width(), 228);
  EXPECT_EQ(fresh.height(), 171);
  EXPECT_EQ(differingPixels(fresh, old), 0);
}

TEST(ThumbnailPng, PartPictureShrunkAsFromTheFileReadBack) {
  ::unsetenv("DISPLAY");
  const RgbImage picture =
      partImage(test::cylinder(30.0, 60.0, 96, 8), test::rapidThenFeed(), PartImageOptions{640, 480, "cylinder.nc", {}});
  test::TempDir dir;
  writeBytes(thumbnailPng(picture, 100), dir.path() / "new.png");
  thumbnailFromFile(picture, 100, dir.path(), dir.path() / "old.png");
  const Png fresh(dir.path() / "new.png"), old(dir.path() / "old.png");
  EXPECT_EQ(fresh.width(), 640 / 6);
  EXPECT_EQ(differingPixels(fresh, old), 0);
}

TEST(ThumbnailPng, AnEmptyPictureIsRefused) {
  EXPECT_THROW(thumbnailPng(RgbImage{}, 240), std::runtime_error);
  EXPECT_THROW(thumbnailPng(RgbImage{4, 4, std::vector<unsigned char>(47)}, 2), std::runtime_error);
}

}  // namespace
}  // namespace lathesim::render
