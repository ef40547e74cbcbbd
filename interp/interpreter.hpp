#pragma once
// G-code text → Toolpath. The single entry point of the interp module.

#include <string>
#include <vector>

#include "interp/base/diagnostic.hpp"
#include "interp/base/move.hpp"
#include "interp/base/move_sink.hpp"
#include "interp/base/paged_text.hpp"
#include "interp/base/skipped_block.hpp"
#include "interp/state/interpreter_options.hpp"

namespace lathesim::interp {

class Program;

struct InterpretResult {
  Toolpath toolpath;
  std::vector<SkippedBlock> skippedBlocks;  // every '/' block the run reached and skipped, once each
  std::vector<Diagnostic> diagnostics;  // the error that stopped the program alone, or the
                                        // warnings and notes of a program that ran, by line
  bool ok() const;
};

/// The moves in `result.toolpath.moves`.
InterpretResult interpret(PagedText programText, const std::string& fileName,
                          const InterpreterOptions& options);

/// The moves handed to `moves` as they are made, in order, each once nothing can change it:
/// a long program never holds its whole toolpath (`result.toolpath` has everything else). A
/// program that fails may have handed on moves before its error: the consumer drops them; the
/// moves made before the error and not handed on are left in `result.toolpath.moves`, as
/// their blocks made them (what `interpret` without a sink gives after those handed on).
InterpretResult interpret(PagedText programText, const std::string& fileName,
                          const InterpreterOptions& options, MoveSink& moves);

/// The same for `program`, its text already read through by readProgram (text/program.hpp) with
/// the options' block skip, dialect and machine M codes, so that a caller that read it for a
/// purpose of its own (the tools named in comments) does not have it read again.
InterpretResult interpret(Program&& program, const std::string& fileName, const InterpreterOptions& options,
                          MoveSink& moves);

}  // namespace lathesim::interp
