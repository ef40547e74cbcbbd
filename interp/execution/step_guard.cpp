#include "interp/execution/step_guard.hpp"

#include <algorithm>

namespace lathesim::interp {

bool StepGuard::step(std::size_t index) {
  Frame& loops = frames_.back();
  // A loop is left once execution stands outside the blocks it spans.
  std::erase_if(loops, [index](const RunningLoop& loop) { return index < loop.first || index > loop.last; });
  if (!ran_[index]) {
    ran_[index] = true;
    return false;
  }
  return ++steps_ > maxSteps_;
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
