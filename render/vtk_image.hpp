#pragma once
// Inside render only: an RgbImage as VTK image data, and VTK image data as PNG bytes.

#include <string>

#include <vtkImageData.h>
#include <vtkSmartPointer.h>

#include "render/rgb_image.hpp"

namespace lathesim::render {

/// `image`'s pixels as VTK image data (one slice, 3 unsigned char components), not copied:
/// `image` must outlive it and is only read through it.
vtkSmartPointer<vtkImageData> imageDataOf(const RgbImage& image);

/// `data` (unsigned char RGB) encoded as a PNG. Throws std::runtime_error if it cannot be encoded.
std::string pngOf(vtkImageData* data);

}  // namespace lathesim::render
