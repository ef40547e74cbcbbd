// Pixels in memory as VTK image data and as PNG bytes (see rgb_image.hpp, vtk_image.hpp).

#include "render/rgb_image.hpp"

#include <stdexcept>

#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include "render/vtk_image.hpp"

namespace lathesim::render {

vtkSmartPointer<vtkImageData> imageDataOf(const RgbImage& image) {
  if (image.widthPx <= 0 || image.heightPx <= 0 ||
      image.rgb.size() != static_cast<std::size_t>(image.widthPx) * static_cast<std::size_t>(image.heightPx) * 3)
    throw std::runtime_error("an image of " + std::to_string(image.widthPx) + "×" + std::to_string(image.heightPx) +
                             " pixels holding " + std::to_string(image.rgb.size()) + " bytes");
  vtkNew<vtkUnsignedCharArray> pixels;
  pixels->SetNumberOfComponents(3);
  // save = 1: the array never frees nor writes the vector's memory (VTK takes no const pointer).
  pixels->SetArray(const_cast<unsigned char*>(image.rgb.data()), static_cast<vtkIdType>(image.rgb.size()), 1);
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetDimensions(image.widthPx, image.heightPx, 1);
  data->GetPointData()->SetScalars(pixels);
  return data;
}

std::string pngOf(vtkImageData* data) {
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(data);
  writer->WriteToMemoryOn();
  writer->Write();
  vtkUnsignedCharArray* bytes = writer->GetResult();
  if (bytes == nullptr || bytes->GetNumberOfValues() == 0) throw std::runtime_error("cannot encode the image as PNG");
  return std::string(reinterpret_cast<const char*>(bytes->GetPointer(0)), static_cast<std::size_t>(bytes->GetNumberOfValues()));
}

std::string encodePng(const RgbImage& image) { return pngOf(imageDataOf(image)); }

}  // namespace lathesim::render
