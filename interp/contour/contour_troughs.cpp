#include "interp/contour/contour_troughs.hpp"

#include <algorithm>
#include <numbers>

#include "interp/base/tolerance.hpp"
#include "interp/contour/contour_geometry.hpp"

namespace lathesim::interp {
namespace {

/// The points of a block where its depth may turn, in order along it: its ends, and for an arc
/// its highest and lowest X when they lie inside it.
std::vector<RZ> turningPoints(const ContourSegment& segment) {
  std::vector<RZ> points = {segment.from};
  if (isArc(segment.kind)) {
    std::vector<RZ> extremes;
    for (const double angle : {std::numbers::pi / 2, -std::numbers::pi / 2}) {
      if (arcPassesAngleInside(segment, angle)) extremes.push_back(arcPointAt(segment, angle));
    }
    std::sort(extremes.begin(), extremes.end(), [&](const RZ& a, const RZ& b) {
      return arcTravelRad(segment, a) < arcTravelRad(segment, b);
    });
    points.insert(points.end(), extremes.begin(), extremes.end());
  }
  points.push_back(segment.to);
  return points;
}

}  // namespace

std::vector<std::size_t> troughBottoms(const Contour& contour, double stepDir) {
  std::vector<std::size_t> bottoms;
  bool goingDeeper = false;  // the last move that changed the depth went deeper
  std::size_t deeperBlock = 0;  // the block of that move
  for (std::size_t i = 1; i < contour.size(); ++i) {
    const std::vector<RZ> points = turningPoints(contour[i]);
    for (std::size_t j = 0; j + 1 < points.size(); ++j) {
      const double deeperMm = stepDir * (points[j + 1].x() - points[j].x());
      if (deeperMm > kTolMm) {
        goingDeeper = true;
        deeperBlock = i;
        continue;
      }
      if (deeperMm < -kTolMm) {
        if (goingDeeper) bottoms.push_back(deeperBlock);  // back toward the start's side
        goingDeeper = false;
      }
    }
  }
  return bottoms;
}

}  // namespace lathesim::interp
