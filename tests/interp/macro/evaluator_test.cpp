// The expression evaluator against values worked out by hand: Fanuc's precedence, the
// functions in degrees, ROUND/FIX/FUP on negative numbers, the <vacant> rules, and the
// errors (division by zero, a bad argument, brackets nested too deep), each located.

#include "interp/macro/evaluator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <string_view>

#include "interp/text/expression_parser.hpp"
#include "interp/text/lexer.hpp"

namespace lathesim::interp::macro {
namespace {

// `text` (ASCII) as the characters of a block on line 1, spaces dropped, each at its column.
// Built here rather than by BlockReader, which reads a line opening with '[' as a trainer's
// directive: an expression alone on a line is no program block.
RawBlock blockOf(std::string_view text) {
  RawBlock block;
  block.line = 1;
  block.column = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != ' ') block.chars.push_back({std::string(1, text[i]), static_cast<int>(i) + 1});
  }
  return block;
}

// `text` is one expression (or, with a comparison, one bracketed condition) written on line 1.
Result<Value> evaluateText(std::string_view text, const VariableStore& variables = VariableStore()) {
  const RawBlock raw = blockOf(text);
  auto tokens = lexBlock(raw);
  if (!tokens.ok()) return tokens.error();
  TokenCursor cursor(tokens.value(), raw.line, raw.chars.back().column + 1);
  auto expression = parseExpression(cursor);
  if (!expression.ok()) return expression.error();
  EXPECT_TRUE(cursor.atEnd()) << text;
  return evaluate(expression.value(), {variables, raw.line, std::nullopt});
}

double valueOf(std::string_view text, const VariableStore& variables = VariableStore()) {
  auto value = evaluateText(text, variables);
  EXPECT_TRUE(value.ok()) << text << ": " << (value.ok() ? "" : value.error().message);
  EXPECT_TRUE(value.ok() && value.value()) << text << " is vacant";
  return value.ok() && value.value() ? *value.value() : std::nan("");
}

Error errorOf(std::string_view text, const VariableStore& variables = VariableStore()) {
  auto value = evaluateText(text, variables);
  EXPECT_FALSE(value.ok()) << text;
  return value.ok() ? Error{} : value.error();
}

Result<bool> conditionOf(std::string_view text, const VariableStore& variables) {
  const RawBlock raw = blockOf(text);
  auto tokens = lexBlock(raw);
  EXPECT_TRUE(tokens.ok());
  TokenCursor cursor(tokens.value(), raw.line, raw.chars.back().column + 1);
  auto condition = parseCondition(cursor);
  if (!condition.ok()) return condition.error();
  return evaluate(condition.value(), {variables, raw.line, std::nullopt});
}

bool holds(std::string_view text, const VariableStore& variables) {
  auto result = conditionOf(text, variables);
  EXPECT_TRUE(result.ok()) << text << ": " << (result.ok() ? "" : result.error().message);
  return result.ok() && result.value();
}

constexpr double kTrig = 1e-12;  // the degree functions go through radians

TEST(MacroPrecedence, MultiplicationGroupBeforeAdditionGroup) {
  EXPECT_DOUBLE_EQ(valueOf("1+2*3"), 7.0);
  EXPECT_DOUBLE_EQ(valueOf("[1+2]*3"), 9.0);
  EXPECT_DOUBLE_EQ(valueOf("10-4-3"), 3.0);  // left to right: [10-4]-3
  EXPECT_DOUBLE_EQ(valueOf("8/4/2"), 1.0);   // [8/4]/2
  EXPECT_DOUBLE_EQ(valueOf("2*3MOD4"), 2.0);  // one level, left to right: [2*3] MOD 4
  EXPECT_DOUBLE_EQ(valueOf("1 OR 2 AND 3"), 3.0);  // AND first: 2 AND 3 = 2, 1 OR 2 = 3
  EXPECT_DOUBLE_EQ(valueOf("5 XOR 1 + 1"), 5.0);   // one level: [5 XOR 1] + 1 = 4 + 1
  EXPECT_DOUBLE_EQ(valueOf("-2*3"), -6.0);
  EXPECT_DOUBLE_EQ(valueOf("2+SQRT[16]*2"), 10.0);  // the function first, then *, then +
  EXPECT_DOUBLE_EQ(valueOf("2 - -3"), 5.0);
  EXPECT_DOUBLE_EQ(valueOf("7/2"), 3.5);  // real division
}

