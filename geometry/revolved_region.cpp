#include "geometry/revolved_region.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lathesim {

RevolvedRegion::RevolvedRegion(const std::vector<ConvexPolygon>& polygons) {
  for (const ConvexPolygon& polygon : polygons) {
    const auto& v = polygon.vertices();
    Piece piece;
    piece.crossesAxis = polygon.lowerBound().x() < 0.0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const RZ& a = v[i];
      const RZ& b = v[(i + 1) % v.size()];
      const RZ d = b - a;
      const double length = d.norm();
      if (length == 0.0) continue;
      // Counter-clockwise vertices: the outward normal is the edge turned clockwise.
      piece.edges.push_back({a.x(), a.y(), d.x(), d.y(), d.y() / length, -d.x() / length, 1.0 / (length * length)});
    }
    if (v.size() == 1) piece.edges.push_back({v[0].x(), v[0].y(), 0, 0, 0, 0, 0});
    if (pieces_.empty()) {
      lower_ = polygon.lowerBound();
      upper_ = polygon.upperBound();
    } else {
      lower_ = lower_.cwiseMin(polygon.lowerBound());
      upper_ = upper_.cwiseMax(polygon.upperBound());
    }
    pieces_.push_back(std::move(piece));
  }
}

double RevolvedRegion::pieceDistance(const Piece& piece, double r, double z, double cap) {
  const bool isArea = piece.edges.size() >= 3;
  if (isArea) {
    double maxLine = -std::numeric_limits<double>::infinity();
    for (const Edge& e : piece.edges) maxLine = std::max(maxLine, e.nx * (r - e.ax) + e.nz * (z - e.az));
    // Inside: exact. Outside but farther than cap from a supporting line: farther than cap
    // from the polygon too, so the exact search can be skipped.
    if (maxLine <= 0.0 || maxLine >= cap) return maxLine;
  }
  double best = std::numeric_limits<double>::infinity();
  for (const Edge& e : piece.edges) {
    const double px = r - e.ax, pz = z - e.az;
    const double t = std::clamp((px * e.dx + pz * e.dz) * e.inverseLengthSquared, 0.0, 1.0);
    const double qx = px - t * e.dx, qz = pz - t * e.dz;
    best = std::min(best, qx * qx + qz * qz);
  }
  return std::sqrt(best);
}

double RevolvedRegion::signedDistance(double rho, double z, double cap) const {
  double d = std::numeric_limits<double>::infinity();
  for (const Piece& piece : pieces_) {
    d = std::min(d, pieceDistance(piece, rho, z, cap));
    if (piece.crossesAxis) d = std::min(d, pieceDistance(piece, -rho, z, cap));
  }
  return d;
}

double RevolvedRegion::maxRadius() const { return std::max(std::abs(lower_.x()), std::abs(upper_.x())); }

}  // namespace lathesim
