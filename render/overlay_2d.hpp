#pragma once
// Inside render only: lines, dashes and filled shapes drawn over a picture in pixels (the
// toolpath, dimension lines, arrows), built up and then handed to VTK as one 2D actor.

#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <vtkSmartPointer.h>

class vtkActor2D;

namespace lathesim::render {

using Rgb = std::array<double, 3>;  // 0–1
using Pixel = Eigen::Vector2d;      // from the lower-left corner
using PixelSegment = std::array<Pixel, 2>;

class Overlay2D {
 public:
  void line(const Pixel& a, const Pixel& b, const Rgb& colour);
  /// Dashes of `dashPx` with gaps of half that, continuing the pattern from `phasePx` along
  /// the line; returns the phase at the line's end.
  double dashed(const Pixel& a, const Pixel& b, const Rgb& colour, double dashPx, double phasePx = 0.0);
  void polygon(const std::vector<Pixel>& corners, const Rgb& colour);  // convex, filled
  /// A filled arrowhead with its tip at `tip`, pointing along `direction`.
  void arrowhead(const Pixel& tip, const Eigen::Vector2d& direction, double lengthPx, const Rgb& colour);

  bool empty() const { return points_.empty(); }
  /// One actor holding everything drawn, its lines `lineWidthPx` wide.
  vtkSmartPointer<vtkActor2D> actor(double lineWidthPx) const;

 private:
  std::vector<Pixel> points_;
  std::vector<std::array<int, 2>> lines_;
  std::vector<Rgb> lineColours_;
  std::vector<std::vector<int>> polygons_;
  std::vector<Rgb> polygonColours_;
};

/// Clips the segment a–b to the rectangle [x0, x1] × [y0, y1] (Liang–Barsky): the part of it
/// inside, as parameters 0 ≤ t0 ≤ t1 ≤ 1 along it; nullopt when none is.
struct ClipSpan {
  double t0 = 0, t1 = 1;
};
std::optional<ClipSpan> clipToRectangle(const Pixel& a, const Pixel& b, double x0, double y0, double x1, double y1);

}  // namespace lathesim::render
