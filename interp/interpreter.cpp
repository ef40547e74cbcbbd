#include "interp/interpreter.hpp"

#include <algorithm>
#include <cassert>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "interp/execution/move_pipeline.hpp"
#include "interp/execution/program_runner.hpp"
#include "interp/text/control_family.hpp"
#include "interp/text/program.hpp"

namespace lathesim::interp {
namespace {

// A file with no block to run is the wrong file or a program cut short, not a part that
// needs no machining: said as such rather than simulated as an untouched bar.
Status refuseEmptyProgram(const Program& program, std::string_view programText) {
  if (program.blockCount() != 0) return success();
  const bool blank = programText.find_first_not_of(" \t\r\n") == std::string_view::npos;
  return Error{0, 0,
               blank ? "the program is empty: there is no block to run"
                     : "the program holds only comments (and '%' or directive lines): there is no block to run; "
                       "is it the right file, or was it cut short?"};
}

// A program of another control family is refused as a whole, naming the family.
Status refuseForeignProgram(PagedText programText, const InterpreterOptions& options) {
  const auto foreign = options.foreignProgram ? *options.foreignProgram : recogniseForeignProgram(programText);
  if (!foreign) return success();
  return Error{foreign->line, foreign->column,
               fmt::format("this is a program for {} ('{}'), not Fanuc/GSK lathe G-code: lathesim "
                           "reads the dialects fanuc-a, fanuc-b, hnc and haas and does not translate other "
                           "control families",
                           foreign->family, foreign->evidence)};
}

}  // namespace

bool InterpretResult::ok() const {
  return std::none_of(diagnostics.begin(), diagnostics.end(),
                      [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

InterpretResult interpret(PagedText programText, const std::string& fileName,
                          const InterpreterOptions& options) {
  std::vector<Move> moves;
  MoveCollector collector(moves);
  InterpretResult result = interpret(programText, fileName, options, collector);
  moves.insert(moves.end(), result.toolpath.moves.begin(), result.toolpath.moves.end());  // an error's
  result.toolpath.moves = std::move(moves);
  return result;
}

InterpretResult interpret(PagedText programText, const std::string& fileName,
                          const InterpreterOptions& options, MoveSink& moves) {
  return interpret(readProgram(programText, options.control.blockSkip, options.dialect, options.control.machineMCodes),
                   fileName, options, moves);
}

InterpretResult interpret(Program&& program, const std::string& fileName, const InterpreterOptions& options,
                          MoveSink& moves) {
  assert(program.sources.front().blockDelete == options.control.blockSkip &&
         program.sources.front().dialect == options.dialect &&
         program.sources.front().machine == options.control.machineMCodes);
  const PagedText programText = program.sources.front().text;  // a copy: sources grows as M98 reads files
  InterpretResult result;
  result.toolpath.programName = fileName;
  result.toolpath.startPosition = options.startPosition;
  std::vector<Error> warnings;
  std::vector<Error> notes;
  for (const ReadNote& note : program.notes) (note.warning ? warnings : notes).push_back({note.line, note.column, note.message});
  Status status = refuseForeignProgram(programText, options);
  if (status.ok()) status = refuseEmptyProgram(program, programText.view());
  MovePipeline pipeline(options, moves, warnings);
  moves.recordingIn(result.toolpath);
  if (status.ok()) {
    status = runProgram(program, options, result.toolpath, pipeline, warnings, notes, result.skippedBlocks);
    if (status.ok()) status = pipeline.finish();
    else result.toolpath.moves = pipeline.abandon();
  }
  // A diagnostic in the file it names: the program's own, or a subprogram's. The program's
  // lines are quoted in one pass once all are known (quoteLines), holding nothing a line.
  std::vector<std::size_t> inProgram;  // of result.diagnostics
  const auto add = [&](Severity severity, const Error& e) {
    for (const SourceText& source : program.sources) {
      if (!e.file.empty() && source.name == e.file) {
        result.diagnostics.push_back({severity, e.file, e.line, e.column, e.message, lineOf(source.text, e.line)});
        return;
      }
    }
    inProgram.push_back(result.diagnostics.size());
    result.diagnostics.push_back({severity, fileName, e.line, e.column, e.message, ""});
  };
  if (!status.ok()) {
    // The error alone: it is what must be fixed, and nothing past it ran.
    add(Severity::Error, status.error());
  } else {
    std::stable_sort(warnings.begin(), warnings.end(), [](const Error& a, const Error& b) {
      return a.line != b.line ? a.line < b.line : a.column < b.column;
    });
    for (const Error& warning : warnings) add(Severity::Warning, warning);
    for (const Error& note : notes) add(Severity::Note, note);
  }
  std::vector<Diagnostic*> quoting;
  for (const std::size_t index : inProgram) quoting.push_back(&result.diagnostics[index]);
  quoteLines(programText, std::move(quoting));
  return result;
}

}  // namespace lathesim::interp
