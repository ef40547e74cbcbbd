#include "geometry/convex_overlap.hpp"

#include <numbers>
#include <vector>

namespace lathesim {
namespace {

double cross(const RZ& a, const RZ& b) { return a.x() * b.y() - a.y() * b.x(); }

/// The part of `polygon` on the left of the directed line p → q (inside for a ccw clipper).
std::vector<RZ> clipLeftOf(const std::vector<RZ>& polygon, const RZ& p, const RZ& q) {
  std::vector<RZ> out;
  const RZ d = q - p;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const RZ& a = polygon[i];
    const RZ& b = polygon[(i + 1) % polygon.size()];
    const double sa = cross(d, a - p), sb = cross(d, b - p);
    if (sa >= 0) out.push_back(a);
    if ((sa >= 0) != (sb >= 0)) out.push_back(a + (b - a) * (sa / (sa - sb)));
  }
  return out;
}

double twiceSignedArea(const std::vector<RZ>& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) twice += cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  return twice;
}

}  // namespace

std::vector<ConvexPolygon> differenceOf(const ConvexPolygon& a, const ConvexPolygon& b) {
  if (a.vertices().size() < 3 || b.vertices().size() < 3) return {a};  // no area to cut, or none to cut by
  std::vector<ConvexPolygon> pieces;
  std::vector<RZ> remaining = a.vertices();
  const auto& clipper = b.vertices();
  for (std::size_t i = 0; i < clipper.size() && remaining.size() >= 3; ++i) {
    const RZ& p = clipper[i];
    const RZ& q = clipper[(i + 1) % clipper.size()];
    // Outside this edge (right of p → q) the rest of a is not in b; inside, later edges decide.
    const std::vector<RZ> outside = clipLeftOf(remaining, q, p);
    if (outside.size() >= 3 && twiceSignedArea(outside) > 0.0) pieces.push_back(ConvexPolygon::hullOf(outside));
    remaining = clipLeftOf(remaining, p, q);
  }
  return pieces;
}

Overlap overlapOf(const ConvexPolygon& a, const ConvexPolygon& b) {
  if (a.vertices().size() < 3 || b.vertices().size() < 3) return {};
  std::vector<RZ> clipped = a.vertices();
  const auto& clipper = b.vertices();
  for (std::size_t i = 0; i < clipper.size() && !clipped.empty(); ++i)
    clipped = clipLeftOf(clipped, clipper[i], clipper[(i + 1) % clipper.size()]);
  if (clipped.size() < 3) return {};
  double twiceArea = 0.0;
  RZ weighted(0, 0);
  for (std::size_t i = 0; i < clipped.size(); ++i) {
    const RZ& p = clipped[i];
    const RZ& q = clipped[(i + 1) % clipped.size()];
    const double c = cross(p, q);
    twiceArea += c;
    weighted += (p + q) * c;
  }
  if (twiceArea <= 0.0) return {};
  return {twiceArea / 2.0, weighted / (3.0 * twiceArea)};
}

double revolvedVolumeMm3(const Overlap& overlap) {
  return overlap.areaMm2 * 2.0 * std::numbers::pi * overlap.centroid.x();
}

}  // namespace lathesim
