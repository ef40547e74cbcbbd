#include "interp/base/printable_text.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace lathesim::interp {
namespace {

TEST(PrintableText, KeepsTextTabsNewlinesAndUtf8) {
  EXPECT_EQ(printable("G00 X20\tZ2\n(粗车 Ø40 – ok)"), "G00 X20\tZ2\n(粗车 Ø40 – ok)");
  EXPECT_EQ(printable(""), "");
}

// Every C0 code but tab and newline, DEL, and every C1 code: none reaches the terminal raw.
TEST(PrintableText, WritesOutEveryControlCode) {
  for (int c = 0; c < 0x20; ++c) {
    if (c == '\t' || c == '\n') continue;
    char expected[8];
    std::snprintf(expected, sizeof expected, "\\x%02x", c);
    EXPECT_EQ(printable(std::string(1, static_cast<char>(c))), expected) << c;
  }
  EXPECT_EQ(printable("\x7f"), "\\x7f");
  for (int c = 0x80; c <= 0x9F; ++c) {
    const std::string encoded{static_cast<char>(0xC2), static_cast<char>(c)};
    char expected[8];
    std::snprintf(expected, sizeof expected, "\\u%04x", c);
    EXPECT_EQ(printable(encoded), expected) << c;
  }
  EXPECT_EQ(printable("\xc2\xa0"), "\xc2\xa0");  // U+00A0, a no-break space: printable
}

// U+202E would show "G00 X20" as "02X 00G": the bidirectional controls are written out.
TEST(PrintableText, WritesOutBidirectionalControls) {
  EXPECT_EQ(printable("a\u202Eb\u2066c\u2069"), "a\\u202eb\\u2066c\\u2069");
  EXPECT_EQ(printable("\u2029\u206A"), "\u2029\u206A");  // their neighbours are not
}

// Bytes that are not well-formed UTF-8 are written out one by one; what follows them is read
// afresh.
TEST(PrintableText, WritesOutBytesThatAreNotUtf8) {
  EXPECT_EQ(printable("\xff"), "\\xff");
  EXPECT_EQ(printable("a\x80z"), "a\\x80z");                     // a lone continuation byte
  EXPECT_EQ(printable("\xe7\xb2"), "\\xe7\\xb2");                // cut short at the end
  EXPECT_EQ(printable("\xe7\xb2X"), "\\xe7\\xb2X");              // cut short by a letter
  EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf");                // overlong '/'
  EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80");       // a surrogate
  EXPECT_EQ(printable("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // beyond U+10FFFF
  EXPECT_EQ(printable("\xf0\x9f\x94\xa7"), "\xf0\x9f\x94\xa7");  // U+1F527, four bytes, fine
}

}  // namespace
}  // namespace lathesim::interp
