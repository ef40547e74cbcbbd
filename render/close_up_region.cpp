#include "render/close_up_region.hpp"

#include <algorithm>
#include <cmath>

namespace lathesim::render {
namespace {

// What a close-up shows around its box: the box stretched to the picture's aspect, and its
// margins (6 % a side, part_picture.cpp; 25 % allowed).
constexpr double kCloseUpReach = 1.25;

// A close-up magnifies the voxels: at 0.2 mm a voxel fills ~20 pixels, and one facet a voxel
// shows as steps across the crests and saw edges along the flanks. Its mesh is made this
// many times finer than the voxels (the level set's trilinear surface), for facets of about
// 7 pixels: 3 at 0.2 mm for the default size, 1 where a voxel is small already; at most 4.
int closeUpSubdivisions(double voxelPx) {
  constexpr double kFacetPx = 7.0;
  constexpr int kMostSubdivisions = 4;
  return static_cast<int>(std::clamp(std::lround(voxelPx / kFacetPx), 1L, static_cast<long>(kMostSubdivisions)));
}

}  // namespace

CloseUpRegion closeUpRegion(const CloseUp& box, int widthPx, int heightPx, double voxelMm) {
  const double aspect = static_cast<double>(widthPx) / heightPx;
  const double lengthMm = box.zHighMm - box.zLowMm, depthMm = box.radiusHighMm - box.radiusLowMm;
  const double halfZMm = kCloseUpReach * std::max(0.5 * lengthMm, 0.5 * depthMm * aspect);
  const double halfXMm = kCloseUpReach * std::max(0.5 * depthMm, 0.5 * lengthMm / aspect);
  const double middleZMm = 0.5 * (box.zLowMm + box.zHighMm);
  const double reachMm = 0.5 * (box.radiusLowMm + box.radiusHighMm) + halfXMm;
  return {Eigen::Vector3d(reachMm - 2 * halfXMm, -halfXMm, middleZMm - halfZMm),
          Eigen::Vector3d(reachMm, reachMm, middleZMm + halfZMm),
          closeUpSubdivisions(voxelMm * widthPx / (2 * halfZMm))};
}

}  // namespace lathesim::render
