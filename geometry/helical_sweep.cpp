#include "geometry/helical_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace lathesim {
namespace {

// atan2(y, x) to about 1e-11 rad (a z error of 1e-12·lead), in a fraction of libm's time: the
// hot loop takes one per column of voxels. atan of the ratio in [0, 1], reduced below tan 15°
// by atan a = π/6 + atan((a − 1/√3)/(1 + a/√3)), then its odd series to a¹⁵.
double fastAtan2(double y, double x) {
  const double ax = std::abs(x), ay = std::abs(y);
  const bool swapped = ay > ax;
  const double big = swapped ? ay : ax;
  if (big == 0.0) return 0.0;
  double a = (swapped ? ax : ay) / big;
  constexpr double kTan15 = 0.26794919243112270;
  constexpr double kInvSqrt3 = 0.57735026918962576;
  const bool shifted = a > kTan15;
  if (shifted) a = (a - kInvSqrt3) / (1.0 + a * kInvSqrt3);
  const double a2 = a * a;
  double t = a * (1.0 + a2 * (-1.0 / 3 + a2 * (1.0 / 5 + a2 * (-1.0 / 7 + a2 * (1.0 / 9 + a2 * (-1.0 / 11 + a2 * (1.0 / 13 - a2 / 15)))))));
  if (shifted) t += std::numbers::pi / 6;
  if (swapped) t = std::numbers::pi / 2 - t;
  if (x < 0) t = std::numbers::pi - t;
  return y < 0 ? -t : t;
}

// The angle a − b wrapped into (−π, π].
double wrapped(double a) {
  a = std::remainder(a, kTwoPi);
  return a <= -std::numbers::pi ? a + kTwoPi : a;
}

}  // namespace

HelicalSweep::HelicalSweep(const ConvexPolygon& outline, const RZ& from, const RZ& to, double revolutions,
                           double startSpindleDeg, int sense)
    : outline_({outline}),
      vertices_(outline.vertices()),
      from_(from),
      direction_(to - from),
      inverseLengthSquared_(direction_.squaredNorm() > 0 ? 1.0 / direction_.squaredNorm() : 0.0),
      revolutions_(revolutions),
      phi0_(-startSpindleDeg * std::numbers::pi / 180.0),
      omega_(-sense * kTwoPi * revolutions),
      alongReach_(0.0),
      hull_({outline.sweptAlong(from, to)}) {
  lowestRadius_ = std::min(from.x(), to.x()) + outline.lowerBound().x();
  inverseLength_ = std::sqrt(inverseLengthSquared_);
  inverseOmega_ = 1.0 / omega_;
  inverseDirectionZ_ = direction_.y() != 0.0 ? 1.0 / direction_.y() : 0.0;
  const auto& corners = outline.vertices();
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const RZ& p = corners[i];
    const RZ& q = corners[(i + 1) % corners.size()];
    const RZ& low = p.x() <= q.x() ? p : q;
    const RZ& high = p.x() <= q.x() ? q : p;
    const double dr = high.x() - low.x();
    edges_.push_back({low.x(), high.x(), low.y(), dr > 0 ? (high.y() - low.y()) / dr : 0.0, high.y()});
  }
  const double length = direction_.norm();
  for (const RZ& v : outline.vertices())
    alongReach_ = std::max(alongReach_, length > 0 ? std::abs(v.dot(direction_)) / length : v.norm());
}

double HelicalSweep::lipschitzAt(double rhoMinMm) const {
  if (!(rhoMinMm > 0.0)) return std::numeric_limits<double>::infinity();
  const double carried = direction_.norm() / (kTwoPi * revolutions_) / rhoMinMm;
  return std::sqrt(1.0 + carried * carried);
}

// The least and greatest axial coordinate of the outline's points whose radial coordinate lies
// in [a, b] (relative to the programmed point), or an empty range (low > high).
std::pair<double, double> HelicalSweep::axialExtentIn(double a, double b) const {
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const Edge& e : edges_) {
    if (e.rHigh < a || e.rLow > b) continue;
    // The edge clipped to the band: z at its ends, or where it crosses the band's edges.
    const double r0 = std::max(e.rLow, a), r1 = std::min(e.rHigh, b);
    const double z0 = e.zAtLow + (r0 - e.rLow) * e.dzPerDr, z1 = e.zAtLow + (r1 - e.rLow) * e.dzPerDr;
    low = std::min({low, z0, z1, e.rLow == e.rHigh ? e.zOther : z0});
    high = std::max({high, z0, z1, e.rLow == e.rHigh ? e.zOther : z1});
  }
  return {low, high};
}

