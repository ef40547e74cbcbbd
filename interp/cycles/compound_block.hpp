#pragma once
// G70–G76 in place of their block's motion (compound_cycle.hpp): the cycle run, its start
// noted, the contour's moves (G70) and the legs emitted.

#include <cstddef>
#include <optional>

#include "interp/base/result.hpp"
#include "interp/cycles/block_runner.hpp"
#include "interp/state/block_work.hpp"
#include "interp/text/block_parser.hpp"

namespace lathesim::interp {

/// Runs compound cycle `code` on `work`'s block, which stands at `place` in its program (null
/// for a block on its own: G70–G73 are then errors); G71–G73: the nf block to go on after
/// when it follows the cycle.
Result<std::optional<std::size_t>> runCompoundCycleBlock(BlockWork& work, const Code& code,
                                                         const BlockPlace* place);

}  // namespace lathesim::interp
