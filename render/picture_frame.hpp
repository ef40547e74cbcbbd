#pragma once
// Where things land in a picture: the view a turned part is seen from, and the frame that
// maps millimetres to pixels. Plain Eigen, so framing rules can be worked out and tested by
// hand; vtk_scene.hpp turns a frame into a VTK camera.

#include <algorithm>
#include <limits>

#include <Eigen/Core>

#include "geometry/rz.hpp"

namespace lathesim::render {

/// The camera turns this far about the vertical (X) axis from square-on, towards +Z, so the
/// end face shows (the isometric-like view). Turning about X keeps the spindle axis
/// horizontal, and with a parallel projection the toolpath plane (y = 0) projects onto the
/// part's top silhouette exactly.
inline constexpr double kIsoAzimuthDeg = 22.0;

/// The view: looking at the XZ plane from +Y, turned towards +Z by an azimuth, X up.
struct View {
  Eigen::Vector3d towardsViewer, up, right;
};
/// azimuth 0 is the front view of a drawing: X up, Z to the right.
View partView(double azimuthDeg = kIsoAzimuthDeg);

/// Extent of everything drawn, along the view's axes (mm).
struct Extent {
  double minRight = std::numeric_limits<double>::infinity(), maxRight = -minRight;
  double minUp = minRight, maxUp = -minRight;
  double minDepth = minRight, maxDepth = -minRight;
  bool empty() const { return !(minRight <= maxRight); }
  void include(const View& view, const Eigen::Vector3d& p) {
    const double r = p.dot(view.right), u = p.dot(view.up), d = p.dot(view.towardsViewer);
    minRight = std::min(minRight, r), maxRight = std::max(maxRight, r);
    minUp = std::min(minUp, u), maxUp = std::max(maxUp, u);
    minDepth = std::min(minDepth, d), maxDepth = std::max(maxDepth, d);
  }
};

/// A point of the meridian plane y = 0 (radius, Z) in part coordinates.
inline Eigen::Vector3d meridianPoint(const RZ& p) { return {p.x(), 0.0, p.y()}; }

/// A parallel projection of `view` onto a picture: mm at the centre, the scale, the size.
/// Pixel (0, 0) is the lower-left corner, as VTK counts display coordinates.
struct PictureFrame {
  View view;
  Eigen::Vector2d centreMm{0, 0};  // (right, up) at the picture's centre
  double minDepthMm = 0, maxDepthMm = 0;
  double pxPerMm = 1;
  int widthPx = 1, heightPx = 1;

  Eigen::Vector2d pixelOf(const Eigen::Vector3d& p) const {
    return {widthPx / 2.0 + (p.dot(view.right) - centreMm.x()) * pxPerMm,
            heightPx / 2.0 + (p.dot(view.up) - centreMm.y()) * pxPerMm};
  }
  Eigen::Vector2d pixelOf(const RZ& meridian) const { return pixelOf(meridianPoint(meridian)); }
};

/// Frames `e` in a picture of widthPx × heightPx: centred, as large as fits with `marginFraction`
/// of the picture's width and height left free on each side, and `topFraction` more on top.
PictureFrame frameExtent(const View& view, const Extent& e, int widthPx, int heightPx, double marginFraction,
                         double topFraction = 0.0);

}  // namespace lathesim::render
