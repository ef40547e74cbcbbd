#include "render/picture_frame.hpp"

#include <cmath>

#include <Eigen/Geometry>

namespace lathesim::render {

View partView(double azimuthDeg) {
  const double a = azimuthDeg * M_PI / 180.0;
  View v;
  v.towardsViewer = Eigen::Vector3d(0.0, std::cos(a), std::sin(a));
  v.up = Eigen::Vector3d(1.0, 0.0, 0.0);
  v.right = v.up.cross(v.towardsViewer);  // (0, −sin, cos): +Z to the right
  return v;
}

PictureFrame frameExtent(const View& view, const Extent& e, int widthPx, int heightPx, double marginFraction,
                         double topFraction) {
  PictureFrame f;
  f.view = view;
  f.widthPx = widthPx;
  f.heightPx = heightPx;
  const double spanRight = std::max(e.maxRight - e.minRight, 1e-3);
  const double spanUp = std::max(e.maxUp - e.minUp, 1e-3);
  const double usableWidth = widthPx * (1.0 - 2.0 * marginFraction);
  const double usableHeight = heightPx * (1.0 - 2.0 * marginFraction - topFraction);
  f.pxPerMm = std::min(usableWidth / spanRight, usableHeight / spanUp);
  // Centred across; up, the extent sits in the usable band, below the top's extra room.
  const double bandCentrePx = heightPx * (marginFraction + (1.0 - 2.0 * marginFraction - topFraction) / 2.0);
  f.centreMm = {(e.minRight + e.maxRight) / 2.0,
                (e.minUp + e.maxUp) / 2.0 + (heightPx / 2.0 - bandCentrePx) / f.pxPerMm};
  f.minDepthMm = e.minDepth;
  f.maxDepthMm = e.maxDepth;
  return f;
}

}  // namespace lathesim::render
