#include "geometry/revolved_region.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lathesim {

namespace {

bool isSymmetricAboutAxis(const ConvexPolygon& polygon) {
  std::vector<RZ> mirrored = polygon.vertices();
  for (RZ& v : mirrored) v.x() = -v.x();
  const ConvexPolygon image = ConvexPolygon::hullOf(mirrored);
  if (image.vertices().size() != polygon.vertices().size()) return false;
  for (const RZ& v : image.vertices()) {
    bool found = false;
    for (const RZ& w : polygon.vertices()) found |= (v - w).norm() <= 1e-12 * (1.0 + w.norm());
    if (!found) return false;
  }
  return true;
}

}  // namespace

RevolvedRegion::RevolvedRegion(const std::vector<ConvexPolygon>& polygons) {
  for (const ConvexPolygon& polygon : polygons) {
    const auto& v = polygon.vertices();
    Piece piece;
    piece.isArea = v.size() >= 3;
    // Across the axis the mirror image counts too, unless it is the polygon itself (a
    // bar's section): then measuring it again would only repeat the same numbers.
    piece.crossesAxis = polygon.lowerBound().x() < 0.0 && !isSymmetricAboutAxis(polygon);
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
  const bool isArea = piece.isArea;
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

// The hottest loop of a simulation: cloned for AVX2 where the processor has it (chosen at
// load time), plain SSE2 elsewhere. Written with plain ternaries over fixed-size arrays so
// that each k-loop becomes a few vector instructions.
__attribute__((target_clones("avx2", "default"))) void RevolvedRegion::pieceDistanceColumn(
    const Piece& piece, double r, double z0, double dz, double cap, double (&out)[kColumn]) {
  double line[kColumn];
  double zOffset[kColumn];
  for (int k = 0; k < kColumn; ++k) zOffset[k] = z0 + dz * k;
  const bool isArea = piece.isArea;
  for (int k = 0; k < kColumn; ++k) line[k] = isArea ? -std::numeric_limits<double>::infinity() : 0.0;
  if (isArea)
    for (const Edge& e : piece.edges) {
      const double radial = e.nx * (r - e.ax) - e.nz * e.az;
      for (int k = 0; k < kColumn; ++k) {
        const double d = radial + e.nz * zOffset[k];
        line[k] = d > line[k] ? d : line[k];
      }
    }
  bool needsEdges = !isArea;
  for (int k = 0; k < kColumn; ++k) needsEdges |= line[k] > 0.0 && line[k] < cap;
  if (needsEdges) {
    double best[kColumn];
    for (int k = 0; k < kColumn; ++k) best[k] = std::numeric_limits<double>::infinity();
    for (const Edge& e : piece.edges) {
      const double px = r - e.ax;
      const double radialDot = px * e.dx;
      for (int k = 0; k < kColumn; ++k) {
        const double pz = zOffset[k] - e.az;
        double t = (radialDot + pz * e.dz) * e.inverseLengthSquared;
        t = t < 0.0 ? 0.0 : t;
        t = t > 1.0 ? 1.0 : t;
        const double qx = px - t * e.dx, qz = pz - t * e.dz;
        const double d2 = qx * qx + qz * qz;
        best[k] = d2 < best[k] ? d2 : best[k];
      }
    }
    for (int k = 0; k < kColumn; ++k) {
      const bool outsideNear = !isArea || (line[k] > 0.0 && line[k] < cap);
      line[k] = outsideNear ? std::sqrt(best[k]) : line[k];
    }
  }
  for (int k = 0; k < kColumn; ++k) out[k] = line[k] < out[k] ? line[k] : out[k];
}

void RevolvedRegion::signedDistanceColumn(double rho, double z0, double dz, double cap, double (&out)[kColumn]) const {
  for (double& v : out) v = std::numeric_limits<double>::infinity();
  for (const Piece& piece : pieces_) {
    pieceDistanceColumn(piece, rho, z0, dz, cap, out);
    if (piece.crossesAxis) pieceDistanceColumn(piece, -rho, z0, dz, cap, out);
  }
}

RevolvedRegion RevolvedRegion::near(double rho, double z, double radius) const {
  RevolvedRegion subset;
  subset.lower_ = lower_;
  subset.upper_ = upper_;
  for (const Piece& piece : pieces_) {
    double d = pieceDistance(piece, rho, z, radius + 1.0);
    if (piece.crossesAxis) d = std::min(d, pieceDistance(piece, -rho, z, radius + 1.0));
    if (d > radius) continue;
    if (!piece.isArea || piece.crossesAxis) {
      subset.pieces_.push_back(piece);
      continue;
    }
    // Inside a convex polygon the distance is set by the edge line farthest out; outside,
    // the nearest point lies on that edge too (or on a vertex it shares). An edge whose line
    // is more than 2·radius behind the farthest one at the centre cannot become the
    // farthest anywhere within radius (each line distance changes by at most radius).
    double farthest = -std::numeric_limits<double>::infinity();
    for (const Edge& e : piece.edges) farthest = std::max(farthest, e.nx * (rho - e.ax) + e.nz * (z - e.az));
    Piece kept{{}, true, false};
    for (const Edge& e : piece.edges)
      if (e.nx * (rho - e.ax) + e.nz * (z - e.az) >= farthest - 2.0 * radius) kept.edges.push_back(e);
    subset.pieces_.push_back(std::move(kept));
  }
  return subset;
}

double RevolvedRegion::maxRadius() const { return std::max(std::abs(lower_.x()), std::abs(upper_.x())); }

}  // namespace lathesim
