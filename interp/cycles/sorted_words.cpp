#include "interp/cycles/sorted_words.hpp"

#include "interp/macro/block_words.hpp"
#include "interp/text/word_units.hpp"

namespace lathesim::interp {

Result<ParsedBlock> sortedWords(const Program& program, const ProgramBlock& block, const macro::VariableStore* variables,
                                const ModalState& state, const InterpreterOptions& options) {
  if (const Error* error = program.errorOf(block)) return *error;
  if (auto words = program.plainWords(block)) return std::move(*words);
  if (block.macroBlock() == nullptr) return Error{block.line, block.column, "a block skipped by block delete has no words to run"};
  const macro::MacroBlock& macroBlock = *block.macroBlock();
  if (macroBlock.statement) return Error{block.line, block.column, "a macro statement has no words to run here"};
  const macro::VariableStore none;
  auto evaluated = macro::evaluateWords(macroBlock, variables != nullptr ? *variables : none, block.line,
                                        NumberReading::of(options.control, state.inch));
  if (!evaluated.ok()) return evaluated.error();
  auto parsed = parseBlock(evaluated.value().words, block.line, block.column, options.dialect,
                           options.control.machineMCodes);
  if (!parsed.ok()) return macro::withLeftOutNote(parsed.error(), evaluated.value().leftOut);
  return parsed;
}

}  // namespace lathesim::interp
