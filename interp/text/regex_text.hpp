#pragma once
// What the std::regex patterns that read a program's lines and comments (other control
// families, a stated bar, tools named in comments) may be given. libstdc++'s regex recurses
// once per character it tries, so a long enough text overflows the stack: a line of 300 000
// characters crashed lathesim. They look at a line's or comment's first kRegexTextChars
// characters only, far past any real block or comment.

#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

#include "interp/base/utf8.hpp"

namespace lathesim::interp {

inline constexpr std::size_t kRegexTextChars = 1000;

/// The length of `text` cut after kRegexTextChars bytes (at the start of a code point).
inline std::size_t regexTextLength(std::string_view text) {
  if (text.size() <= kRegexTextChars) return text.size();
  std::size_t end = kRegexTextChars;
  while (end > 0 && !startsCodePoint(text[end])) --end;
  return end;
}

/// `text` cut after kRegexTextChars bytes (at the start of a code point).
inline std::string regexText(std::string_view text) { return std::string(text.substr(0, regexTextLength(text))); }

/// The value of digits a pattern matched (`[0-9]+\.?[0-9]*`), or nullopt when they are too
/// many to be a finite number (std::stod would throw).
inline std::optional<double> matchedNumber(const std::string& digits) {
  const double value = std::strtod(digits.c_str(), nullptr);
  if (!std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace lathesim::interp