TEST(MacroPrecedence, ModBindsLikeTimesAndDivide) {
  // Custom Macro B: MOD is an operator of the * / AND level, applied left to right with them.
  // Each line has another value if MOD is moved to the level of + (or above *).
  EXPECT_DOUBLE_EQ(valueOf("2 + 7 MOD 4"), 5.0);   // 2 + [7 MOD 4]; at + 's level [2+7] MOD 4 = 1
  EXPECT_DOUBLE_EQ(valueOf("10 - 7 MOD 4"), 7.0);  // 10 - 3; at + 's level 3 MOD 4 = 3
  EXPECT_DOUBLE_EQ(valueOf("7 MOD 4 * 3"), 9.0);   // [7 MOD 4] * 3; at + 's level 7 MOD 12 = 7
  EXPECT_DOUBLE_EQ(valueOf("3 * 7 MOD 4"), 1.0);   // [3*7] MOD 4; above *, 3 * [7 MOD 4] = 9
  EXPECT_DOUBLE_EQ(valueOf("20 / 4 MOD 3"), 2.0);  // [20/4] MOD 3
}

TEST(MacroFunctions, TrigonometryInDegrees) {
  EXPECT_NEAR(valueOf("SIN[30]"), 0.5, kTrig);
  EXPECT_NEAR(valueOf("COS[60]"), 0.5, kTrig);
  EXPECT_NEAR(valueOf("TAN[45]"), 1.0, kTrig);
  EXPECT_NEAR(valueOf("SIN[-390]"), -0.5, kTrig);  // -390° is -30°
  EXPECT_EQ(valueOf("COS[90]"), 0.0);              // exactly: TAN[90] has no value
  EXPECT_EQ(valueOf("SIN[180]"), 0.0);
  EXPECT_EQ(valueOf("COS[-180]"), -1.0);
  EXPECT_NEAR(valueOf("ASIN[0.5]"), 30.0, kTrig);
  EXPECT_NEAR(valueOf("ASIN[-0.5]"), 330.0, kTrig);  // NAT = 0: 270°–90°
  EXPECT_NEAR(valueOf("ACOS[-1]"), 180.0, kTrig);
  EXPECT_NEAR(valueOf("ACOS[0.5]"), 60.0, kTrig);
  EXPECT_NEAR(valueOf("ATAN[1]/[1]"), 45.0, kTrig);
  EXPECT_NEAR(valueOf("ATAN[1]/[-1]"), 135.0, kTrig);
  EXPECT_NEAR(valueOf("ATAN[-1]/[-1]"), 225.0, kTrig);  // 0°–360°
  EXPECT_NEAR(valueOf("ATAN[-1]/[1]"), 315.0, kTrig);
  EXPECT_NEAR(valueOf("ATAN[0]/[-5]"), 180.0, kTrig);
  EXPECT_NEAR(valueOf("ATAN[-2]/[0]"), 270.0, kTrig);
  EXPECT_NEAR(valueOf("ATAN[1,SQRT[3]]"), 30.0, kTrig);
  EXPECT_NEAR(valueOf("ATAN[1]"), 45.0, kTrig);
  EXPECT_NEAR(valueOf("ATAN[-1]"), 315.0, kTrig);
}

TEST(MacroFunctions, RoundFixFupOnNegativeNumbers) {
  EXPECT_EQ(valueOf("ROUND[1.5]"), 2.0);
  EXPECT_EQ(valueOf("ROUND[-1.5]"), -2.0);  // half away from zero
  EXPECT_EQ(valueOf("ROUND[-1.4]"), -1.0);
  EXPECT_EQ(valueOf("FIX[1.8]"), 1.0);
  EXPECT_EQ(valueOf("FIX[-1.2]"), -1.0);  // toward zero (Fanuc: FIX[-1.2] = -1.0)
  EXPECT_EQ(valueOf("FIX[-2]"), -2.0);
  EXPECT_EQ(valueOf("FUP[1.2]"), 2.0);
  EXPECT_EQ(valueOf("FUP[-1.2]"), -2.0);  // away from zero (Fanuc: FUP[-1.2] = -2.0)
  EXPECT_EQ(valueOf("FUP[2]"), 2.0);
}

