#include "interp/interpreter.hpp"

#include <algorithm>
#include <tuple>
#include <utility>

#include <fmt/format.h>

#include "interp/execution/block_executor.hpp"
#include "interp/execution/call_stack.hpp"
#include "interp/execution/modal_state.hpp"
#include "interp/compensation/nose_compensation.hpp"
#include "interp/motion/corners.hpp"
#include "interp/motion/rapid_path.hpp"
#include "interp/motion/travel_limits.hpp"
#include "interp/text/control_family.hpp"
#include "interp/text/program.hpp"
#include "interp/text/program_library.hpp"
#include "interp/text/word_units.hpp"

namespace lathesim::interp {
namespace {

// An error or warning of a block in a subprogram's own file names that file.
Error inFile(Error error, const Program& program, const ProgramBlock& block) {
  if (block.source != 0) error.file = program.sources[static_cast<std::size_t>(block.source)].name;
  return error;
}

// M98 of a program the text does not hold: read it from its file (program_library.hpp), or
// say which names were looked for where.
Status loadSubprogram(Program& program, const SubprogramCall& call, const ProgramBlock& caller,
                      const InterpreterOptions& options) {
  if (program.programStart.count(call.programNumber) != 0) return success();
  if (const auto file = findProgramFile(call.programNumber, options.programDirectories)) {
    appendProgramFile(program, file->path.string(), file->text, call.programNumber, options.control.blockSkip,
                      options.dialect);
    return success();
  }
  const auto names = programFileNames(call.programNumber);
  std::string directories;
  for (const auto& directory : options.programDirectories)
    directories += (directories.empty() ? "" : ", ") + directory.string();
  return inFile(Error{caller.line, call.column,
                      fmt::format("M98 calls O{:04}, which is neither in this program nor in a file: "
                                  "looked for {}, {}, {} … {} in {}; give the directory of the "
                                  "control's programs with --programs DIR",
                                  call.programNumber, names[0], names[1], names[2], names.back(),
                                  directories.empty() ? "no directory" : directories)},
                program, caller);
}

// More moves than `maxMoves`: an error at the line of the move that passed the limit
// (a subprogram file's moves carry the line of the M98 that called it).
std::optional<Error> moveLimitError(const std::vector<Move>& moves, std::size_t maxMoves) {
  if (moves.size() <= maxMoves) return std::nullopt;
  const Move& passing = moves[maxMoves];
  return Error{passing.line, passing.column,
               fmt::format("the program makes more than {} moves (the limit) by this block: a toolpath that long takes "
                           "hours to simulate, and nested repeats can ask for billions; if it is meant, raise the "
                           "limit with --max-moves or [sim] max_moves",
                           maxMoves)};
}

// Runs the program from its first block until M02/M30, the end of the text, or the first
// error; appends to `toolpath` and `warnings`. A block's read error is reported when
// execution reaches it. Moves made in a subprogram's own file carry the line of the M98 in
// the program that called it first, so every line of the toolpath is a line of the program.
Status runProgram(Program& program, const InterpreterOptions& options, Toolpath& toolpath,
                  std::vector<Error>& warnings) {
  ModalState state;
  state.frame.offsets = options.workOffsets;
  state.position = options.startPosition - state.frame.shift();
  state.feedMode = options.control.powerOnFeedMode;
  state.compound = CompoundCycleParams::of(options.control);
  if (!options.toolNumbers.empty()) state.tool = options.toolNumbers.front();

  if (program.textAfterEnd) warnings.push_back(*program.textAfterEnd);
  CallStack calls(program);
  std::size_t next = 0;
  while (!state.ended && next < program.blocks.size()) {
    const std::size_t index = next++;
    const ProgramBlock block = program.blocks[index];  // a copy: loading a file may grow the blocks
    toolpath.blockCount = std::max(toolpath.blockCount, block.ordinal + 1);
    if (block.skipped) continue;
    if (!block.parsed.ok()) return inFile(block.parsed.error(), program, block);

    const BlockPlace place{program, index};
    auto outcome = executeBlock(block.parsed.value(), state, options, block.ordinal, &place);
    if (!outcome.ok()) return inFile(outcome.error(), program, block);

    BlockOutcome& done = outcome.value();
    if (block.source != 0 && calls.outermostCall()) {
      const ProgramBlock& site = program.blocks[*calls.outermostCall()];
      for (Move& move : done.moves) std::tie(move.line, move.column) = std::pair{site.line, site.column};
      for (CycleStart& start : done.cycleStarts) std::tie(start.line, start.column) = std::pair{site.line, site.column};
    }
    const ProgramFlow& flow = done.flow;
    if (flow.call) {
      if (auto loaded = loadSubprogram(program, *flow.call, block, options); !loaded.ok()) return loaded.error();
      auto target = calls.call(*flow.call, index);
      if (!target.ok()) return inFile(target.error(), program, block);
      next = target.value();
    } else if (flow.giveBack && !calls.inSubprogram()) {
      // M99 in the main program: the control starts it over, forever; it is simulated once.
      warnings.push_back(inFile({block.line, flow.giveBack->column,
                                 "M99 ends the main program: the control runs it again from the start, "
                                 "forever; lathesim simulates it once"},
                                program, block));
      done.state.ended = true;
    } else if (flow.giveBack) {
      auto target = calls.giveBack(*flow.giveBack, index);
      if (!target.ok()) return inFile(target.error(), program, block);
      next = target.value();
    } else if (flow.continueAfter) {
      next = *flow.continueAfter + 1;
    }
    state = std::move(done.state);
    toolpath.moves.insert(toolpath.moves.end(), done.moves.begin(), done.moves.end());
    if (auto tooMany = moveLimitError(toolpath.moves, options.maxMoves)) return *tooMany;
    toolpath.cycleStarts.insert(toolpath.cycleStarts.end(), done.cycleStarts.begin(), done.cycleStarts.end());
    if (const auto stop = block.parsed.value().mCode(MGroup::Stop)) {
      const bool own = block.source == 0 || !calls.outermostCall();
      const ProgramBlock& at = own ? block : program.blocks[*calls.outermostCall()];
      toolpath.stops.push_back({at.line, own ? stop->column : at.column, stop->text});
    }
    for (const Error& warning : done.warnings) warnings.push_back(inFile(warning, program, block));
  }
  if (!state.ended) {
    if (auto error = calls.unfinished()) return *error;
  }
  if (auto mixed = state.lengthWriting.mixedWarning(NumberReading::of(options.control, state.inch)))
    warnings.push_back(*mixed);
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

// A file with no block to run is the wrong file or a program cut short, not a part that
// needs no machining: said as such rather than simulated as an untouched bar.
Status refuseEmptyProgram(const Program& program, std::string_view programText) {
  if (!program.blocks.empty()) return success();
  const bool blank = programText.find_first_not_of(" \t\r\n") == std::string_view::npos;
  return Error{0, 0,
               blank ? "the program is empty: there is no block to run"
                     : "the program holds only comments (and '%' or directive lines): there is no block to run; "
                       "is it the right file, or was it cut short?"};
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
  Program program = readProgram(programText, options.control.blockSkip, options.dialect);
  for (const ReadNote& note : program.notes) notes.push_back({note.line, note.column, note.message});
  Status status = refuseForeignProgram(programText);
  if (status.ok()) status = refuseEmptyProgram(program, programText);
  if (status.ok()) status = runProgram(program, options, result.toolpath, warnings);
  // The moves are made as programmed, in the work coordinate systems (G54–G59, G50); placed in
  // the setup's frame, then G41/G42 and the tool offsets' shifts are applied, each rapid is
  // given the path the machine makes, and the whole checked against the machine's travel.
  std::vector<Move>& moves = result.toolpath.moves;
  if (status.ok()) status = insertCorners(moves, warnings);
  if (status.ok()) placeInSetupFrame(moves);
  if (status.ok()) status = compensateNoseRadius(moves);
  if (status.ok()) status = applyToolOffsets(moves);
  if (status.ok() && options.control.rapidPath == RapidPath::NonLinear) splitRapidsIntoAxisLegs(moves, options.machine);
  if (status.ok())  // the dog-legs' second legs count too
    if (auto tooMany = moveLimitError(moves, options.maxMoves)) status = *tooMany;
  if (status.ok() && options.machine.travel) status = checkTravel(moves, *options.machine.travel);
  // A diagnostic in the file it names: the program's own, or a subprogram's.
  const LineStarts programLines(programText);
  const auto diagnostic = [&](Severity severity, const Error& e) {
    for (const SourceText& source : program.sources)
      if (!e.file.empty() && source.name == e.file)
        return Diagnostic{severity, e.file, e.line, e.column, e.message, lineOf(source.text, e.line)};
    return Diagnostic{severity, fileName, e.line, e.column, e.message, programLines.lineOf(programText, e.line)};
  };
  if (!status.ok()) {
    // The error alone: it is what must be fixed, and nothing past it ran.
    result.diagnostics.push_back(diagnostic(Severity::Error, status.error()));
    return result;
  }
  std::stable_sort(warnings.begin(), warnings.end(), [](const Error& a, const Error& b) {
    return a.line != b.line ? a.line < b.line : a.column < b.column;
  });
  for (const Error& warning : warnings) result.diagnostics.push_back(diagnostic(Severity::Warning, warning));
  for (const Error& note : notes) result.diagnostics.push_back(diagnostic(Severity::Note, note));
  return result;
}

}  // namespace lathesim::interp
