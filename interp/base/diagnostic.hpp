#pragma once
// A problem in a user's input (a program or a setup file), located to the character.

#include <string>
#include <string_view>
#include <vector>

#include "interp/base/paged_text.hpp"

namespace lathesim::interp {

enum class Severity { Error, Warning, Note };  // a note: something read differently, said once

struct Diagnostic {
  Severity severity = Severity::Error;
  std::string file;
  int line = 0;    // 1-based; 0 when the problem is the file as a whole
  int column = 0;  // 1-based
  std::string message;
  std::string sourceLine;  // the offending line's text, for the caret display
};

/// "file:line:col: error: message", then the source line and a caret under the column
/// (the caret counts UTF-8 characters, so it stays aligned after Chinese comments).
std::string format(const Diagnostic& diagnostic);

/// The text of 1-based line `line` in `text`, without its line ending; empty if absent.
std::string lineOf(PagedText text, int line);

/// Fills the source line of each of `diagnostics` (the lines of `text` they are at, as lineOf
/// gives them) in one pass over `text`, holding nothing for the lines no diagnostic is at.
void quoteLines(PagedText text, std::vector<Diagnostic*> diagnostics);

/// Where each line of a text starts, found once: many diagnostics can then each quote their
/// line without scanning the text from its start (a warning on every block of a long program
/// made that quadratic: 40 000 blocks took 8 s). Holds offsets only, so it stays valid when
/// the string holding the text is moved.
class LineStarts {
 public:
  LineStarts() = default;
  explicit LineStarts(PagedText text);
  /// As lineOf(text, line), for the text this was made from.
  std::string lineOf(std::string_view text, int line) const;

 private:
  std::vector<std::size_t> starts_;
};

}  // namespace lathesim::interp
