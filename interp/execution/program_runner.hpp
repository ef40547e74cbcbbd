#pragma once
// A program read by readProgram, run block by block from the first until M02/M30, the end of
// the text or the first error: plain blocks through the block executor, blocks of Custom
// Macro B with their words evaluated as they run (their values may change between runs),
// the statements through MacroFlow, and the calls (M98, G65) and returns (M99) through the
// call stack. Every run of a block counts against the step limit.
// A program called that the text lacks is read from its file (text/program_library.hpp) and
// appended to `program`; an error or warning of a block of that file names the file, and its
// moves carry the line of the call in the main program that led there, so every line of the
// toolpath is a line of the program.

#include <optional>
#include <vector>

#include "interp/execution/move_pipeline.hpp"
#include "interp/interpreter.hpp"
#include "interp/base/result.hpp"
#include "interp/text/program.hpp"

namespace lathesim::interp {

/// Runs `program`, handing its moves to `moves` block by block (the caller finishes it), its
/// cycle starts, stops and parts catcher commands to `toolpath`, its warnings to `warnings`
/// (each once, however often its block runs) and its notes (a macro's #3006 stops) to
/// `notes`, the '/' blocks it skipped to `skipped`. A block's read error is reported when
/// execution reaches it.
Status runProgram(Program& program, const InterpreterOptions& options, Toolpath& toolpath, MovePipeline& moves,
                  std::vector<Error>& warnings, std::vector<Error>& notes, std::vector<SkippedBlock>& skipped);

/// When `moves` passes `maxMoves` (InterpreterOptions::maxMoves), the error at `line`,
/// `column` (the block that made the move past the limit) that names the limit.
std::optional<Error> moveLimitError(std::size_t moves, std::size_t maxMoves, int line, int column);

}  // namespace lathesim::interp
