#include "interp/interpreter.hpp"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

#include "interp/execution/block_executor.hpp"
#include "interp/execution/call_stack.hpp"
#include "interp/motion/feed_warnings.hpp"
#include "interp/execution/modal_state.hpp"
#include "interp/compensation/nose_compensation.hpp"
#include "interp/text/control_family.hpp"
#include "interp/text/program.hpp"

namespace lathesim::interp {
namespace {

// Runs the program from its first block until M02/M30, the end of the text, or the first
// error; appends to `toolpath` and `warnings`. A block's read error is reported when
// execution reaches it.
Status runProgram(std::string_view programText, const InterpreterOptions& options,
                  Toolpath& toolpath, std::vector<Error>& warnings, std::vector<Error>& notes) {
  ModalState state;
  state.frame.offsets = options.workOffsets;
  state.position = options.startPosition - state.frame.shift();
  state.feedMode = options.initialFeedMode;
  if (!options.toolNumbers.empty()) state.tool = options.toolNumbers.front();

  const Program program = readProgram(programText, options.blockDelete, options.dialect);
  for (const ReadNote& note : program.notes) notes.push_back({note.line, note.column, note.message});
  CallStack calls(program);
  std::size_t next = 0;
  while (!state.ended && next < program.blocks.size()) {
    const std::size_t index = next++;
    const ProgramBlock& block = program.blocks[index];
    toolpath.blockCount = std::max(toolpath.blockCount, block.ordinal + 1);
    if (block.skipped) continue;
    if (!block.parsed.ok()) return block.parsed.error();

    const BlockPlace place{program, index};
    auto outcome = executeBlock(block.parsed.value(), state, options, block.ordinal, &place);
    if (!outcome.ok()) return outcome.error();

    BlockOutcome& done = outcome.value();
    const ProgramFlow& flow = done.flow;
    if (flow.call) {
      auto target = calls.call(*flow.call, index);
      if (!target.ok()) return target.error();
      next = target.value();
    } else if (flow.returnColumn) {
      auto target = calls.giveBack(*flow.returnColumn, index);
      if (!target.ok()) return target.error();
      next = target.value();
    } else if (flow.continueAfter) {
      next = *flow.continueAfter + 1;
    }
    state = std::move(done.state);
    toolpath.moves.insert(toolpath.moves.end(), done.moves.begin(), done.moves.end());
    toolpath.cycleStarts.insert(toolpath.cycleStarts.end(), done.cycleStarts.begin(), done.cycleStarts.end());
    warnings.insert(warnings.end(), done.warnings.begin(), done.warnings.end());
  }
  if (!state.ended) {
    if (auto error = calls.unfinished()) return *error;
  }
  return success();
}

// Each move from its work coordinate system into the setup's frame. A change of system
// re-expresses the position (work_coordinates.cpp), so consecutive moves stay joined.
void placeInSetupFrame(std::vector<Move>& moves) {
  for (Move& move : moves) {
    move.from += move.workShift;
    move.to += move.workShift;
    if (isArc(move.kind)) move.center += move.workShift;
  }
}

// A program of another control family is refused as a whole, naming the family.
Status refuseForeignProgram(std::string_view programText) {
  const auto foreign = recogniseForeignProgram(programText);
  if (!foreign) return success();
  return Error{foreign->line, foreign->column,
               fmt::format("this is a program for {} ('{}'), not Fanuc/GSK lathe G-code: lathesim "
                           "reads the dialects fanuc-a, fanuc-b and hnc and does not translate other "
                           "control families",
                           foreign->family, foreign->evidence)};
}

}  // namespace

bool InterpretResult::ok() const {
  return std::none_of(diagnostics.begin(), diagnostics.end(),
                      [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

InterpretResult interpret(std::string_view programText, const std::string& fileName,
                          const InterpreterOptions& options) {
  InterpretResult result;
  result.toolpath.programName = fileName;
  result.toolpath.startPosition = options.startPosition;
  std::vector<Error> warnings;
  std::vector<Error> notes;
  Status status = refuseForeignProgram(programText);
  if (status.ok()) status = runProgram(programText, options, result.toolpath, warnings, notes);
  // The moves are made as programmed, in the work coordinate systems; placed in the setup's
  // frame, then G41/G42 and the tool offsets' shifts are applied.
  if (status.ok()) placeInSetupFrame(result.toolpath.moves);
  if (status.ok()) status = compensateNoseRadius(result.toolpath.moves);
  if (status.ok()) status = applyToolOffsets(result.toolpath.moves);
  if (!status.ok()) {
    // The error alone: it is what must be fixed, and nothing past it ran.
    const Error& error = status.error();
    result.diagnostics.push_back({Severity::Error, fileName, error.line, error.column,
                                  error.message, lineOf(programText, error.line)});
    return result;
  }
  for (Error& warning : implausibleFeedWarnings(result.toolpath)) warnings.push_back(std::move(warning));
  std::stable_sort(warnings.begin(), warnings.end(), [](const Error& a, const Error& b) {
    return a.line != b.line ? a.line < b.line : a.column < b.column;
  });
  for (const Error& warning : warnings) {
    result.diagnostics.push_back({Severity::Warning, fileName, warning.line, warning.column,
                                  warning.message, lineOf(programText, warning.line)});
  }
  for (const Error& note : notes) {
    result.diagnostics.push_back({Severity::Note, fileName, note.line, note.column, note.message,
                                  lineOf(programText, note.line)});
  }
  return result;
}

}  // namespace lathesim::interp
