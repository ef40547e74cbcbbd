#pragma once
// Spindle speeds (rpm) under G96 and G97, and the clamps that apply to each.

#include <optional>

#include "interp/control/machine_limits.hpp"

namespace lathesim::interp {

/// The most G96 may turn: the G50 S limit when one is given, and never above max_rpm.
double surfaceSpeedClampRpm(std::optional<double> limitRpm, const MachineLimits& machine);

/// rpm under G96 at `radiusMm` from the axis: 1000·V / (2π·r) (V in m/min), clamped to the
/// G50 S limit when one is given and always to the machine's top speed. At r = 0 the
/// clamp alone decides; V = 0 is 0 rpm; a radius below the axis counts by its size.
double surfaceSpeedRpm(double surfaceMPerMin, double radiusMm, std::optional<double> limitRpm,
                       const MachineLimits& machine);

/// rpm under G97: S, capped by the machine's top speed (G50 S does not apply under G97).
double constantRpm(double sRpm, const MachineLimits& machine);

}  // namespace lathesim::interp
