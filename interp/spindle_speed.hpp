#pragma once
// The spindle speed a move turns at, from the spindle state stamped on it.

#include <optional>

#include "interp/machine_limits.hpp"
#include "interp/move.hpp"

namespace lathesim::interp {

/// rpm under G96 at `radiusMm` from the axis: 1000·V / (2π·r) (V in m/min), clamped to the
/// G50 S limit when one is given and always to the machine's top speed. At r = 0 the
/// clamp alone decides.
double surfaceSpeedRpm(double surfaceMPerMin, double radiusMm, std::optional<double> limitRpm,
                       const MachineLimits& machine);

/// rpm under G97: S, capped by the machine's top speed (G50 S does not apply under G97).
double constantRpm(double sRpm, const MachineLimits& machine);

/// The rpm at `radiusMm` for the spindle state stamped on `move`; 0 when the spindle is
/// stopped (M05, or never started).
double rpmAt(const Move& move, double radiusMm, const MachineLimits& machine);

}  // namespace lathesim::interp
