#include "geometry/helical_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace lathesim {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The angle a − b wrapped into (−π, π].
double wrapped(double a) {
  a = std::remainder(a, kTwoPi);
  return a <= -std::numbers::pi ? a + kTwoPi : a;
}

}  // namespace

HelicalSweep::HelicalSweep(const ConvexPolygon& outline, const RZ& from, const RZ& to, double revolutions,
                           double startSpindleDeg, int sense)
    : outline_({outline}),
      from_(from),
      direction_(to - from),
      inverseLengthSquared_(direction_.squaredNorm() > 0 ? 1.0 / direction_.squaredNorm() : 0.0),
      revolutions_(revolutions),
      phi0_(-startSpindleDeg * std::numbers::pi / 180.0),
      omega_(-sense * kTwoPi * revolutions),
      alongReach_(0.0),
      hull_({outline.sweptAlong(from, to)}) {
  const double length = direction_.norm();
  for (const RZ& v : outline.vertices())
    alongReach_ = std::max(alongReach_, length > 0 ? std::abs(v.dot(direction_)) / length : v.norm());
}

double HelicalSweep::lipschitzAt(double rhoMinMm) const {
  if (!(rhoMinMm > 0.0)) return std::numeric_limits<double>::infinity();
  const double carried = direction_.norm() / (kTwoPi * revolutions_) / rhoMinMm;
  return std::sqrt(1.0 + carried * carried);
}

void HelicalSweep::candidatesInto(double rho, double phi, double z0, double dz, int count, double cap,
                                  double* out) const {
  // The pass parameters u* of the points' projections on the line of travel bound which
  // u_k can come within cap: |u − u*|·|d| ≤ alongReach + cap.
  const double uA = ((rho - from_.x()) * direction_.x() + (z0 - from_.y()) * direction_.y()) * inverseLengthSquared_;
  const double uB = uA + (count - 1) * dz * direction_.y() * inverseLengthSquared_;
  const double slack = (alongReach_ + cap) * std::sqrt(inverseLengthSquared_);
  const double uLo = std::max(0.0, std::min(uA, uB) - slack);
  const double uHi = std::min(1.0, std::max(uA, uB) + slack);
  double column[kColumn];
  if (uLo <= uHi) {
    // The solutions of φ(u) ≡ φ are u = base + m·step for every integer m.
    const double step = 1.0 / revolutions_;
    const double base = (phi - phi0_) / omega_;
    for (double u = base + std::ceil((uLo - base) / step) * step; u <= uHi; u += step) {
      const RZ at = from_ + u * direction_;
      std::fill(column, column + kColumn, std::numeric_limits<double>::infinity());
      outline_.planarDistanceColumnMin(rho - at.x(), z0 - at.y(), dz, cap, column);
      for (int k = 0; k < count; ++k) out[k] = std::min(out[k], column[k]);
    }
  }
  // The two ends: the outline in the half-plane of its azimuth, at 3D distance. In that
  // half-plane the point stands at (ρ cos Δ, z), within ρ·(1 − cos Δ) ≤ 2ρ of (ρ, z) along r,
  // so an end farther than the candidates' reach plus that along the travel cannot be within cap.
  const double endSlack = slack + 2.0 * rho * std::abs(direction_.x()) * inverseLengthSquared_;
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
      out[k] = std::min(out[k], std::sqrt(inPlane * inPlane + across * across));
    }
  }
}

double HelicalSweep::signedDistance(double x, double y, double z, double cap) const {
  double d = std::numeric_limits<double>::infinity();
  candidatesInto(std::hypot(x, y), std::atan2(y, x), z, 0.0, 1, cap, &d);
  return d;
}

void HelicalSweep::signedDistanceColumn(double x, double y, double z0, double dz, double cap,
                                        double (&out)[kColumn]) const {
  std::fill(out, out + kColumn, std::numeric_limits<double>::infinity());
  candidatesInto(std::hypot(x, y), std::atan2(y, x), z0, dz, kColumn, cap, out);
}

}  // namespace lathesim
