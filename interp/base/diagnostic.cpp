#include "interp/base/diagnostic.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "interp/base/printable_text.hpp"
#include "interp/base/utf8.hpp"

namespace lathesim::interp {

std::string format(const Diagnostic& diagnostic) {
  const char* severity = diagnostic.severity == Severity::Error     ? "error"
                         : diagnostic.severity == Severity::Warning ? "warning"
                                                                    : "note";
  const std::string file = printable(diagnostic.file);
  const std::string message = printable(diagnostic.message);
  if (diagnostic.line <= 0) return fmt::format("{}: {}: {}", file, severity, message);
  std::string text = fmt::format("{}:{}:{}: {}: {}\n", file, diagnostic.line, diagnostic.column, severity, message);
  text += printable(diagnostic.sourceLine);
  text += '\n';
  // The column counts code points, so one space per code point before it keeps the caret
  // under the right character even after multi-byte (e.g. Chinese) text — counted in the
  // line as shown, where an escaped control character takes four.
  const std::string_view line = diagnostic.sourceLine;
  std::size_t before = 0;
  int column = 1;
  for (; column < diagnostic.column && before < line.size(); ++column) before += codePointLength(line, before);
  const int width = codePointCount(printable(line.substr(0, before))) + std::max(diagnostic.column - column, 0);
  text.append(static_cast<std::size_t>(width), ' ');
  text += '^';
  return text;
}

void quoteLines(PagedText paged, std::vector<Diagnostic*> diagnostics) {
  const std::string_view text = paged.view();
  std::stable_sort(diagnostics.begin(), diagnostics.end(),
                   [](const Diagnostic* a, const Diagnostic* b) { return a->line < b->line; });
  int line = 1;
  std::size_t begin = 0;  // where `line` starts; past the text's end when it has no such line
  for (Diagnostic* diagnostic : diagnostics) {
    for (; line < diagnostic->line && begin <= text.size(); ++line) {
      paged.readingAt(begin);
      const std::size_t newline = text.find('\n', begin);
      begin = newline == std::string_view::npos ? text.size() + 1 : newline + 1;
    }
    if (diagnostic->line <= 0 || begin > text.size()) {
      diagnostic->sourceLine.clear();
      continue;
    }
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    if (end > begin && text[end - 1] == '\r') --end;
    diagnostic->sourceLine = std::string(text.substr(begin, end - begin));
  }
}

LineStarts::LineStarts(PagedText paged) {
  const std::string_view text = paged.view();
  starts_.push_back(0);
  for (std::size_t at = text.find('\n'); at != std::string_view::npos; at = text.find('\n', at + 1)) {
    paged.readingAt(at);
    starts_.push_back(at + 1);
  }
}

std::string LineStarts::lineOf(std::string_view text, int line) const {
  if (line <= 0 || static_cast<std::size_t>(line) > starts_.size()) return {};
  const std::size_t begin = starts_[static_cast<std::size_t>(line) - 1];
  if (begin > text.size()) return {};
  std::size_t end = text.find('\n', begin);
  if (end == std::string_view::npos) end = text.size();
  if (end > begin && text[end - 1] == '\r') --end;
  return std::string(text.substr(begin, end - begin));
}

std::string lineOf(PagedText paged, int line) {
  const std::string_view text = paged.view();
  if (line <= 0) return {};
  std::size_t begin = 0;
  for (int current = 1; current < line; ++current) {
    paged.readingAt(begin);
    const std::size_t newline = text.find('\n', begin);
    if (newline == std::string_view::npos) return {};
    begin = newline + 1;
  }
  std::size_t end = text.find('\n', begin);
  if (end == std::string_view::npos) end = text.size();
  if (end > begin && text[end - 1] == '\r') --end;
  return std::string(text.substr(begin, end - begin));
}

}  // namespace lathesim::interp
