#pragma once
// A slice of a batch for one machine of several: `--shard I/N` runs the jobs whose 0-based
// place p in the manifest has p mod N = I − 1 (every N-th job from the I-th), so programs
// that sit together in a manifest — often of one size — are spread over the machines.

#include <optional>
#include <string>

namespace lathesim::batch {

struct Shard {
  int index = 1;  // 1-based: I of I/N
  int count = 1;  // N

  bool holds(int jobIndex) const { return jobIndex % count == index - 1; }
  bool whole() const { return count == 1; }
  /// "I-of-N", as it appears in a shard's summary file names.
  std::string tag() const { return std::to_string(index) + "-of-" + std::to_string(count); }
};

/// Reads "I/N" with 1 ≤ I ≤ N; nullopt if `text` is not that.
std::optional<Shard> parseShard(const std::string& text);

}  // namespace lathesim::batch
