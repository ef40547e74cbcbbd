// Contour geometry for the compound cycles; see contour_geometry.hpp.

#include "interp/contour/contour_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace lathesim::interp {
namespace {

constexpr double kLengthTolMm = 1e-9;
constexpr double kAngleTolRad = 1e-9;

double radiusOf(const ContourSegment& arc) { return (arc.from - arc.center).norm(); }

/// Angle travelled from the arc's start to direction `angleRad`, in [0, 2π).
double travelTo(const ContourSegment& arc, double angleRad) {
  const double start = angleAround(arc.center, arc.from);
  const double turn = arc.kind == MoveKind::ArcCCW ? angleRad - start : start - angleRad;
  double travel = std::fmod(turn, kTwoPi);
  if (travel < 0) travel += kTwoPi;
  return travel;
}

}  // namespace

Contour translatedContour(const Contour& contour, const RZ& offsetMm) {
  Contour moved = contour;
  for (ContourSegment& segment : moved) {
    segment.from += offsetMm;
    segment.to += offsetMm;
    if (isArc(segment.kind)) segment.center += offsetMm;
  }
  return moved;
}

RZ swappedAxes(const RZ& point) { return RZ(point.y(), point.x()); }

MoveKind mirroredKind(MoveKind kind) {
  if (kind == MoveKind::ArcCW) return MoveKind::ArcCCW;
  if (kind == MoveKind::ArcCCW) return MoveKind::ArcCW;
  return kind;
}

double angleAround(const RZ& center, const RZ& point) {
  return std::atan2(point.x() - center.x(), point.y() - center.y());
}

double arcSweepRad(const ContourSegment& arc) {
  const double sweep = travelTo(arc, angleAround(arc.center, arc.to));
  return sweep < kAngleTolRad ? kTwoPi : sweep;
}

double arcTravelRad(const ContourSegment& arc, const RZ& point) {
  return travelTo(arc, angleAround(arc.center, point));
}

RZ arcPointAt(const ContourSegment& arc, double angleRad) {
  const double radius = radiusOf(arc);
  return arc.center + RZ(radius * std::sin(angleRad), radius * std::cos(angleRad));
}

ContourSegment reversed(const ContourSegment& segment) {
  ContourSegment back = segment;
  back.kind = mirroredKind(segment.kind);
  std::swap(back.from, back.to);
  return back;
}

bool arcPassesAngleInside(const ContourSegment& arc, double angleRad) {
  const double travel = travelTo(arc, angleRad);
  return travel > kAngleTolRad && travel < arcSweepRad(arc) - kAngleTolRad;
}

std::vector<RZ> levelCrossings(const ContourSegment& segment, double xMm) {
  if (!isArc(segment.kind)) {
    const RZ along = segment.to - segment.from;
    if (std::abs(along.x()) < kLengthTolMm) {
      if (std::abs(segment.from.x() - xMm) > kLengthTolMm) return {};
      return {segment.from, segment.to};
    }
    const double t = (xMm - segment.from.x()) / along.x();
    if (t < -kLengthTolMm || t > 1 + kLengthTolMm) return {};
    return {RZ(xMm, segment.from.y() + std::clamp(t, 0.0, 1.0) * along.y())};
  }
  const double radius = radiusOf(segment);
  const double dx = xMm - segment.center.x();
  if (std::abs(dx) > radius + kLengthTolMm) return {};
  const double halfChord = std::sqrt(std::max(0.0, radius * radius - dx * dx));
  const double sweep = arcSweepRad(segment);
  std::vector<std::pair<double, RZ>> found;  // (travel from the start, point)
  for (const double side : {1.0, -1.0}) {
    const RZ point(xMm, segment.center.y() + side * halfChord);
    double travel = travelTo(segment, angleAround(segment.center, point));
    if (travel > kTwoPi - kAngleTolRad) travel = 0;  // just before the start: the start
    if (travel > sweep + kAngleTolRad) continue;
    if (!found.empty() && (found.front().second - point).norm() < kLengthTolMm) continue;
    found.emplace_back(travel, point);
  }
  std::sort(found.begin(), found.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<RZ> points;
  for (const auto& entry : found) points.push_back(entry.second);
  return points;
}

}  // namespace lathesim::interp
