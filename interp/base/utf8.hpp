#pragma once
// UTF-8 helpers: columns are counted in code points, not bytes.
// Character classes the way G-code reads them: ASCII only, whatever the locale.

#include <cstddef>
#include <string_view>

namespace lathesim::interp {

/// True for the bytes that start a UTF-8 code point (every byte but 10xxxxxx).
inline bool startsCodePoint(char byte) {
  return (static_cast<unsigned char>(byte) & 0xC0U) != 0x80U;
}

/// The number of code points in `text` (bytes that start one).
inline int codePointCount(std::string_view text) {
  int count = 0;
  for (char byte : text) count += startsCodePoint(byte) ? 1 : 0;
  return count;
}

/// The length in bytes of the code point starting at text[at] (1 for a stray byte).
inline std::size_t codePointLength(std::string_view text, std::size_t at) {
  std::size_t end = at + 1;
  while (end < text.size() && !startsCodePoint(text[end])) ++end;
  return end - at;
}

/// '0'–'9' (std::isdigit depends on the locale and on a non-negative argument).
inline bool isAsciiDigit(char c) { return c >= '0' && c <= '9'; }

/// 'A'–'Z' and 'a'–'z'.
inline bool isAsciiLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

}  // namespace lathesim::interp
