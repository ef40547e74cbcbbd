#pragma once
// A sampled meridian section worked out exactly, for tests of what reads sections.

#include <algorithm>
#include <cmath>

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

}  // namespace lathesim::test
