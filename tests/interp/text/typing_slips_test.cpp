// Typing slips: each refused at the column of the slip, with the text that was meant. Each is
// swept over where in the block it stands (first word, middle, last) and over the words before
// it, since the column and the hint must follow the slip, not the block's start.

#include "interp/text/typing_slips.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;
using test::run;

// The same slip placed after `before` and before `after` on line 2 of a program: the error is
// at line 2, at the column where the slip starts plus `offset`.
struct Placement {
  std::string before;
  std::string after;
};

const std::vector<Placement> kPlacements{{"", ""}, {"G00 ", " Z2"}, {"N20 G00 X40 ", ""}, {"X40  ", " F0.1"}};

int columnOf(const Placement& p) { return static_cast<int>(p.before.size()) + 1; }

TEST(TypingSlips, LetterOForZeroInsideANumber) {
  // Q2OO is Q200; X1O.5 is X10.5; the O's may be lower case.
  struct Case {
    std::string slip;
    int offset;  // of the first O within the slip
    std::string meant;
  };
  for (const Case& c : {Case{"Q2OO", 2, "Q200"}, Case{"X1O.5", 2, "X10.5"}, Case{"Z-2oo", 3, "Z-200"},
                        Case{"U1O0O", 2, "U1000"}}) {
    for (const Placement& p : kPlacements) {
      const std::string program = "G00 X50 Z5\n" + p.before + c.slip + p.after + "\n";
      SCOPED_TRACE(program);
      expectError(run(program), 2, columnOf(p) + c.offset, "did you mean the digit 0 (" + c.meant + ")?");
    }
  }
}

TEST(TypingSlips, LetterOForZeroRightAfterTheAddress) {
  for (const Placement& p : kPlacements) {
    const std::string program = "G00 X50 Z5\n" + p.before + "GO1" + p.after + "\n";
    SCOPED_TRACE(program);
    expectError(run(program), 2, columnOf(p) + 1,
                "the letter 'O' right after G, where a number belongs; did you mean the digit 0 (G01)?");
  }
}

TEST(TypingSlips, LetterOForZeroInAProgramNumber) {
  expectError(run("O1OOO\nG00 X50 Z5\n"), 1, 3, "the letter 'O' inside the number O1; did you mean the digit 0 (O1000)?");
  expectError(run("o1OoO\nG00 X50 Z5\n"), 1, 3, "(O1000)?");
  // A lower-case o for the address is the letter O: o1000 is the program number O1000.
  const auto lower = run("o1000\nG00 X50 Z5\n");
  ASSERT_TRUE(lower.ok()) << test::messageOf(lower);
}

TEST(TypingSlips, ProseIsNotAZero) {
  // "co" in a prose tail after ';' is not a zero: the tail is a comment.
  EXPECT_TRUE(run("G00 X50 Z5 ;coolant on\n").ok());
}

TEST(TypingSlips, ZeroForTheLetterOOfAProgramNumber) {
  expectError(run("01000\nG00 X50 Z5\n"), 1, 1,
              "a block opens with the number 01000: a program number is the letter O, not the digit zero (did you "
              "mean O1000?)");
  expectError(run("G00 X50 Z5\n   00042\n"), 2, 4, "(did you mean O0042?)");
  // A number not opening with a zero is not this slip.
  const auto other = run("1000\n");
  ASSERT_FALSE(other.ok());
  EXPECT_EQ(other.diagnostics[0].message.find("did you mean"), std::string::npos) << other.diagnostics[0].message;
}

TEST(TypingSlips, PastedCitation) {
  for (const Placement& p : kPlacements) {
    const std::string program = "G00 X50 Z5\n" + p.before + "[cite: 133]" + p.after + "\n";
    SCOPED_TRACE(program);
    expectError(run(program), 2, columnOf(p), "'[cite:133]' is a citation pasted with the program");
  }
  expectError(run("G00 X50 Z5 [CITE_START]\n"), 1, 12, "'[CITE_START]' is a citation");
}

TEST(TypingSlips, StrayBracket) {
  for (const std::string bracket : {"]", "["}) {
    for (const Placement& p : {Placement{"G00 X50 ", ""}, Placement{"G00 X50 Z5 ", " M08"}}) {
      const std::string program = p.before + bracket + p.after + "\n";
      SCOPED_TRACE(program);
      expectError(run(program), 1, columnOf(p), "stray '" + bracket + "': a bracket holds a Macro B expression");
    }
  }
  // A bracket inside an expression is not stray.
  EXPECT_TRUE(run("#1=20\nG00 X[#1+2] Z5\n").ok());
}

}  // namespace
}  // namespace lathesim::interp
