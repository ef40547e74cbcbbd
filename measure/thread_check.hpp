#pragma once
// A drawing's thread callout (drawing.hpp) against the thread measured in its zone
// (thread_measure.hpp): the pitch to a tenth of a voxel (what the measurement resolves), the
// number of starts and the hand exactly, and each diameter the callout limits within its
// limits at every angle measured.

#include <optional>
#include <string>
#include <vector>

#include "measure/drawing.hpp"
#include "measure/thread_measure.hpp"

namespace lathesim::measure {

struct ThreadCheckItem {
  std::string name;      // "pitch", "starts", "hand", "major", "minor", "pitch_diameter"
  std::string expected;  // as the callout says, in words
  std::string measured;
  bool within = true;
};

struct ThreadCheck {
  ThreadCallout callout;
  std::optional<int> line;  // of the thread measured there (its first pass), when one was cut
  std::vector<ThreadCheckItem> items;
  bool within() const;
};

/// Checks `callout` against the thread of `threads` whose span overlaps its zone.
ThreadCheck checkThread(const ThreadCallout& callout, const std::vector<MeasuredThread>& threads, double voxelMm);

}  // namespace lathesim::measure
