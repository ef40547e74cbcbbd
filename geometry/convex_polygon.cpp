#include "geometry/convex_polygon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lathesim {
namespace {

double cross(const RZ& o, const RZ& a, const RZ& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

double distanceToSegment(const RZ& p, const RZ& a, const RZ& b) {
  const RZ ab = b - a;
  const double lengthSquared = ab.squaredNorm();
  const double t = lengthSquared > 0.0 ? std::clamp((p - a).dot(ab) / lengthSquared, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

bool segmentsCross(const RZ& a, const RZ& b, const RZ& c, const RZ& d) {
  const double d1 = cross(c, d, a), d2 = cross(c, d, b);
  const double d3 = cross(a, b, c), d4 = cross(a, b, d);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}

}  // namespace

ConvexPolygon ConvexPolygon::hullOf(std::span<const RZ> points) {
  // Andrew's monotone chain; drops collinear points so edges are never degenerate.
  std::vector<RZ> p(points.begin(), points.end());
  std::sort(p.begin(), p.end(), [](const RZ& a, const RZ& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return ConvexPolygon(std::move(p));
  std::vector<RZ> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  hull.resize(k - 1);
  return ConvexPolygon(std::move(hull));
}

ConvexPolygon::Checked ConvexPolygon::fromOutline(std::span<const RZ> outline) {
  const std::size_t n = outline.size();
  if (n < 3) return {std::nullopt, "needs at least 3 vertices, got " + std::to_string(n)};
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (outline[i] == outline[j]) return {std::nullopt, "repeats vertex " + std::to_string(j + 1)};
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours through the closing edge
      if (segmentsCross(outline[i], outline[(i + 1) % n], outline[j], outline[(j + 1) % n]))
        return {std::nullopt, "is self-intersecting (edges " + std::to_string(i + 1) + " and " +
                                  std::to_string(j + 1) + " cross)"};
    }
  int turn = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double c = cross(outline[i], outline[(i + 1) % n], outline[(i + 2) % n]);
    const int sign = (c > 0) - (c < 0);
    if (sign == 0) continue;
    if (turn != 0 && sign != turn)
      return {std::nullopt, "is not convex (it turns the other way at vertex " + std::to_string((i + 1) % n + 1) + ")"};
    turn = sign;
  }
  if (turn == 0) return {std::nullopt, "has no area (all vertices on one line)"};
  return {hullOf(outline), {}};
}

double ConvexPolygon::signedDistance(const RZ& p) const {
  const std::size_t n = vertices_.size();
  if (n == 1) return (p - vertices_[0]).norm();
  if (n == 2) return distanceToSegment(p, vertices_[0], vertices_[1]);
  // Inside a convex polygon the distance to the boundary is the smallest distance to an
  // edge's supporting line; outside it is the distance to the nearest edge segment.
  double maxLineDistance = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const RZ& a = vertices_[i];
    const RZ& b = vertices_[(i + 1) % n];
    const RZ edge = b - a;
    const double outward = (edge.y() * (p.x() - a.x()) - edge.x() * (p.y() - a.y())) / edge.norm();
    maxLineDistance = std::max(maxLineDistance, outward);
  }
  if (maxLineDistance <= 0.0) return maxLineDistance;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) best = std::min(best, distanceToSegment(p, vertices_[i], vertices_[(i + 1) % n]));
  return best;
}

ConvexPolygon ConvexPolygon::sweptAlong(const RZ& a, const RZ& b) const {
  std::vector<RZ> points;
  points.reserve(2 * vertices_.size());
  for (const RZ& v : vertices_) {
    points.push_back(v + a);
    points.push_back(v + b);
  }
  return hullOf(points);
}

ConvexPolygon ConvexPolygon::translated(const RZ& offset) const {
  std::vector<RZ> moved = vertices_;
  for (RZ& v : moved) v += offset;
  return ConvexPolygon(std::move(moved));
}

double ConvexPolygon::area() const {
  double twice = 0.0;
  for (std::size_t i = 0; i < vertices_.size(); ++i) {
    const RZ& a = vertices_[i];
    const RZ& b = vertices_[(i + 1) % vertices_.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice;
}

RZ ConvexPolygon::lowerBound() const {
  RZ m = vertices_.front();
  for (const RZ& v : vertices_) m = m.cwiseMin(v);
  return m;
}

RZ ConvexPolygon::upperBound() const {
  RZ m = vertices_.front();
  for (const RZ& v : vertices_) m = m.cwiseMax(v);
  return m;
}

}  // namespace lathesim
