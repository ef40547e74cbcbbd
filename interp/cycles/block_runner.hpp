#pragma once
// Where a cycle's block stands in its program, and what runs the program's other blocks for
// it. G70 runs its contour's blocks N(ns)…N(nf), and G71–G73 run them to find the contour,
// through the block executor; the executor (execution/block_executor.hpp) implements
// BlockRunner and hands it down, so that cycles/ never calls up into execution/.

#include <cstddef>
#include <vector>

#include "interp/base/move.hpp"
#include "interp/base/result.hpp"
#include "interp/macro/variables.hpp"
#include "interp/state/interpreter_options.hpp"
#include "interp/state/modal_state.hpp"
#include "interp/text/block_parser.hpp"
#include "interp/text/program.hpp"

namespace lathesim::interp {

/// What one block did when run on its own.
struct BlockRun {
  ModalState state;             // the state after the block
  std::vector<Move> moves;      // in order
  std::vector<Error> warnings;  // located like errors
};

class BlockRunner {
 public:
  virtual ~BlockRunner() = default;
  /// Runs `words` (the block with ordinal `ordinal`) from `state` as a block on its own: no
  /// program around it, so a compound cycle in it is an error.
  virtual Result<BlockRun> run(ParsedBlock words, ModalState state, const InterpreterOptions& options,
                               int ordinal) const = 0;
};

/// Where a block stands in the whole program; the compound cycles (G70–G73) need it to find
/// and run their contour blocks.
struct BlockPlace {
  const Program& program;
  std::size_t index;            // its ordinal (Program::block)
  const BlockRunner& runner;    // runs the contour's blocks
  const macro::VariableStore* variables = nullptr;  // the macro variables, for contour blocks
                                                    // whose words are expressions
};

}  // namespace lathesim::interp
