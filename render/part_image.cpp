#include "render/part_image.hpp"

#include "render/label_layout.hpp"
#include "render/part_picture.hpp"

#include <cmath>

namespace lathesim::render {

double TailstockPicture::coneEndZMm() const {
  constexpr double kHalfAngleRad = 30.0 * M_PI / 180.0;  // a 60° centre
  return pointZMm + quillRadiusMm / std::tan(kHalfAngleRad);
}

void writePartImagePng(const TriangleMesh& part, const interp::Toolpath& toolpath,
                       const PartImageOptions& options, const std::filesystem::path& png) {
  PartPicture picture(options, toolpath, part);
  picture.writePng(png);
}

PictureLayout partImageLayout(const TriangleMesh& part, const interp::Toolpath& toolpath, const PartImageOptions& options) {
  PartPicture picture(options, toolpath, part);
  PictureLayout layout;
  for (const PlacedLabel& p : picture.labels())
    layout.labels.push_back({p.label.text, p.box.left, p.box.bottom, p.box.right, p.box.top});
  layout.dimensionLines = picture.dimensionLines();
  for (const LeaderLine& leader : picture.leaders()) layout.leaders.push_back(leader.segment);
  return layout;
}

RgbImage partImage(const TriangleMesh& part, const interp::Toolpath& toolpath, const PartImageOptions& options) {
  PartPicture picture(options, toolpath, part);
  return picture.image();
}

}  // namespace lathesim::render
