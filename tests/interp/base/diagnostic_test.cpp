#include "interp/base/diagnostic.hpp"

#include <gtest/gtest.h>

namespace lathesim::interp {
namespace {

TEST(Diagnostic, FormatShowsLocationMessageLineAndCaret) {
  const Diagnostic d{Severity::Error, "bad.nc", 3, 10, "something is wrong",
                     "G94 X108 Z-30 R-10 F1;"};
  EXPECT_EQ(format(d),
            "bad.nc:3:10: error: something is wrong\n"
            "G94 X108 Z-30 R-10 F1;\n"
            "         ^");
}

TEST(Diagnostic, CaretCountsCodePointsNotBytes) {
  // "(粗车)" is 4 code points but 8 bytes; X is column 6.
  const Diagnostic d{Severity::Error, "a.nc", 1, 6, "m", "(粗车) X20.3."};
  EXPECT_EQ(format(d), "a.nc:1:6: error: m\n(粗车) X20.3.\n     ^");
}

TEST(Diagnostic, WarningAndWholeFileForms) {
  EXPECT_EQ(format({Severity::Warning, "a.nc", 2, 1, "w", "M30"}),
            "a.nc:2:1: warning: w\nM30\n^");
  EXPECT_EQ(format({Severity::Error, "a.nc", 0, 0, "cannot read", ""}),
            "a.nc: error: cannot read");
}

// A line holding ESC (and a C1 CSI) is shown with them written out; the caret stays under
// the character its column names, however wide the escapes before it.
TEST(Diagnostic, ControlCharactersAreWrittenOutAndTheCaretFollows) {
  const Diagnostic d{Severity::Error, "t\x1b.nc", 1, 11, "bad \x07 here", "\x1b[2J X1\xc2\x9b" "5 @"};
  EXPECT_EQ(format(d),
            "t\\x1b.nc:1:11: error: bad \\x07 here\n"
            "\\x1b[2J X1\\u009b5 @\n" +
                std::string(18, ' ') + "^");
  // A column past the end of the line still counts its own spaces.
  EXPECT_EQ(format({Severity::Error, "a.nc", 1, 5, "m", "\tX"}), "a.nc:1:5: error: m\n\tX\n    ^");
}

TEST(Diagnostic, LineOfStripsLineEndings) {
  const std::string_view text = "first\r\nsecond\nthird";
  EXPECT_EQ(lineOf(text, 1), "first");
  EXPECT_EQ(lineOf(text, 2), "second");
  EXPECT_EQ(lineOf(text, 3), "third");
  EXPECT_EQ(lineOf(text, 4), "");
  EXPECT_EQ(lineOf(text, 0), "");
}

// The lines found once (LineStarts: a warning on every block of a long program made the
// quoting quadratic, 40 000 blocks in 8 s, now 1.6 s) are the lines lineOf finds.
TEST(Diagnostic, LineStartsQuoteTheSameLinesAsLineOf) {
  for (const std::string_view text : {"first\r\nsecond\nthird", "", "\n\n", "a\nb\n"}) {
    const LineStarts lines(text);
    for (int line = -1; line <= 5; ++line) EXPECT_EQ(lines.lineOf(text, line), lineOf(text, line)) << line;
  }
}

// Lines quoted in one pass, for diagnostics in any order, two on one line, some at lines the
// text lacks, are the lines lineOf finds.
TEST(Diagnostic, QuotedInOnePassAsLineOfQuotes) {
  for (const std::string_view text : {"first\r\nsecond\nthird", "", "\n\n", "a\nb\n"}) {
    std::vector<Diagnostic> diagnostics;
    for (const int line : {5, 2, -1, 3, 2, 0, 1, 4}) diagnostics.push_back({Severity::Warning, "f", line, 1, "m", "stale"});
    std::vector<Diagnostic*> quoting;
    for (Diagnostic& d : diagnostics) quoting.push_back(&d);
    quoteLines(text, quoting);
    for (const Diagnostic& d : diagnostics) EXPECT_EQ(d.sourceLine, lineOf(text, d.line)) << d.line;
  }
}

}  // namespace
}  // namespace lathesim::interp
