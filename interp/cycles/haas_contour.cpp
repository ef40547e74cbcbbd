#include "interp/cycles/haas_contour.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "interp/base/tolerance.hpp"
#include "interp/contour/contour_geometry.hpp"

namespace lathesim::interp {
namespace {

// A G71 level steps in X (a radius, written as a diameter), a G72 level in Z.
double stepOf(const RZ& point, bool turning) { return turning ? point.x() : point.y(); }
double writtenStep(const RZ& point, bool turning) { return turning ? 2.0 * point.x() : point.y(); }

/// The points of a block where its step-axis coordinate may be extreme: its end, and for an
/// arc the points of its circle in the step axis's two directions when they lie inside it.
std::vector<RZ> extremePoints(const ContourSegment& segment, bool turning) {
  std::vector<RZ> points = {segment.to};
  if (!isArc(segment.kind)) return points;
  const double first = turning ? std::numbers::pi / 2 : 0.0;
  for (const double angle : {first, first - std::numbers::pi}) {
    if (arcPassesAngleInside(segment, angle)) points.push_back(arcPointAt(segment, angle));
  }
  return points;
}

}  // namespace

std::optional<Error> haasContourProblem(const RZ& start, const Contour& contour, bool turning) {
  if (contour.empty()) return std::nullopt;
  const double towardB = stepOf(contour.front().to, turning) - stepOf(start, turning);
  if (std::abs(towardB) <= kTolMm) return std::nullopt;  // the engine says what is wrong with it
  const double stepDir = towardB > 0 ? 1.0 : -1.0;
  const ContourSegment& last = contour.back();  // the Q block (its chamfer or corner too)
  for (const ContourSegment& segment : contour) {
    if (segment.line == last.line && segment.column == last.column) break;
    for (const RZ& point : extremePoints(segment, turning)) {
      if ((stepOf(point, turning) - stepOf(start, turning)) * stepDir >= -kTolMm) continue;
      const char axis = turning ? 'X' : 'Z';
      return Error{segment.line, segment.column,
                   fmt::format("{0} contour goes past the start point before its last block ({1}{2:g} beyond the "
                               "start's {1}{3:g}): a Haas lets only the Q block leave the start point's side (its "
                               "operator's manual, \"Type 2 details\"); start the cycle further out or end the "
                               "contour with this move",
                               turning ? "G71" : "G72", axis, writtenStep(point, turning),
                               writtenStep(start, turning))};
    }
  }
  return std::nullopt;
}

}  // namespace lathesim::interp
