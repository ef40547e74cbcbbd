#include "interp/text/expression_parser.hpp"

#include <array>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "interp/base/utf8.hpp"

namespace lathesim::interp::macro {
namespace {

struct NamedFunction {
  std::string_view name;
  Function function;
};

constexpr std::array kFunctions{
    NamedFunction{"SIN", Function::Sin},     NamedFunction{"COS", Function::Cos},
    NamedFunction{"TAN", Function::Tan},     NamedFunction{"ASIN", Function::Asin},
    NamedFunction{"ACOS", Function::Acos},   NamedFunction{"ATAN", Function::Atan},
    NamedFunction{"SQRT", Function::Sqrt},   NamedFunction{"ABS", Function::Abs},
    NamedFunction{"ROUND", Function::Round}, NamedFunction{"FIX", Function::Fix},
    NamedFunction{"FUP", Function::Fup},     NamedFunction{"LN", Function::Ln},
    NamedFunction{"EXP", Function::Exp},     NamedFunction{"POW", Function::Pow},
};

// Fanuc functions that exchange data with the PMC or the control's number formats; they have
// no meaning for a simulated part.
constexpr std::array<std::string_view, 3> kUnsupportedFunctions{"BIN", "BCD", "ADP"};

struct NamedComparison {
  std::string_view name;
  Comparison comparison;
};

constexpr std::array kComparisons{
    NamedComparison{"EQ", Comparison::Eq}, NamedComparison{"NE", Comparison::Ne},
    NamedComparison{"GT", Comparison::Gt}, NamedComparison{"GE", Comparison::Ge},
    NamedComparison{"LT", Comparison::Lt}, NamedComparison{"LE", Comparison::Le},
};

std::optional<BinaryOp> additiveOp(const Token& token) {
  if (token.kind == TokenKind::Plus) return BinaryOp::Add;
  if (token.kind == TokenKind::Minus) return BinaryOp::Subtract;
  if (token.kind == TokenKind::Name && token.text == "OR") return BinaryOp::Or;
  if (token.kind == TokenKind::Name && token.text == "XOR") return BinaryOp::Xor;
  return std::nullopt;
}

std::optional<BinaryOp> multiplicativeOp(const Token& token) {
  if (token.kind == TokenKind::Times) return BinaryOp::Multiply;
  if (token.kind == TokenKind::Divide) return BinaryOp::Divide;
  if (token.kind == TokenKind::Name && token.text == "AND") return BinaryOp::And;
  if (token.kind == TokenKind::Name && token.text == "MOD") return BinaryOp::Mod;
  return std::nullopt;
}

// Counts one more operation of the block; fails past kMaxOperations.
Status countOperation(TokenCursor& cursor, int column) {
  if (++cursor.operations <= kMaxOperations) return success();
  return Error{cursor.line(), column,
               fmt::format("this block holds more than {} operations; split the calculation over several "
                           "blocks",
                           kMaxOperations)};
}

Expression node(Expression::Kind kind, int column, std::vector<Expression> operands = {}) {
  Expression e;
  e.kind = kind;
  e.column = column;
  e.operands = std::move(operands);
  return e;
}

Result<Expression> parsePrimary(TokenCursor& cursor);

// '[' expr ']' — also a function's argument list when `allowComma` (POW[a,b], ATAN[a,b]).
Result<std::vector<Expression>> parseBracketed(TokenCursor& cursor, bool allowComma, std::string_view owner) {
  if (!cursor.nextIs(TokenKind::Open)) {
    return cursor.errorHere(fmt::format("{} needs its argument in brackets, e.g. {}[30]", owner, owner));
  }
  const int open = cursor.take().column;
  if (++cursor.bracketDepth > kMaxBracketDepth) {
    return Error{cursor.line(), open,
                 fmt::format("brackets nest more than {} deep here: a Fanuc control allows {} levels, a "
                             "function's brackets included (alarm 118)",
                             kMaxBracketDepth, kMaxBracketDepth)};
  }
  std::vector<Expression> items;
  for (;;) {
    auto item = parseExpression(cursor);
    if (!item.ok()) return item.error();
    items.push_back(std::move(item).value());
    if (!(allowComma && cursor.nextIs(TokenKind::Comma))) break;
    cursor.take();
  }
  if (!cursor.nextIs(TokenKind::Close)) {
    return cursor.errorHere(fmt::format("expected ']' to close the '[' at column {}{}", open,
                                        cursor.atEnd() ? "" : fmt::format(", found {}", describe(*cursor.peek()))));
  }
  cursor.take();
  --cursor.bracketDepth;
  return items;
}

Result<Expression> parseCall(TokenCursor& cursor, const Token& name, Function function) {
  const bool twoArguments = function == Function::Pow || function == Function::Atan;
  auto arguments = parseBracketed(cursor, twoArguments, name.text);
  if (!arguments.ok()) return arguments.error();
  std::vector<Expression> operands = std::move(arguments).value();
  // ATAN[a]/[b]: the two-argument arctangent, Fanuc's classic form.
  if (function == Function::Atan && operands.size() == 1 && cursor.nextIs(TokenKind::Divide) &&
      cursor.peek(1) != nullptr && cursor.peek(1)->kind == TokenKind::Open) {
    cursor.take();
    auto denominator = parseBracketed(cursor, false, "ATAN[…]/");
    if (!denominator.ok()) return denominator.error();
    operands.push_back(std::move(denominator.value().front()));
  }
  const std::size_t expected = function == Function::Pow ? 2 : 1;
  if (operands.size() != expected && !(function == Function::Atan && operands.size() == 2)) {
    return Error{cursor.line(), name.column,
                 function == Function::Pow
                     ? std::string("POW takes two arguments: POW[base,exponent]")
                     : fmt::format("{} takes one argument, got {}", name.text, operands.size())};
  }
  Expression call = node(Expression::Kind::Call, name.column, std::move(operands));
  call.function = function;
  call.text = name.text;
  return call;
}

Result<Expression> parsePrimary(TokenCursor& cursor) {
  if (cursor.atEnd()) {
    return cursor.errorHere("expected a value at the end of the block: a number, #variable, [expression] or a "
                            "function such as SIN[30]");
  }
  const Token& token = *cursor.peek();
  switch (token.kind) {
    case TokenKind::Number: {
      cursor.take();
      Expression number = node(Expression::Kind::Number, token.column);
      number.number = token.value;
      number.text = token.text;
      return number;
    }
    case TokenKind::Hash: return parseVariable(cursor);
    case TokenKind::Open: {
      auto inner = parseBracketed(cursor, false, "");
      if (!inner.ok()) return inner.error();
      return std::move(inner.value().front());
    }
    case TokenKind::Minus:
    case TokenKind::Plus: {
      cursor.take();
      if (auto counted = countOperation(cursor, token.column); !counted.ok()) return counted.error();
      auto operand = parsePrimary(cursor);
      if (!operand.ok()) return operand.error();
      if (token.kind == TokenKind::Plus) return operand;
      return node(Expression::Kind::Negate, token.column, {std::move(operand).value()});
    }
    case TokenKind::Name: {
      for (const NamedFunction& f : kFunctions) {
        if (f.name == token.text) {
          cursor.take();
          if (auto counted = countOperation(cursor, token.column); !counted.ok()) return counted.error();
          return parseCall(cursor, token, f.function);
        }
      }
      for (std::string_view name : kUnsupportedFunctions) {
        if (name == token.text) {
          return Error{cursor.line(), token.column,
                       fmt::format("{} converts data for the machine's PMC or its number format; lathesim "
                                   "does not read it",
                                   name)};
        }
      }
      break;
    }
    default: break;
  }
  return Error{cursor.line(), token.column,
               fmt::format("unexpected {}: expected a value, a number, #variable, [expression] or a function "
                           "such as SIN[30]",
                           describe(token))};
}

// One precedence level: operands joined left to right by the operators `levelOp` accepts
// (Fanuc evaluates [1-2-3] as [[1-2]-3]).
using OperandParser = Result<Expression> (*)(TokenCursor&);
using OperatorAtLevel = std::optional<BinaryOp> (*)(const Token&);

Result<Expression> parseLeftAssociative(TokenCursor& cursor, OperandParser parseOperand, OperatorAtLevel levelOp) {
  auto left = parseOperand(cursor);
  if (!left.ok()) return left;
  Expression result = std::move(left).value();
  while (!cursor.atEnd()) {
    const auto op = levelOp(*cursor.peek());
    if (!op) break;
    const Token& token = cursor.take();
    if (auto counted = countOperation(cursor, token.column); !counted.ok()) return counted.error();
    auto right = parseOperand(cursor);
    if (!right.ok()) return right;
    Expression binary = node(Expression::Kind::Binary, token.column, {std::move(result), std::move(right).value()});
    binary.op = *op;
    binary.text = token.text;
    result = std::move(binary);
  }
  return result;
}

Result<Expression> parseTerm(TokenCursor& cursor) { return parseLeftAssociative(cursor, parsePrimary, multiplicativeOp); }

}  // namespace

std::string describe(const Token& token) {
  if (codePointCount(token.text) == 1 && token.kind != TokenKind::Number) return fmt::format("character '{}'", token.text);
  return fmt::format("'{}'", token.text);
}

Result<Expression> parseVariable(TokenCursor& cursor) {
  const Token& hash = cursor.take();
  if (auto counted = countOperation(cursor, hash.column); !counted.ok()) return counted.error();
  if (cursor.nextIs(TokenKind::Hash)) {
    return cursor.errorHere("a variable numbered by a variable is written #[#…] on a Fanuc control, e.g. #[#1], "
                            "not ##1");
  }
  if (!cursor.nextIs(TokenKind::Number) && !cursor.nextIs(TokenKind::Open)) {
    return Error{cursor.line(), hash.column,
                 "# needs a variable number after it: #1, #100, or #[expression]"};
  }
  auto index = parsePrimary(cursor);
  if (!index.ok()) return index;
  return node(Expression::Kind::Variable, hash.column, {std::move(index).value()});
}

Result<Expression> parseAddressValue(TokenCursor& cursor) { return parsePrimary(cursor); }

Result<Expression> parseExpression(TokenCursor& cursor) {
  return parseLeftAssociative(cursor, parseTerm, additiveOp);
}

Result<Condition> parseCondition(TokenCursor& cursor) {
  if (!cursor.nextIs(TokenKind::Open)) {
    return cursor.errorHere("expected a condition in brackets, e.g. [#1 LT 10]");
  }
  const int open = cursor.take().column;
  ++cursor.bracketDepth;
  auto left = parseExpression(cursor);
  if (!left.ok()) return left.error();
  Condition condition;
  condition.left = std::move(left).value();
  std::optional<NamedComparison> found;
  if (cursor.nextIs(TokenKind::Name)) {
    for (const NamedComparison& c : kComparisons)
      if (c.name == cursor.peek()->text) found = c;
  }
  if (!found) {
    return cursor.errorHere(fmt::format("expected a comparison (EQ NE GT GE LT LE) in the condition opened at "
                                        "column {}{}",
                                        open, cursor.atEnd() ? "" : fmt::format(", found {}", describe(*cursor.peek()))));
  }
  condition.op = found->comparison;
  condition.column = cursor.take().column;
  auto right = parseExpression(cursor);
  if (!right.ok()) return right.error();
  condition.right = std::move(right).value();
  if (!cursor.nextIs(TokenKind::Close)) {
    return cursor.errorHere(fmt::format("expected ']' to close the condition opened at column {}{}", open,
                                        cursor.atEnd() ? "" : fmt::format(", found {}", describe(*cursor.peek()))));
  }
  cursor.take();
  --cursor.bracketDepth;
  return condition;
}

}  // namespace lathesim::interp::macro
