#include "geometry/straight_slot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace lathesim {
namespace {

ConvexPolygon widenedAlongR(const ConvexPolygon& polygon, double half) {
  std::vector<RZ> points;
  for (const RZ& v : polygon.vertices()) {
    points.push_back(v + RZ(half, 0));
    points.push_back(v - RZ(half, 0));
  }
  return ConvexPolygon::hullOf(points);
}

double combined(double inPlane, double across) {
  if (inPlane > 0.0 && across > 0.0) return std::sqrt(inPlane * inPlane + across * across);
  return std::max(inPlane, across);
}

}  // namespace

StraightSlot::StraightSlot(const ConvexPolygon& outline, const RZ& from, const RZ& to, double thicknessMm,
                           double spindleDeg)
    : section_({outline.sweptAlong(from, to)}),
      halfThickness_(thicknessMm / 2.0),
      cosine_(std::cos(-spindleDeg * std::numbers::pi / 180.0)),
      sine_(std::sin(-spindleDeg * std::numbers::pi / 180.0)),
      hull_({widenedAlongR(outline.sweptAlong(from, to), thicknessMm / 2.0)}) {}

double StraightSlot::signedDistance(double x, double y, double z, double cap) const {
  const double inPlaneR = x * cosine_ + y * sine_;
  const double across = std::abs(-x * sine_ + y * cosine_) - halfThickness_;
  return combined(section_.planarDistance(inPlaneR, z, cap), across);
}

void StraightSlot::signedDistanceColumn(double x, double y, double z0, double dz, double cap,
                                        double (&out)[kColumn]) const {
  const double inPlaneR = x * cosine_ + y * sine_;
  const double across = std::abs(-x * sine_ + y * cosine_) - halfThickness_;
  std::fill(out, out + kColumn, std::numeric_limits<double>::infinity());
  if (across >= cap) return;  // every point is farther than cap
  section_.planarDistanceColumnMin(inPlaneR, z0, dz, cap, out);
  for (double& d : out) d = combined(d, across);
}

}  // namespace lathesim
