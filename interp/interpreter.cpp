#include "interp/interpreter.hpp"

#include <algorithm>
#include <utility>

#include "interp/block_executor.hpp"
#include "interp/block_parser.hpp"
#include "interp/feed_warnings.hpp"
#include "interp/lexer.hpp"
#include "interp/modal_state.hpp"

namespace lathesim::interp {
namespace {

// Reads blocks until the text ends, M02/M30, or the first error; appends to `toolpath` and
// `warnings`.
Status runProgram(std::string_view programText, const InterpreterOptions& options,
                  Toolpath& toolpath, std::vector<Error>& warnings) {
  ModalState state;
  state.position = options.startPosition;
  if (!options.toolNumbers.empty()) state.tool = options.toolNumbers.front();

  BlockReader reader(programText);
  while (!state.ended) {
    auto next = reader.next();
    if (!next.ok()) return next.error();
    if (!next.value()) break;
    const RawBlock& raw = *next.value();
    const int ordinal = toolpath.blockCount++;
    if (raw.deleted && options.blockDelete) continue;

    auto words = tokenize(raw);
    if (!words.ok()) return words.error();
    auto parsed = parseBlock(words.value(), raw.line, raw.column);
    if (!parsed.ok()) return parsed.error();
    auto outcome = executeBlock(std::move(parsed).value(), state, options, ordinal);
    if (!outcome.ok()) return outcome.error();

    state = std::move(outcome.value().state);
    const auto& moves = outcome.value().moves;
    toolpath.moves.insert(toolpath.moves.end(), moves.begin(), moves.end());
    const auto& starts = outcome.value().cycleStarts;
    toolpath.cycleStarts.insert(toolpath.cycleStarts.end(), starts.begin(), starts.end());
    const auto& found = outcome.value().warnings;
    warnings.insert(warnings.end(), found.begin(), found.end());
  }
  return success();
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
  const Status status = runProgram(programText, options, result.toolpath, warnings);
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
