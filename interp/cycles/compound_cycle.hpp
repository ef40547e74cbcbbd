#pragma once
// G70–G76, the one-shot compound cycles: their words read (first block or second block), the
// modal first-block values kept, the contour found for G70–G73, and the legs made by
// g73_cycle, peck_cycle, roughing_cycle and g76_cycle. The executor stamps the legs like any move.

#include <cstddef>
#include <optional>
#include <vector>

#include "interp/execution/block_executor.hpp"
#include "interp/text/block_parser.hpp"
#include "interp/contour/cycle_leg.hpp"
#include "interp/interpreter.hpp"
#include "interp/state/modal_state.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp {

struct CompoundOutcome {
  std::vector<Move> contourMoves;  // G70: the contour blocks' own moves, before the legs
  std::vector<CycleLeg> legs;      // the cycle block's moves
  std::optional<std::size_t> continueAfter;  // G71–G73: the nf block, when it follows
  std::vector<Error> warnings;               // G70's contour blocks', and the cycle's own
};

/// G70 to G76.
bool isCompoundCycle(const Code& code);

/// Runs compound cycle `code` of `block`, taking the words it uses. `state` (its F, S, T
/// already set from the block) is updated: the first-block values, and for G70 what the
/// contour blocks set. `place` locates the block in the program (needed by G70–G73).
/// `feedGiven`: the block gave F (G76 may not give I as well).
Result<CompoundOutcome> runCompoundCycle(const Code& code, ParsedBlock& block, ModalState& state,
                                         const InterpreterOptions& options,
                                         const BlockPlace* place, bool feedGiven = false);

}  // namespace lathesim::interp
