// The slips people make most, each answered in words that say what happened and what to
// write instead: an unclosed or nested comment, a stray character, a decimal point where a
// whole number is meant, a program that is only comments.

#include <gtest/gtest.h>

#include "interp/interpreter.hpp"
#include "test_support.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;
using test::run;

TEST(CommonSlips, UnclosedComment) {
  expectError(run("G00 X20 Z2\nG01 X18 (finish pass\nZ-10 F0.1)\n"), 2, 9,
              "comment opened here is not closed: expected ')' before the end of the line");
}

// Comments do not nest: the first ')' closes the comment, and the outer ')' is left over.
TEST(CommonSlips, NestedComment) {
  expectError(run("G00 X20 Z2 (rough (OD) pass)\nM30\n"), 1, 28,
              "')' closes no comment: comments do not nest, so the '(' at column 19 is text of the comment opened "
              "at column 12, which the ')' at column 22 closed");
  // An inner '(' with no ')' after the comment is harmless: the comment simply holds it.
  EXPECT_TRUE(run("G00 X20 Z2 (rough (OD pass)\nM30\n").ok());
}

TEST(CommonSlips, StrayCharacters) {
  expectError(run("G00 X20 Z2 @\n"), 1, 12, "unexpected character '@': expected a word");
  expectError(run("G01 X20 Z2 F0.1 )\n"), 1, 17, "')' closes no comment");
}

// A decimal point in a number that counts or names: what to write instead.
TEST(CommonSlips, DecimalPointWhereAWholeNumberIsMeant) {
  const std::string sub = "\nM30\nO1000\nG01 U-1 F0.1\nM99\n";
  expectError(run("G00 X20 Z2\nM98 P1000." + sub), 2, 5,
              "P1000. is not a program number: a decimal point where a whole number is meant; write P1000");
  expectError(run("G00 X20 Z2\nM98 P1000 L2.5" + sub), 2, 11,
              "L2.5 is not a repeat count: a decimal point where a whole number is meant; a count has no fraction");
  expectError(run("G00 X20 Z2\nM98 P1000 L3.0" + sub), 2, 11, "write L3");
  expectError(run("N10. G00 X20 Z2\n"), 1, 1, "N10. is not a sequence number: a decimal point where a whole number "
                                              "is meant; write N10");
  expectError(run("G00 X20 Z2\nG73 U1 W1 R2.5\n"), 2, 11,
              "G73 R2.5 is not a number of passes d: a decimal point where a whole number is meant");
}

// Found by the interpreter fuzz harness: ",A30." read as Fanuc's comma word indexed the G65
// argument table with a lower-case letter, past its end (undefined behaviour).
TEST(CommonSlips, CommaBetweenMacroArguments) {
  expectError(run("G65 P9010 D40, A30. B-20.\nM30\nO9010\nM99\n"), 1, 14,
              "',A30.' in a G65 block: a macro call's arguments are letters and numbers one after another, with no "
              "comma between them");
}

TEST(CommonSlips, ProgramOfOnlyCommentsOrNothing) {
  for (const char* text : {"(PART 1234)\n(OP 10)\n", "%\n(only a comment)\n%\n", "[BILLET X40 Z80\n(T1)\n"}) {
    const InterpretResult r = run(text);
    ASSERT_EQ(r.diagnostics.size(), 1u) << text;
    EXPECT_EQ(r.diagnostics[0].severity, Severity::Error);
    EXPECT_EQ(r.diagnostics[0].line, 0);
    EXPECT_NE(r.diagnostics[0].message.find("holds only comments"), std::string::npos) << r.diagnostics[0].message;
    EXPECT_EQ(format(r.diagnostics[0]).rfind("test.nc: error: the program holds only comments", 0), 0u);
  }
  for (const char* text : {"", "\n  \n\t\r\n"}) {
    const InterpretResult r = run(text);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.diagnostics[0].message, "the program is empty: there is no block to run");
  }
}

}  // namespace
}  // namespace lathesim::interp
