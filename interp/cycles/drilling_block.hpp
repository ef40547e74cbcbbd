#pragma once
// G81–G84 read from their block: drilling and tapping on the spindle's axis (the legs:
// drilling_cycle.hpp), the R point, peck and dwell kept for the blocks that repeat the cycle.

#include <optional>

#include "interp/base/result.hpp"
#include "interp/state/block_work.hpp"
#include "interp/text/block_parser.hpp"

namespace lathesim::interp {

/// The drilling cycle `code` (G81–G84) on `work`'s block, or the modal one when it is none.
Status runDrillingCycle(BlockWork& work, const std::optional<Code>& code);

}  // namespace lathesim::interp
