#include "render/part_image.hpp"

#include "render/part_picture.hpp"

namespace lathesim::render {

void writePartImagePng(const TriangleMesh& part, const interp::Toolpath& toolpath,
                       const PartImageOptions& options, const std::filesystem::path& png) {
  PartPicture picture(options, toolpath, part);
  picture.writePng(png);
}

RgbImage partImage(const TriangleMesh& part, const interp::Toolpath& toolpath, const PartImageOptions& options) {
  PartPicture picture(options, toolpath, part);
  return picture.image();
}

}  // namespace lathesim::render
