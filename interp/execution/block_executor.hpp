#pragma once
// One parsed block applied to the modal state: the moves it makes and the state after it.
// The block is validated as a whole before its result is kept: on an error the caller's
// state is untouched and no move of the block is emitted. Every word must be used by some
// code of the block; a word left over is an error.

#include <optional>
#include <vector>

#include "interp/compensation/uncompensated_nose.hpp"
#include "interp/cycles/block_runner.hpp"
#include "interp/text/block_parser.hpp"
#include "interp/state/interpreter_options.hpp"
#include "interp/state/modal_state.hpp"
#include "interp/text/program.hpp"
#include "interp/execution/program_flow.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp {

struct BlockOutcome {
  ModalState state;         // the state after the block
  std::vector<Move> moves;  // in order, zero-length moves left out (a dwell is kept)
  std::vector<Error> warnings;         // located like errors; they do not stop the program
  std::vector<CycleStart> cycleStarts;  // the cycle this block ran, if any
  ProgramFlow flow;         // M98, M99, or where G71–G73 resume
  std::optional<ContourPass> contourPass;  // G70–G73: the contour it finished or roughed
  bool legsCompensated = false;  // G90/G94 under G41/G42: the cycle offset its own legs
};

/// Runs `block` from `state`. `ordinal` is the block's 0-based number among the blocks read.
/// Without `place` (a block on its own) G70–G73 are errors.
Result<BlockOutcome> executeBlock(ParsedBlock block, ModalState state,
                                  const InterpreterOptions& options, int ordinal,
                                  const BlockPlace* place = nullptr);

/// The block executor as the cycles run it (cycles/block_runner.hpp).
const BlockRunner& blockExecutor();

}  // namespace lathesim::interp
