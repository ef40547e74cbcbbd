#pragma once
// Reading a rendered PNG back, pixel by pixel, to check colours at known places.

#include <filesystem>
#include <string>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

namespace lathesim::render::test {

struct Rgb {
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
  Rgb at(int x, int y) const {
    const auto* p = static_cast<const unsigned char*>(image_->GetScalarPointer(x, y, 0));
    return {p[0], p[1], p[2]};
  }
  /// Pixels in x ∈ [x0, x1), y ∈ [y0, y1) for which `test` holds.
  template <class Test>
  int count(int x0, int x1, int y0, int y1, Test test) const {
    int n = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) n += test(at(x, y)) ? 1 : 0;
    return n;
  }

 private:
  vtkNew<vtkPNGReader> reader_;
  vtkImageData* image_ = nullptr;
};

}  // namespace lathesim::render::test
