#pragma once
// The thread codes read from their block: G32, a cut synchronised with the spindle
// (thread_cut.hpp), and G92, the thread cycle (g92_cycle.hpp), with their lead, start angle,
// run-out and starts (thread_words.hpp); and the check every thread's legs get against the
// axes' speed (G76's too).

#include <optional>
#include <vector>

#include "interp/base/result.hpp"
#include "interp/contour/cycle_leg.hpp"
#include "interp/state/block_work.hpp"
#include "interp/text/block_parser.hpp"

namespace lathesim::interp {

/// G32 on `work`'s block (`code` as written, or none when modal).
Status runThreadCut(BlockWork& work, const std::optional<Code>& code);

/// G92 on `work`'s block (`code` as written, or none when the block repeats the cycle).
Status runThreadCycle(BlockWork& work, const std::optional<Code>& code);

/// Warns (at `column`) when a thread leg's lead × rpm is faster than its lead axis can move.
void warnIfThreadTooFast(BlockWork& work, const std::vector<CycleLeg>& legs, int column);

}  // namespace lathesim::interp
