#include "interp/interpreter.hpp"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

#include "interp/compensation/nose_compensation.hpp"
#include "interp/execution/program_runner.hpp"
#include "interp/motion/corners.hpp"
#include "interp/motion/rapid_path.hpp"
#include "interp/motion/travel_limits.hpp"
#include "interp/text/control_family.hpp"
#include "interp/text/program.hpp"

namespace lathesim::interp {
namespace {

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
  Program program = readProgram(programText, options.control.blockSkip, options.dialect, options.control.machineMCodes);
  for (const ReadNote& note : program.notes) notes.push_back({note.line, note.column, note.message});
  Status status = refuseForeignProgram(programText);
  if (status.ok()) status = refuseEmptyProgram(program, programText);
  if (status.ok()) status = runProgram(program, options, result.toolpath, warnings, notes);
  // The blocks are freed before compensation needs memory; the texts stay for the messages.
  program.blocks = {};
  program.programOf = {};
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
    if (moves.size() > options.maxMoves) {  // at the line of the move past the limit
      const Move& past = moves[options.maxMoves];
      status = *moveLimitError(moves.size(), options.maxMoves, past.line, past.column);
    }
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
