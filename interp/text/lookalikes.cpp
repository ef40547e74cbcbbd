#include "interp/text/lookalikes.hpp"

#include <array>
#include <cstdint>

#include <fmt/format.h>

namespace lathesim::interp {
namespace {

struct Entry {
  std::uint32_t codePoint;
  std::string_view name;
  std::string_view meant;
};

// Single code points; the full-width ASCII block is computed below.
constexpr std::array kTable{
    Entry{0x00A0, "NO-BREAK SPACE", " "},
    Entry{0x2007, "FIGURE SPACE", " "},
    Entry{0x202F, "NARROW NO-BREAK SPACE", " "},
    Entry{0x3000, "IDEOGRAPHIC SPACE", " "},
    Entry{0x2010, "HYPHEN", "-"},
    Entry{0x2011, "NON-BREAKING HYPHEN", "-"},
    Entry{0x2012, "FIGURE DASH", "-"},
    Entry{0x2013, "EN DASH", "-"},
    Entry{0x2014, "EM DASH", "-"},
    Entry{0x2015, "HORIZONTAL BAR", "-"},
    Entry{0x2212, "MINUS SIGN", "-"},
    Entry{0xFE63, "SMALL HYPHEN-MINUS", "-"},
    Entry{0x2024, "ONE DOT LEADER", "."},
    Entry{0x3002, "IDEOGRAPHIC FULL STOP", "."},
    Entry{0x0391, "GREEK CAPITAL LETTER ALPHA", "A"},
    Entry{0x0392, "GREEK CAPITAL LETTER BETA", "B"},
    Entry{0x0395, "GREEK CAPITAL LETTER EPSILON", "E"},
    Entry{0x0396, "GREEK CAPITAL LETTER ZETA", "Z"},
    Entry{0x0397, "GREEK CAPITAL LETTER ETA", "H"},
    Entry{0x0399, "GREEK CAPITAL LETTER IOTA", "I"},
    Entry{0x039A, "GREEK CAPITAL LETTER KAPPA", "K"},
    Entry{0x039C, "GREEK CAPITAL LETTER MU", "M"},
    Entry{0x039D, "GREEK CAPITAL LETTER NU", "N"},
    Entry{0x039F, "GREEK CAPITAL LETTER OMICRON", "O"},
    Entry{0x03A1, "GREEK CAPITAL LETTER RHO", "P"},
    Entry{0x03A4, "GREEK CAPITAL LETTER TAU", "T"},
    Entry{0x03A7, "GREEK CAPITAL LETTER CHI", "X"},
    Entry{0x03BF, "GREEK SMALL LETTER OMICRON", "o"},
    Entry{0x0410, "CYRILLIC CAPITAL LETTER A", "A"},
    Entry{0x0412, "CYRILLIC CAPITAL LETTER VE", "B"},
    Entry{0x0415, "CYRILLIC CAPITAL LETTER IE", "E"},
    Entry{0x041A, "CYRILLIC CAPITAL LETTER KA", "K"},
    Entry{0x041C, "CYRILLIC CAPITAL LETTER EM", "M"},
    Entry{0x041D, "CYRILLIC CAPITAL LETTER EN", "H"},
    Entry{0x041E, "CYRILLIC CAPITAL LETTER O", "O"},
    Entry{0x0420, "CYRILLIC CAPITAL LETTER ER", "P"},
    Entry{0x0421, "CYRILLIC CAPITAL LETTER ES", "C"},
    Entry{0x0422, "CYRILLIC CAPITAL LETTER TE", "T"},
    Entry{0x0425, "CYRILLIC CAPITAL LETTER HA", "X"},
    Entry{0x0430, "CYRILLIC SMALL LETTER A", "a"},
    Entry{0x0435, "CYRILLIC SMALL LETTER IE", "e"},
    Entry{0x043E, "CYRILLIC SMALL LETTER O", "o"},
    Entry{0x0440, "CYRILLIC SMALL LETTER ER", "p"},
    Entry{0x0441, "CYRILLIC SMALL LETTER ES", "c"},
    Entry{0x0445, "CYRILLIC SMALL LETTER HA", "x"},
};

std::optional<std::uint32_t> decode(std::string_view text) {
  if (text.empty()) return std::nullopt;
  const auto byte = [&](std::size_t i) { return static_cast<std::uint32_t>(static_cast<unsigned char>(text[i])); };
  const std::uint32_t lead = byte(0);
  if (lead < 0x80) return lead;
  const std::size_t length = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 0;
  if (length == 0 || text.size() != length) return std::nullopt;
  std::uint32_t value = lead & (0x7FU >> length);
  for (std::size_t i = 1; i < length; ++i) value = (value << 6) | (byte(i) & 0x3FU);
  return value;
}

// The full-width forms U+FF01…U+FF5E of ASCII '!'…'~' (digits, letters, '-', '.', ';', '(' …).
constexpr std::uint32_t kFullWidthFirst = 0xFF01;
constexpr std::uint32_t kFullWidthLast = 0xFF5E;
constexpr std::uint32_t kFullWidthToAscii = 0xFF01 - 0x21;

const std::string_view kAsciiPrintable =
    "!\"#$%&'()*+,-./0123456789:;<=>?@ABCDEFGHIJKLMNOPQRSTUVWXYZ[\\]^_`abcdefghijklmnopqrstuvwxyz{|}~";

}  // namespace

std::optional<LookAlike> lookAlikeOf(std::string_view codePoint) {
  const auto value = decode(codePoint);
  if (!value) return std::nullopt;
  if (*value >= kFullWidthFirst && *value <= kFullWidthLast) {
    const std::size_t ascii = *value - kFullWidthToAscii - 0x21;
    const char c = kAsciiPrintable[ascii];
    const std::string_view kind = (c >= '0' && c <= '9')   ? "FULLWIDTH DIGIT"
                                  : (c >= 'A' && c <= 'Z') ? "FULLWIDTH LATIN CAPITAL LETTER"
                                  : (c >= 'a' && c <= 'z') ? "FULLWIDTH LATIN SMALL LETTER"
                                                           : "FULLWIDTH PUNCTUATION";
    return LookAlike{kind, kAsciiPrintable.substr(ascii, 1)};
  }
  for (const Entry& entry : kTable)
    if (entry.codePoint == *value) return LookAlike{entry.name, entry.meant};
  return std::nullopt;
}

std::string codePointLabel(std::string_view codePoint) {
  const auto value = decode(codePoint);
  return value ? fmt::format("U+{:04X}", *value) : std::string("an invalid UTF-8 byte");
}

}  // namespace lathesim::interp
