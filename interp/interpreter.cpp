#include "interp/interpreter.hpp"

#include <algorithm>
#include <utility>

#include "interp/compensation/nose_compensation.hpp"
#include "interp/execution/program_runner.hpp"
#include "interp/motion/feed_warnings.hpp"
#include "interp/text/program.hpp"

namespace lathesim::interp {

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
  Status status = [&] {  // the program read is freed before compensation needs memory
    const Program program = readProgram(programText, options.blockDelete, options.dialect);
    return runProgram(program, options, result.toolpath, warnings);
  }();
  // The moves are made as programmed; then G41/G42 and the offsets' shifts are applied.
  if (status.ok()) status = compensateNoseRadius(result.toolpath.moves);
  if (status.ok()) status = applyToolOffsets(result.toolpath.moves, options.offsets);
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
  return result;
}

}  // namespace lathesim::interp
