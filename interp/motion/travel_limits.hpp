#pragma once
// Overtravel: the machine's axes stop at their stroke limits (MachineLimits::travel), so a move
// whose end, or whose arc, lies beyond them is an alarm at its block, as on the control; never
// a rapid far outside the machine. Checked on the programmed point's path in the setup's frame
// (after offsets and G50), on every move's ends and on each arc's extreme points.

#include <vector>

#include "interp/control/machine_limits.hpp"
#include "interp/move.hpp"
#include "interp/result.hpp"

namespace lathesim::interp {

/// The first move that leaves `travel`, as an error at its block; success when none does.
Status checkTravel(const std::vector<Move>& moves, const TravelLimits& travel);

}  // namespace lathesim::interp
