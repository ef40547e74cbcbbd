#pragma once
// The run's tool table and bar, for report.json ("tools", "stock") and report.html: every
// tool the setup or the program's comments declared, the T words (tool and offset) the run
// used it with, the offsets as the moves were shifted by them, and where each came from.

#include <nlohmann/json.hpp>
#include <vector>

#include "interp/base/move.hpp"
#include "setup/setup.hpp"

namespace lathesim::app {

/// A tool and offset pair the run used (T0101: tool 1, offset 1).
struct UsedToolOffset {
  int tool = 0;
  int offset = 0;
  int firstLine = 0;   // the first move's line under this pair
  std::size_t moves = 0;
  // Each distinct shift the moves under it had (radius, Z), in order: more than one when G10
  // changed the offset during the run. At most kShiftsKept; `moreShifts` counts the rest.
  std::vector<RZ> shifts;
  std::size_t moreShifts = 0;
};

/// Watches the moves as they pass (cheaply: a move under the same pair and shift as the one
/// before costs a comparison) and keeps the pairs in the order they were first used.
class ToolUsage {
 public:
  static constexpr std::size_t kShiftsKept = 8;
  void note(const interp::Move& move);
  const std::vector<UsedToolOffset>& used() const { return used_; }

 private:
  std::vector<UsedToolOffset> used_;
  UsedToolOffset* last_ = nullptr;  // the pair of the move before
  RZ lastShift_{0, 0};
};

/// report.json's "tools": one entry a tool the setup (or a comment) declares, in its order,
/// then any tool the run used that none declares; each with its facts, source and the offsets
/// the run used it with (the setup's [[offset]] values and the shifts the moves had).
nlohmann::ordered_json toolTableJson(const setup::Setup& setup, const std::vector<UsedToolOffset>& used);

/// report.json's "stock": the bar's diameter, length, bore, face Z and material, and who stated
/// each ("from": the setup, --stock, the program, or "assumed").
nlohmann::ordered_json stockJson(const setup::Setup& setup);

}  // namespace lathesim::app
