#include "interp/diagnostic.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "interp/text/utf8.hpp"

namespace lathesim::interp {

std::string format(const Diagnostic& diagnostic) {
  const char* severity = diagnostic.severity == Severity::Error     ? "error"
                         : diagnostic.severity == Severity::Warning ? "warning"
                                                                    : "note";
  if (diagnostic.line <= 0) {
    return fmt::format("{}: {}: {}", diagnostic.file, severity, diagnostic.message);
  }
  std::string text = fmt::format("{}:{}:{}: {}: {}\n", diagnostic.file, diagnostic.line,
                                 diagnostic.column, severity, diagnostic.message);
  text += diagnostic.sourceLine;
  text += '\n';
  // The column counts code points, so one space per code point before it keeps the
  // caret under the right character even after multi-byte (e.g. Chinese) text.
  text.append(static_cast<std::size_t>(std::max(diagnostic.column - 1, 0)), ' ');
  text += '^';
  return text;
}

std::string lineOf(std::string_view text, int line) {
  if (line <= 0) return {};
  std::size_t begin = 0;
  for (int current = 1; current < line; ++current) {
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
