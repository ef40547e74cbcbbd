#include "interp/motion/feed_warnings.hpp"

#include <fmt/format.h>

namespace lathesim::interp {

std::vector<Error> implausibleFeedWarnings(const Toolpath& toolpath) {
  std::vector<Error> warnings;
  const Move* previous = nullptr;
  for (const Move& move : toolpath.moves) {
    if (!isCutting(move.kind) || move.kind == MoveKind::Thread) continue;  // a thread's F is its lead
    const bool same = previous && previous->feed == move.feed && previous->feedMode == move.feedMode;
    previous = &move;
    if (same) continue;
    if (move.feedMode == FeedMode::PerRevolution && move.feed > kMaxPlausibleFeedMmPerRev) {
      warnings.push_back({move.line, move.column,
                          fmt::format("F{0:g} under G99 is {0:g} mm per revolution; did you mean G98 "
                                      "(mm per minute)?",
                                      move.feed)});
    } else if (move.feedMode == FeedMode::PerMinute && move.feed < kMinPlausibleFeedMmPerMin) {
      warnings.push_back({move.line, move.column,
                          fmt::format("F{0:g} under G98 is {0:g} mm per minute; did you mean G99 "
                                      "(mm per revolution)?",
                                      move.feed)});
    }
  }
  return warnings;
}

}  // namespace lathesim::interp
