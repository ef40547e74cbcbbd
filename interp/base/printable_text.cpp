#include "interp/base/printable_text.hpp"

#include <cstdint>

namespace lathesim::interp {
namespace {

// The code point of the well-formed UTF-8 sequence at text[at] and its length in bytes, or
// length 0 when the bytes there are not one (a stray continuation byte, a truncated or
// overlong sequence, a surrogate, a value beyond U+10FFFF).
struct Decoded {
  std::uint32_t codePoint = 0;
  std::size_t length = 0;
};

Decoded decode(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t i) { return static_cast<std::uint8_t>(text[i]); };
  const std::uint8_t lead = byte(at);
  if (lead < 0x80) return {lead, 1};
  std::size_t length = 0;
  std::uint32_t value = 0;
  std::uint32_t smallest = 0;  // below this the sequence is overlong
  if ((lead & 0xE0U) == 0xC0U) {
    length = 2, value = lead & 0x1FU, smallest = 0x80;
  } else if ((lead & 0xF0U) == 0xE0U) {
    length = 3, value = lead & 0x0FU, smallest = 0x800;
  } else if ((lead & 0xF8U) == 0xF0U) {
    length = 4, value = lead & 0x07U, smallest = 0x10000;
  } else {
    return {};
  }
  if (at + length > text.size()) return {};
  for (std::size_t i = 1; i < length; ++i) {
    if ((byte(at + i) & 0xC0U) != 0x80U) return {};
    value = (value << 6) | (byte(at + i) & 0x3FU);
  }
  if (value < smallest || value > 0x10FFFF || (value >= 0xD800 && value <= 0xDFFF)) return {};
  return {value, length};
}

bool actsOnTerminal(std::uint32_t c) {
  return (c < 0x20 && c != '\t' && c != '\n') || c == 0x7F || (c >= 0x80 && c <= 0x9F) || (c >= 0x202A && c <= 0x202E) ||
         (c >= 0x2066 && c <= 0x2069);
}

// Appends `prefix` and `value` as `digits` lower-case hex digits (\x1b, \u202e). By hand,
// not through fmt: every diagnostic escapes its whole line, byte by byte for a binary file.
void appendEscape(std::string& shown, const char* prefix, std::uint32_t value, int digits) {
  static constexpr char kHex[] = "0123456789abcdef";
  shown += prefix;
  for (int shift = 4 * (digits - 1); shift >= 0; shift -= 4) shown += kHex[(value >> shift) & 0xFU];
}

}  // namespace

std::string printable(std::string_view text) {
  std::string shown;
  shown.reserve(text.size());
  for (std::size_t at = 0; at < text.size();) {
    const Decoded d = decode(text, at);
    if (d.length == 0) {
      appendEscape(shown, "\\x", static_cast<std::uint8_t>(text[at]), 2);
      ++at;
      continue;
    }
    if (!actsOnTerminal(d.codePoint)) {
      shown.append(text.substr(at, d.length));
    } else if (d.codePoint < 0x80) {
      appendEscape(shown, "\\x", d.codePoint, 2);
    } else {
      appendEscape(shown, "\\u", d.codePoint, 4);
    }
    at += d.length;
  }
  return shown;
}

}  // namespace lathesim::interp
