#include "interp/spindle_speed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lathesim::interp {

double surfaceSpeedRpm(double surfaceMPerMin, double radiusMm, std::optional<double> limitRpm,
                       const MachineLimits& machine) {
  constexpr double kMmPerM = 1000.0;
  const double circumferenceMm = 2.0 * M_PI * radiusMm;
  const double unclamped = circumferenceMm > 0.0 ? kMmPerM * surfaceMPerMin / circumferenceMm
                                                 : std::numeric_limits<double>::infinity();
  const double clamp = std::min(limitRpm.value_or(machine.maxRpm), machine.maxRpm);
  return std::min(unclamped, clamp);
}

double constantRpm(double sRpm, const MachineLimits& machine) { return std::min(sRpm, machine.maxRpm); }

double rpmAt(const Move& move, double radiusMm, const MachineLimits& machine) {
  if (!move.spindleOn) return 0.0;
  if (move.spindleMode == SpindleMode::Rpm) return constantRpm(move.spindleS, machine);
  if (move.spindleS <= 0.0) return 0.0;
  return surfaceSpeedRpm(move.spindleS, radiusMm, move.spindleLimitRpm, machine);
}

}  // namespace lathesim::interp
