#pragma once
// Overtravel: the machine's axes stop at their stroke limits (MachineLimits::travel), so a move
// whose end, or whose arc, lies beyond a travel the setup states is an alarm at its block, as
// on the control; never a rapid far outside the machine. A travel nobody stated (derived from
// the setup's reference, start and bar) is only an assumption: leaving it is a located warning,
// given once per axis, and never refuses a program. Checked on the programmed point's path in
// the setup's frame (after offsets and G50), on every move's ends and on each arc's extreme
// points.

#include <vector>

#include "interp/control/machine_limits.hpp"
#include "interp/base/move.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp {

/// Which derived axes have had their warning: each is warned of once per program.
struct DerivedTravelWarned {
  bool x = false;
  bool z = false;
};

/// The first move that leaves a stated travel, as an error at its block; success when none
/// does. A move leaving a derived travel adds a warning at its block to `warnings` (once per
/// axis, as `warned` records).
Status checkTravel(const std::vector<Move>& moves, const TravelLimits& travel, DerivedTravelWarned& warned,
                   std::vector<Error>& warnings);

}  // namespace lathesim::interp
