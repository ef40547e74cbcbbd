#pragma once
// Feeds that make sense only in the other feed mode, or in no mode: F200 under G99 is 200 mm
// per revolution (a metre every five turns), F0.2 under G98 is 0.2 mm per minute, F0.005 under
// G99 a chip thinner than any edge cuts (a decimal point or an inch feed gone wrong). All are
// legal, and almost always a mistake. The executor checks each cutting move whose feed or feed
// mode differs from the cutting move's before it, and warns once there, quoting F as written.

#include <optional>
#include <string>

#include "interp/base/move.hpp"

namespace lathesim::interp {

/// Above this a feed per revolution (G99) is implausible (mm/rev).
inline constexpr double kMaxPlausibleFeedMmPerRev = 5.0;
/// Below this a feed per revolution (G99) is implausible (mm/rev).
inline constexpr double kMinPlausibleFeedMmPerRev = 0.01;
/// Below this a feed per minute (G98) is implausible (mm/min).
inline constexpr double kMinPlausibleFeedMmPerMin = 1.0;

/// What is implausible about F `written` (as the program wrote it, in the unit in force: mm, or
/// inch when `inch`), which is `feedMm` mm per minute or revolution under `mode`; nullopt if
/// nothing.
std::optional<std::string> implausibleFeed(const std::string& written, double feedMm, FeedMode mode, bool inch);

}  // namespace lathesim::interp
