#pragma once
// Sampled meridian sections worked out exactly, for tests of what reads sections.

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/meridian_profile.hpp"

namespace lathesim::test {

/// φ of the solid cylinder r ≤ 10, −5 ≤ z ≤ 5 (exact signed distance), sampled every `h` from
/// z = −8 out to r 14, clamped at ±3h as a narrow band is.
inline SampledSection cylinderSection(double h) {
  SampledSection s;
  s.stepMm = h;
  s.zFirstMm = -8;
  s.rCount = static_cast<int>(14 / h);
  s.zCount = static_cast<int>(16 / h);
  s.clampMm = 3 * h;
  for (int k = 0; k < s.zCount; ++k)
    for (int i = 0; i < s.rCount; ++i) {
      const double dr = i * h - 10, dz = std::abs(s.zFirstMm + k * h) - 5;
      const double outside = std::hypot(std::max(dr, 0.0), std::max(dz, 0.0));
      s.phi.push_back(static_cast<float>(std::clamp(outside > 0 ? outside : std::max(dr, dz), -3 * h, 3 * h)));
    }
  return s;
}

/// φ of the solid of revolution whose meridian is the polygon `made` (radius, Z), closed from
/// its last point to its first: its exact signed distance to the polygon's edges off the axis
/// (the axis is no surface), sampled every `h` over z zLow..zHigh and r 0..rHigh, clamped at
/// ±3h as a narrow band is.
inline SampledSection polygonSection(const std::vector<RZ>& made, double h, double zLow, double zHigh, double rHigh) {
  SampledSection s;
  s.stepMm = h;
  s.zFirstMm = zLow;
  s.rCount = static_cast<int>(std::ceil(rHigh / h)) + 1;
  s.zCount = static_cast<int>(std::ceil((zHigh - zLow) / h)) + 1;
  s.clampMm = 3 * h;
  for (int k = 0; k < s.zCount; ++k)
    for (int i = 0; i < s.rCount; ++i) {
      const RZ p(i * h, zLow + k * h);
      double nearest = INFINITY;
      bool inside = false;
      for (std::size_t n = 0; n < made.size(); ++n) {
        const RZ a = made[n], b = made[(n + 1) % made.size()];
        if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < a.x() + (p.y() - a.y()) / (b.y() - a.y()) * (b.x() - a.x()))
          inside = !inside;  // even-odd, along +r
        if (a.x() == 0 && b.x() == 0) continue;
        const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
        nearest = std::min(nearest, (p - (a + t * (b - a))).norm());
      }
      s.phi.push_back(static_cast<float>(std::clamp(inside ? -nearest : nearest, -3 * h, 3 * h)));
    }
  return s;
}

}  // namespace lathesim::test
