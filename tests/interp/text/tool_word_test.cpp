// T words by the control's forms (control parameter tool_word).

#include "interp/text/tool_word.hpp"

#include <gtest/gtest.h>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;

InterpretResult runWithForms(std::string_view program, std::vector<std::string> forms) {
  InterpreterOptions options = test::defaultOptions();
  options.control.toolWordForms = std::move(forms);
  return interpret(program, "t.nc", options);
}

using test::toolsOf;

TEST(ToolWord, TwoPlusTwoReadsTheLastTwoDigitsAsTheOffset) {
  // T0202: tool 2, offset 2. T101: tool 1, offset 1 (the leading zero left out). T0 and T00:
  // offset 0, the tool in place stays.
  const auto result = runWithForms("T0202 G00 X90\nT101 X80\nT0202 X70\nT0 X60\nT00 X50\n", {"2+2"});
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  EXPECT_EQ(toolsOf(result), (std::vector<std::pair<int, int>>{{2, 2}, {1, 1}, {2, 2}, {2, 0}, {2, 0}}));
  EXPECT_TRUE(result.diagnostics.empty());
}

TEST(ToolWord, AOneOrTwoDigitWordIsAnOffsetOfTheToolInPlaceWithAWarning) {
  const auto result = runWithForms("T0202 G00 X90\nT1 X80\n", {"2+2"});
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(toolsOf(result), (std::vector<std::pair<int, int>>{{2, 2}, {2, 1}}));
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].line, 2);
  EXPECT_EQ(result.diagnostics[0].message,
            "T1 is read as offset 1 of the tool in place (no tool change): the last 2 digits of a T word are the "
            "offset; write T0101 for tool and offset");
}

TEST(ToolWord, AWordThatFitsNoFormIsAnErrorNeverAnotherTool) {
  // T01001 would be tool 10 offset 01 to a control that ignored its digit count.
  expectError(runWithForms("T01001\n", {"2+2"}), 1, 1,
              "T01001 is not a tool word of this control: expected 2 digits of tool and 2 of offset (T0101)");
  expectError(runWithForms("T01.01\n", {"2+2"}), 1, 1, "T01.01 is not a tool word of this control");
  expectError(runWithForms("T-101\n", {"2+2", "3+3"}), 1, 1,
              "expected 2 digits of tool and 2 of offset (T0101), or 3 digits of tool and 3 of offset (T001001)");
}

TEST(ToolWord, ThreePlusThreeReadsTheLastThreeDigitsAsTheOffset) {
  const auto result = runWithForms("T002001 G00 X90\nT001 X80\n", {"3+3"});
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  EXPECT_EQ(toolsOf(result), (std::vector<std::pair<int, int>>{{2, 1}, {2, 1}}));
  // With both forms, the first that holds the digits reads the word.
  const auto both = runWithForms("T0201 G00 X90\nT001002 X80\n", {"2+2", "3+3"});
  ASSERT_TRUE(both.ok()) << both.diagnostics[0].message;
  EXPECT_EQ(toolsOf(both), (std::vector<std::pair<int, int>>{{2, 1}, {1, 2}}));
}

}  // namespace
}  // namespace lathesim::interp
