#pragma once
// Reading a rendered PNG back, pixel by pixel, to check colours at known places.

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <type_traits>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

namespace lathesim::render::test {

struct PngColour {
  int r, g, b;
};

/// The PNG as read back; pixel (0, 0) is the lower-left corner, as VTK stores it.
class Png {
 public:
  explicit Png(const std::filesystem::path& file) {
    const std::string name = file.string();
    reader_->SetFileName(name.c_str());
    reader_->Update();
    image_ = reader_->GetOutput();
  }
  int width() const { return image_->GetDimensions()[0]; }
  int height() const { return image_->GetDimensions()[1]; }
  PngColour at(int x, int y) const {
    const auto* p = static_cast<const unsigned char*>(image_->GetScalarPointer(x, y, 0));
    return {p[0], p[1], p[2]};
  }
  /// Pixels in x ∈ [x0, x1), y ∈ [y0, y1) for which `test` holds: test(PngColour), or test(x, y)
  /// for a test that needs to know where the pixel is.
  template <class Test>
  int count(int x0, int x1, int y0, int y1, Test test) const {
    int n = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        if constexpr (std::is_invocable_v<Test, int, int>) n += test(x, y) ? 1 : 0;
        else n += test(at(x, y)) ? 1 : 0;
      }
    return n;
  }

 private:
  vtkNew<vtkPNGReader> reader_;
  vtkImageData* image_ = nullptr;
};

/// The insert's gold: strong red and green, little blue.
inline bool insertGold(const PngColour& c) { return c.r > 170 && c.g > 120 && c.b < 90 && c.r > c.b + 110; }

/// The part pictures' shaded metal: near grey, neither the ghost's amber nor the chuck's blue.
inline bool metal(const PngColour& c) {
  return std::abs(c.r - c.g) <= 14 && std::abs(c.b - c.r) <= 16 && c.r > 40 && std::max({c.r, c.g, c.b}) < 228;
}

/// The part pictures' background at row y (counted from the bottom): a gradient from
/// (0.80, 0.83, 0.87) at the bottom to white at the top (render/part_picture.cpp). Its lower
/// rows are a bluish grey that `metal` alone takes for the part, so tests that look for the
/// part ask `partMetal`.
inline bool pictureBackground(const PngColour& c, int y, int height) {
  const double top = height > 1 ? static_cast<double>(y) / (height - 1) : 1.0;
  const double expected[3] = {255 * (0.80 + 0.20 * top), 255 * (0.83 + 0.17 * top), 255 * (0.87 + 0.13 * top)};
  return std::abs(c.r - expected[0]) + std::abs(c.g - expected[1]) + std::abs(c.b - expected[2]) <= 12;
}

/// The part's shaded metal at pixel (x, y) of a part picture.
inline bool partMetal(const Png& png, int x, int y) {
  const PngColour c = png.at(x, y);
  return metal(c) && !pictureBackground(c, y, png.height());
}

}  // namespace lathesim::render::test
