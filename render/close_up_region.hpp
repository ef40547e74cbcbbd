#pragma once
// What of the part a close-up picture shows, so that it is meshed for the picture alone (the
// cost of the box, not of the part) and finer than the voxels.

#include <Eigen/Core>

#include "render/part_image.hpp"

namespace lathesim::render {

/// The block of space to mesh for a close-up of `box` seen from the front in a picture of
/// widthPx × heightPx: the box stretched to the picture's aspect with its margins, the half
/// of the part toward the viewer (+Y) and a margin behind the meridian plane, where the
/// silhouette's crests may come from; and how many times finer than `voxelMm` to sample
/// the level set's surface there.
struct CloseUpRegion {
  Eigen::Vector3d low{0, 0, 0}, high{0, 0, 0};  // (x, y, z) mm
  int subdivisions = 1;
};

CloseUpRegion closeUpRegion(const CloseUp& box, int widthPx, int heightPx, double voxelMm);

}  // namespace lathesim::render
