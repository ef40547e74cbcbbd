#include "interp/motion/spindle_speed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lathesim::interp {

double surfaceSpeedRpm(double surfaceMPerMin, double radiusMm, std::optional<double> limitRpm,
                       const MachineLimits& machine) {
  constexpr double kMmPerM = 1000.0;
  if (surfaceMPerMin <= 0.0) return 0.0;
  const double circumferenceMm = 2.0 * M_PI * std::abs(radiusMm);
  const double unclamped = circumferenceMm > 0.0 ? kMmPerM * surfaceMPerMin / circumferenceMm
                                                 : std::numeric_limits<double>::infinity();
  return std::min(unclamped, surfaceSpeedClampRpm(limitRpm, machine));
}

double surfaceSpeedClampRpm(std::optional<double> limitRpm, const MachineLimits& machine) {
  return std::min(limitRpm.value_or(machine.maxRpm), machine.maxRpm);
}

double constantRpm(double sRpm, const MachineLimits& machine) { return std::min(sRpm, machine.maxRpm); }

}  // namespace lathesim::interp