void HelicalSweep::candidatesInto(double rho, double phi, double z0, double dz, int count, double cap,
                                  double* out) const {
  const double zLast = z0 + (count - 1) * dz;
  double uLo, uHi;
  if (direction_.x() == 0.0) {
    // Along Z at one radius (a straight thread): a placed outline can come within cap only if
    // some point of it with r within cap of ρ lies within cap of a point's z.
    const auto [low, high] = axialExtentIn(rho - from_.x() - cap, rho - from_.x() + cap);
    if (low > high) {
      uLo = 1.0;
      uHi = 0.0;
    } else {
      const double uA = (z0 - high - cap - from_.y()) * inverseDirectionZ_;
      const double uB = (zLast - low + cap - from_.y()) * inverseDirectionZ_;
      uLo = std::max(0.0, std::min(uA, uB));
      uHi = std::min(1.0, std::max(uA, uB));
    }
  } else {
    // In general: the projections on the line of travel, |u − u*|·|d| ≤ alongReach + cap.
    const double uA = ((rho - from_.x()) * direction_.x() + (z0 - from_.y()) * direction_.y()) * inverseLengthSquared_;
    const double uB = uA + (count - 1) * dz * direction_.y() * inverseLengthSquared_;
    const double slack = (alongReach_ + cap) * inverseLength_;
    uLo = std::max(0.0, std::min(uA, uB) - slack);
    uHi = std::min(1.0, std::max(uA, uB) + slack);
  }
  double column[kColumn];
  std::fill(column, column + kColumn, std::numeric_limits<double>::infinity());
  if (uLo <= uHi) {
    // The solutions of φ(u) ≡ φ are u = base + m·step for every integer m.
    const double step = 1.0 / revolutions_;
    const double base = (phi - phi0_) * inverseOmega_;
    for (double u = base + std::ceil((uLo - base) * revolutions_) * step; u <= uHi; u += step) {
      const RZ at = from_ + u * direction_;
      outline_.planarDistanceColumnMin(rho - at.x(), z0 - at.y(), dz, cap, column);
    }
    for (int k = 0; k < count; ++k) out[k] = std::min(out[k], column[k]);
  }
  // The two ends: the outline in the half-plane of its azimuth, at 3D distance. In that
  // half-plane the point stands at (ρ cos Δ, z), within ρ·(1 − cos Δ) ≤ 2ρ of (ρ, z) along r,
  // so an end farther than the outline's reach plus that along the travel cannot be within cap.
  // An end is also part of the boundary seen from inside: the groove stops in that face, so a
  // point inside lies no deeper than its distance to it. Without this, a voxel just short of
  // the face would read as deep in the groove as the flanks allow, the face would sit up to
  // half a voxel past where it is, and a cube straddling it could be taken as covered.
  const double uA = ((rho - from_.x()) * direction_.x() + (z0 - from_.y()) * direction_.y()) * inverseLengthSquared_;
  const double uB = uA + (count - 1) * dz * direction_.y() * inverseLengthSquared_;
  const double endSlack = (alongReach_ + cap) * inverseLength_ + 2.0 * rho * std::abs(direction_.x()) * inverseLengthSquared_;
  for (const double u : {0.0, 1.0}) {
    if (u < std::min(uA, uB) - endSlack || u > std::max(uA, uB) + endSlack) continue;
    const double delta = wrapped(phi - azimuthAt(u));
    const double across = rho * std::abs(std::sin(delta));
    if (across >= cap) continue;
    const RZ at = from_ + u * direction_;
    std::fill(column, column + kColumn, std::numeric_limits<double>::infinity());
    outline_.planarDistanceColumnMin(rho * std::cos(delta) - at.x(), z0 - at.y(), dz, cap, column);
    for (int k = 0; k < count; ++k) {
      const double inPlane = std::max(column[k], 0.0);
      const double toEnd = std::sqrt(inPlane * inPlane + across * across);
      out[k] = out[k] < 0.0 ? std::max(out[k], -toEnd) : std::min(out[k], toEnd);
    }
  }
}

double HelicalSweep::signedDistance(double x, double y, double z, double cap) const {
  double d = std::numeric_limits<double>::infinity();
  candidatesInto(std::hypot(x, y), fastAtan2(y, x), z, 0.0, 1, cap, &d);
  return d;
}

void HelicalSweep::signedDistanceColumn(double x, double y, double z0, double dz, double cap,
                                        double (&out)[kColumn]) const {
  std::fill(out, out + kColumn, std::numeric_limits<double>::infinity());
  // Nearer the axis than the outline can come along the whole pass, by more than cap: every
  // placement (and either end, whose in-plane radius ρ·cos Δ is smaller still) is farther.
  const double rho = std::sqrt(x * x + y * y);
  if (rho < lowestRadius_ - cap) return;
  candidatesInto(rho, fastAtan2(y, x), z0, dz, kColumn, cap, out);
}

}  // namespace lathesim