TEST(MacroFunctions, OthersByHand) {
  EXPECT_DOUBLE_EQ(valueOf("SQRT[16]"), 4.0);
  EXPECT_DOUBLE_EQ(valueOf("ABS[-3.5]"), 3.5);
  EXPECT_NEAR(valueOf("LN[EXP[2]]"), 2.0, 1e-15);
  EXPECT_DOUBLE_EQ(valueOf("POW[2,10]"), 1024.0);
  EXPECT_DOUBLE_EQ(valueOf("POW[-2,3]"), -8.0);
  EXPECT_DOUBLE_EQ(valueOf("27 MOD 20"), 7.0);
  EXPECT_DOUBLE_EQ(valueOf("-7 MOD 3"), -1.0);  // the dividend's sign
  EXPECT_DOUBLE_EQ(valueOf("5 AND 3"), 1.0);    // 101 & 011
  EXPECT_DOUBLE_EQ(valueOf("5 OR 3"), 7.0);
  EXPECT_DOUBLE_EQ(valueOf("5 XOR 3"), 6.0);
}

TEST(MacroFunctions, BadArgumentsAreLocatedErrors) {
  Error e = errorOf("1+TAN[90]");
  EXPECT_EQ(e.column, 3);
  EXPECT_NE(e.message.find("TAN[90] is infinite"), std::string::npos) << e.message;
  e = errorOf("2*ASIN[1.5]");
  EXPECT_EQ(e.column, 3);
  EXPECT_NE(e.message.find("-1 to 1"), std::string::npos) << e.message;
  EXPECT_NE(errorOf("SQRT[-4]").message.find("square root of a negative number"), std::string::npos);
  EXPECT_NE(errorOf("LN[0]").message.find("≤ 0"), std::string::npos);
  EXPECT_NE(errorOf("ATAN[0]/[0]").message.find("both sides are 0"), std::string::npos);
  EXPECT_NE(errorOf("POW[-2,0.5]").message.find("whole exponent"), std::string::npos);
  EXPECT_NE(errorOf("7.5 MOD 2").message.find("whole numbers"), std::string::npos);
  EXPECT_NE(errorOf("-1 AND 1").message.find("whole numbers ≥ 0"), std::string::npos);
  EXPECT_NE(errorOf("EXP[200]").message.find("out of the range"), std::string::npos);  // e^200 ≈ 7e86
}

TEST(MacroFunctions, DivisionByZeroIsAnErrorAtTheOperator) {
  Error e = errorOf("1+4/[2-2]");
  EXPECT_EQ(e.line, 1);
  EXPECT_EQ(e.column, 4);
  EXPECT_NE(e.message.find("division by zero"), std::string::npos) << e.message;
  e = errorOf("5 MOD 0");
  EXPECT_EQ(e.column, 3);
  EXPECT_NE(e.message.find("division by zero"), std::string::npos);
}

TEST(MacroVacant, ArithmeticTakesVacantAsZeroButCopiesKeepIt) {
  const VariableStore variables;  // every variable vacant
  EXPECT_FALSE(evaluateText("#1", variables).value());
  EXPECT_FALSE(evaluateText("[#1]", variables).value());
  EXPECT_FALSE(evaluateText("-#1", variables).value());
  EXPECT_FALSE(evaluateText("#0", variables).value());
  EXPECT_EQ(valueOf("#1+#1", variables), 0.0);
  EXPECT_EQ(valueOf("#1*5", variables), 0.0);
  EXPECT_EQ(valueOf("#1+3", variables), 3.0);
  EXPECT_EQ(valueOf("COS[#1]", variables), 1.0);  // COS[0]
}

TEST(MacroVacant, EqAndNeTellVacantFromZeroTheOthersDoNot) {
  VariableStore variables;
  // #1 vacant, #2 = 0 (Fanuc's table of conditional expressions with <vacant>).
  ASSERT_TRUE(variables.write(2, 0.0, 1, 1).ok());
  EXPECT_TRUE(holds("[#1 EQ #0]", variables));
  EXPECT_FALSE(holds("[#2 EQ #0]", variables));
  EXPECT_FALSE(holds("[#1 EQ 0]", variables));
  EXPECT_TRUE(holds("[#1 NE 0]", variables));
  EXPECT_FALSE(holds("[#2 NE 0]", variables));
  EXPECT_TRUE(holds("[#1 GE #0]", variables));
  EXPECT_TRUE(holds("[#2 GE #0]", variables));
  EXPECT_FALSE(holds("[#1 GT 0]", variables));
  EXPECT_FALSE(holds("[#2 GT 0]", variables));
  EXPECT_TRUE(holds("[#1 LE #0]", variables));
  EXPECT_FALSE(holds("[#1 LT 0]", variables));
  EXPECT_TRUE(holds("[#1 LT 1]", variables));
}

