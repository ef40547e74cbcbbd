#pragma once
// Feeds that make sense only in the other feed mode: F200 under G99 is 200 mm per
// revolution (a metre every five turns), F0.2 under G98 is 0.2 mm per minute. Both are
// legal, and both are almost always a missing G98/G99.

#include <vector>

#include "interp/move.hpp"
#include "interp/result.hpp"

namespace lathesim::interp {

/// Above this a feed per revolution (G99) is implausible (mm/rev).
inline constexpr double kMaxPlausibleFeedMmPerRev = 5.0;
/// Below this a feed per minute (G98) is implausible (mm/min).
inline constexpr double kMinPlausibleFeedMmPerMin = 1.0;

/// One warning where each implausible feed first cuts: at the first cutting move whose
/// feed or feed mode differs from the cutting move before it.
std::vector<Error> implausibleFeedWarnings(const Toolpath& toolpath);

}  // namespace lathesim::interp
