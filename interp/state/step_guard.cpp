#include "interp/state/step_guard.hpp"

#include <algorithm>

namespace lathesim::interp {

bool StepGuard::step(std::size_t index) {
  Frame& loops = frames_.back();
  // A loop is left once execution stands outside the blocks it spans.
  std::erase_if(loops, [index](const RunningLoop& loop) { return index < loop.first || index > loop.last; });
  if (!noteRun(index)) return false;
  return ++steps_ > maxSteps_;
}

bool StepGuard::noteRun(std::size_t index) {
  auto after = ran_.upper_bound(index);  // the first run starting after `index`
  if (after != ran_.begin()) {
    const auto run = std::prev(after);
    if (index < run->second) return true;
    if (index == run->second) {  // it extends the run before it, and may join the next
      run->second = index + 1;
      if (after != ran_.end() && after->first == run->second) {
        run->second = after->second;
        ran_.erase(after);
      }
      return false;
    }
  }
  if (after != ran_.end() && after->first == index + 1) {  // it extends the next run back
    const std::size_t last = after->second;
    ran_.erase(after);
    ran_.emplace(index, last);
    return false;
  }
  ran_.emplace(index, index + 1);
  return false;
}

void StepGuard::jumpedBack(std::size_t from, std::size_t to, LoopSite site) {
  Frame& loops = frames_.back();
  const auto running = std::find_if(loops.begin(), loops.end(), [&](const RunningLoop& loop) {
    return loop.site.block == site.block && loop.first == to && loop.last == from;
  });
  if (running == loops.end()) loops.push_back({to, from, site});
}

std::optional<LoopSite> StepGuard::stuckLoop() const {
  for (const Frame& loops : frames_) {
    if (loops.empty()) continue;
    const auto widest = std::max_element(loops.begin(), loops.end(), [](const RunningLoop& a, const RunningLoop& b) {
      return a.last - a.first < b.last - b.first;
    });
    return widest->site;
  }
  return std::nullopt;
}

}  // namespace lathesim::interp