TEST(MacroVariables, NumbersAndLevels) {
  VariableStore variables({{500, 12.5}, {100, -1.0}, {7, 3.0}});  // #7 is local: not set
  EXPECT_EQ(valueOf("#500", variables), 12.5);
  EXPECT_EQ(valueOf("#[99+1]", variables), -1.0);  // a variable numbered by an expression
  EXPECT_EQ(valueOf("#[499.6]", variables), 12.5);  // rounded to #500
  EXPECT_FALSE(evaluateText("#7", variables).value());
  ASSERT_TRUE(variables.write(1, 5.0, 1, 1).ok());
  LocalVariables arguments{};
  arguments[0] = 9.0;
  variables.pushLevel(arguments);
  EXPECT_EQ(variables.level(), 1);
  EXPECT_EQ(valueOf("#1", variables), 9.0);
  EXPECT_EQ(valueOf("#500", variables), 12.5);  // common variables are shared
  variables.popLevel();
  EXPECT_EQ(valueOf("#1", variables), 5.0);
}

TEST(MacroVariables, NoSuchVariableIsALocatedError) {
  const VariableStore variables;
  Error e = errorOf("1+#34", variables);
  EXPECT_EQ(e.column, 3);
  EXPECT_NE(e.message.find("#34 is not a variable"), std::string::npos) << e.message;
  EXPECT_NE(errorOf("#5001", variables).message.find("system variable"), std::string::npos);
  EXPECT_NE(errorOf("#[#1]", variables).message.find("vacant"), std::string::npos);
  VariableStore writable;
  EXPECT_NE(writable.write(0, 1.0, 1, 1).error().message.find("#0 is always vacant"), std::string::npos);
}

TEST(MacroSyntax, BracketsNestFiveDeep) {
  EXPECT_EQ(valueOf("[[[[[1+1]]]]]"), 2.0);
  EXPECT_EQ(valueOf("SIN[[[[[90]]]]]"), 1.0);  // the function's brackets count: five
  Error e = errorOf("[[[[[[1]]]]]]");
  EXPECT_EQ(e.column, 6);
  EXPECT_NE(e.message.find("allows 5 levels"), std::string::npos) << e.message;
  e = errorOf("ABS[[[[[[2]]]]]]");
  EXPECT_EQ(e.column, 9);
}

TEST(MacroSyntax, AnExpressionTooLongForAnyControlIsAnErrorNotACrash) {
  // Long chains of signs or terms would nest the evaluation deeper than the stack allows.
  EXPECT_EQ(valueOf(std::string(400, '-') + "1"), 1.0);  // an even number of minus signs
  EXPECT_NE(errorOf(std::string(100000, '-') + "1").message.find("more than 500 operations"), std::string::npos);
  std::string sum = "1";
  for (int i = 0; i < 100000; ++i) sum += "+1";
  const Error e = errorOf(sum);
  EXPECT_EQ(e.column, 1002);  // the 501st '+'
  EXPECT_NE(e.message.find("more than 500 operations"), std::string::npos);
}

TEST(MacroSyntax, MalformedExpressionsSayWhatWasExpected) {
  EXPECT_NE(errorOf("[1+2").message.find("expected ']'"), std::string::npos);
  EXPECT_NE(errorOf("SIN30").message.find("SIN needs its argument in brackets"), std::string::npos);
  EXPECT_NE(errorOf("##1").message.find("#[#1]"), std::string::npos);
  EXPECT_NE(errorOf("1+").message.find("expected a value"), std::string::npos);
  EXPECT_NE(errorOf("BIN[3]").message.find("PMC"), std::string::npos);
  EXPECT_NE(errorOf("POW[2]").message.find("two arguments"), std::string::npos);
}

}  // namespace
}  // namespace lathesim::interp::macro
