// M98/M99 in one file: calls, repeat counts (P digits and L), nesting, recursion, and the
// errors. Positions are (radius, Z); the tool starts at X200 Z200 = (100, 200).

#include <gtest/gtest.h>

#include <fmt/format.h>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;
using test::expectMoves;
using test::kFeed;
using test::kRapid;
using test::run;

// The subprogram feeds U-2 (radius −1) each time it runs.
constexpr std::string_view kSubprogram =
    "O1000\n"           // line 4
    "G01 U-2 F0.1\n"    // 5
    "M99\n";            // 6

std::string withMain(std::string_view callBlock) {
  return "G00 X50 Z2\n" + std::string(callBlock) + "\nM30\n" + std::string(kSubprogram);
}

TEST(Subprogram, RepeatCountInFrontOfTheProgramNumber) {
  // P31000: three runs of O1000, radius 25 → 24 → 23 → 22, then M30.
  const auto result = run(withMain("M98 P31000"));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 25, 2, 0, 0},
                                      {kFeed, 25, 2, 24, 2, 0.1, 0},
                                      {kFeed, 24, 2, 23, 2, 0.1, 0},
                                      {kFeed, 23, 2, 22, 2, 0.1, 0}});
  // A move made by the subprogram carries the subprogram block's line.
  for (std::size_t i = 1; i < 4; ++i) EXPECT_EQ(result.toolpath.moves[i].line, 5);
}

TEST(Subprogram, FourDigitsOrFewerCallOnce) {
  const auto result = run(withMain("M98 P1000"));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves,
              {{kRapid, 100, 200, 25, 2, 0, 0}, {kFeed, 25, 2, 24, 2, 0.1, 0}});
}

TEST(Subprogram, RepeatCountAsL) {
  const auto result = run(withMain("M98 P1000 L2"));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 25, 2, 0, 0},
                                      {kFeed, 25, 2, 24, 2, 0.1, 0},
                                      {kFeed, 24, 2, 23, 2, 0.1, 0}});
}

TEST(Subprogram, ExecutionGoesOnAfterTheCall) {
  // Line 2 calls O1000, line 3 moves in Z from where the subprogram left the tool.
  const auto result = run("G00 X50 Z2\nM98 P1000\nG00 Z5\nM30\n" + std::string(kSubprogram));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 25, 2, 0, 0},
                                      {kFeed, 25, 2, 24, 2, 0.1, 0},
                                      {kRapid, 24, 2, 24, 5, 0, 0}});
  EXPECT_EQ(result.toolpath.moves[2].line, 3);
}

// Main → O1 → O2 → O3 → O4 is four levels; each level feeds U-2 before calling the next.
std::string nested(int levels) {
  std::string text = "G00 X50 Z2 F0.1\nM98 P1\nM30\n";
  for (int level = 1; level <= levels; ++level) {
    text += fmt::format("O{}\nG01 U-2\n", level);
    if (level < levels) text += fmt::format("M98 P{}\n", level + 1);
    text += "M99\n";
  }
  return text;
}

TEST(Subprogram, FourLevelsNest) {
  const auto result = run(nested(4));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 25, 2, 0, 0},
                                      {kFeed, 25, 2, 24, 2, 0.1, 0},
                                      {kFeed, 24, 2, 23, 2, 0.1, 0},
                                      {kFeed, 23, 2, 22, 2, 0.1, 0},
                                      {kFeed, 22, 2, 21, 2, 0.1, 0}});
}

TEST(Subprogram, FifthLevelIsAnError) {
  // Lines: 1–3 main, O1 4–7, O2 8–11, O3 12–15, O4 16–19 (its M98 P5 on line 18).
  expectError(run(nested(5)), 18, 5,
              "M98 calls O0005 from 4 levels of subprograms (O0001 → O0002 → O0003 → O0004 → "
              "O0005): the control nests at most 4 levels");
}

TEST(Subprogram, DirectRecursionIsAnErrorNamingTheChain) {
  expectError(run("M98 P1000\nM30\nO1000\nM98 P1000\nM99\n"), 4, 5,
              "M98 calls O1000 while it is already running (O1000 → O1000)");
}

TEST(Subprogram, IndirectRecursionIsAnErrorNamingTheChain) {
  expectError(run("M98 P1000\nM30\nO1000\nM98 P2000\nM99\nO2000\nM98 P1000\nM99\n"), 7, 5,
              "(O1000 → O2000 → O1000)");
}

TEST(Subprogram, MainProgramCallingItselfIsRecursion) {
  expectError(run("O0001\nM98 P1\nM30\n"), 2, 5, "(O0001 → O0001)");
}

TEST(Subprogram, UnknownProgramIsAnError) {
  expectError(run(withMain("M98 P1234")), 2, 5, "M98 calls O1234 but the program has no block O1234");
}

TEST(Subprogram, M99EndingTheMainProgramRunsItOnceWithAWarning) {
  // The control would start the program over, forever: simulated once, and said.
  const auto result = run("G00 X50\nM99\nG00 X60\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 25, 200, 0, 0}});
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].line, 2);
  EXPECT_EQ(result.diagnostics[0].message,
            "M99 ends the main program: the control runs it again from the start, forever; lathesim simulates it once");
}

TEST(Subprogram, TextEndingInsideASubprogramIsAnError) {
  expectError(run("M98 P1000\nM30\nO1000\nG00 X10\n"), 1, 5,
              "O1000 called here has no M99: the program text ends inside it");
}

TEST(Subprogram, M98NeedsP) { expectError(run("M98 L2\n"), 1, 1, "M98 needs P"); }

TEST(Subprogram, CountGivenTwiceIsAnError) {
  expectError(run(withMain("M98 P21000 L2")), 2, 12, "P21000 and L2 both give the repeat count");
}

TEST(Subprogram, ZeroRepeatCountIsAnError) {
  expectError(run(withMain("M98 P01000")), 2, 5,
              "P01000: the digits before the four-digit program number are the repeat count, "
              "expected 1 to 9999");
}

TEST(Subprogram, LMustBeAWholeCount) {
  expectError(run(withMain("M98 P1000 L0")), 2, 11, "L0 is not a repeat count");
}

TEST(Subprogram, ProgramNumberWithADecimalPointIsAnError) {
  expectError(run(withMain("M98 P1000.")), 2, 5, "P1000. is not a program number");
}

TEST(Subprogram, M99PReturnsToThatSequenceOfTheCaller) {
  // O1000 feeds U-2 and returns to N20, skipping N10's G00 X80: then N20's G00 Z10.
  const auto result = run("G00 X50 Z2\nM98 P1000\nN10 G00 X80\nN20 G00 Z10\nM30\nO1000\nG01 U-2 F0.1\nM99 P20\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 25, 2, 0, 0},
                                      {kFeed, 25, 2, 24, 2, 0.1, 0},
                                      {kRapid, 24, 2, 24, 10, 0, 0}});
  // After the last of several runs only; a number the caller lacks is an error at P.
  const auto twice = run("G00 X50 Z2\nM98 P21000\nN10 G00 X80\nN20 G00 Z10\nM30\nO1000\nG01 U-2 F0.1\nM99 P20\n");
  ASSERT_TRUE(twice.ok());
  EXPECT_EQ(twice.toolpath.moves.back().to, RZ(23, 10));
  expectError(run("M98 P1000\nM30\nO1000\nM99 P10\n"), 4, 5,
              "M99 P10 returns to N10 of the calling program, which has no block N10");
}

}  // namespace
}  // namespace lathesim::interp
