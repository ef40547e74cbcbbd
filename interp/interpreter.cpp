#include "interp/interpreter.hpp"

#include <algorithm>
#include <utility>

#include "interp/execution/block_executor.hpp"
#include "interp/execution/call_stack.hpp"
#include "interp/execution/modal_state.hpp"
#include "interp/compensation/nose_compensation.hpp"
#include "interp/motion/rapid_path.hpp"
#include "interp/motion/travel_limits.hpp"
#include "interp/text/program.hpp"
#include "interp/text/word_units.hpp"

namespace lathesim::interp {
namespace {

// Runs the program from its first block until M02/M30, the end of the text, or the first
// error; appends to `toolpath` and `warnings`. A block's read error is reported when
// execution reaches it.
Status runProgram(std::string_view programText, const InterpreterOptions& options,
                  Toolpath& toolpath, std::vector<Error>& warnings) {
  ModalState state;
  state.position = options.startPosition;
  state.feedMode = options.control.powerOnFeedMode;
  state.compound = CompoundCycleParams::of(options.control);
  if (!options.toolNumbers.empty()) state.tool = options.toolNumbers.front();

  const Program program = readProgram(programText, options.control.blockSkip, options.dialect);
  if (program.textAfterEnd) warnings.push_back(*program.textAfterEnd);
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
    } else if (flow.giveBack && !calls.inSubprogram()) {
      // M99 in the main program: the control starts it over, forever; it is simulated once.
      warnings.push_back({block.line, flow.giveBack->column,
                          "M99 ends the main program: the control runs it again from the start, forever; "
                          "lathesim simulates it once"});
      done.state.ended = true;
    } else if (flow.giveBack) {
      auto target = calls.giveBack(*flow.giveBack, index);
      if (!target.ok()) return target.error();
      next = target.value();
    } else if (flow.continueAfter) {
      next = *flow.continueAfter + 1;
    }
    state = std::move(done.state);
    toolpath.moves.insert(toolpath.moves.end(), done.moves.begin(), done.moves.end());
    toolpath.cycleStarts.insert(toolpath.cycleStarts.end(), done.cycleStarts.begin(), done.cycleStarts.end());
    if (const auto stop = block.parsed.value().mCode(MGroup::Stop))
      toolpath.stops.push_back({block.line, stop->column, stop->text});
    warnings.insert(warnings.end(), done.warnings.begin(), done.warnings.end());
  }
  if (!state.ended) {
    if (auto error = calls.unfinished()) return *error;
  }
  if (auto mixed = state.lengthWriting.mixedWarning(NumberReading::of(options.control, state.inch)))
    warnings.push_back(*mixed);
  return success();
}

// The moves are made in the program's frame; G50 moves that frame (Move::workShift).
void shiftIntoSetupFrame(std::vector<Move>& moves) {
  for (Move& move : moves) {
    move.from += move.workShift;
    move.to += move.workShift;
    move.center += move.workShift;
  }
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
  Status status = runProgram(programText, options, result.toolpath, warnings);
  // The moves are made as programmed; then G41/G42 and the offsets' shifts are applied, the
  // moves placed in the setup's frame, and each rapid given the path the machine makes.
  std::vector<Move>& moves = result.toolpath.moves;
  if (status.ok()) status = compensateNoseRadius(moves);
  if (status.ok()) status = applyToolOffsets(moves, options.offsets);
  if (status.ok()) {
    shiftIntoSetupFrame(moves);
    if (options.control.rapidPath == RapidPath::NonLinear) splitRapidsIntoAxisLegs(moves, options.machine);
    if (options.machine.travel) status = checkTravel(moves, *options.machine.travel);
  }
  if (!status.ok()) {
    // The error alone: it is what must be fixed, and nothing past it ran.
    const Error& error = status.error();
    result.diagnostics.push_back({Severity::Error, fileName, error.line, error.column,
                                  error.message, lineOf(programText, error.line)});
    return result;
  }
  std::stable_sort(warnings.begin(), warnings.end(), [](const Error& a, const Error& b) {
    return a.line != b.line ? a.line < b.line : a.column < b.column;
  });
  for (const Error& warning : warnings) {
    result.diagnostics.push_back({Severity::Warning, fileName, warning.line, warning.column,
                                  warning.message, lineOf(programText, warning.line)});
  }
  return result;
}

}  // namespace lathesim::interp
