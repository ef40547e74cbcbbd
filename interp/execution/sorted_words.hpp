#pragma once
// The words of a program block sorted into codes as the block would run now: a block of plain
// words as read, a macro block's words with their expressions evaluated against the
// variables. For blocks run from elsewhere than the program runner (the contour blocks of
// G70–G73).

#include "interp/state/modal_state.hpp"
#include "interp/interpreter.hpp"
#include "interp/macro/variables.hpp"
#include "interp/base/result.hpp"
#include "interp/text/block_parser.hpp"
#include "interp/text/program.hpp"

namespace lathesim::interp {

/// Fails for a block that cannot be read, or a macro statement (it has no words to run).
/// `variables` may be null when no macro variables exist (a block run on its own). The values
/// are read as the control does from `state` (G20) under `options` (its dialect and parameters).
Result<ParsedBlock> sortedWords(const Program& program, const ProgramBlock& block, const macro::VariableStore* variables,
                                const ModalState& state, const InterpreterOptions& options);

}  // namespace lathesim::interp
