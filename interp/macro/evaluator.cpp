#include "interp/macro/evaluator.hpp"

#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "interp/macro/functions.hpp"

namespace lathesim::interp::macro {
namespace {

constexpr double kMaxVariableNumber = 99999;

// An Error from functions.cpp, which knows no place, put at the operation.
Error located(const Error& error, const EvaluationContext& context, int column) {
  return Error{context.line, column, error.message};
}

}  // namespace

Result<int> variableNumber(const Expression& variable, const EvaluationContext& context) {
  const Expression& index = variable.operands.front();
  auto value = evaluate(index, context);
  if (!value.ok()) return value.error();
  if (!value.value()) {
    return Error{context.line, variable.column,
                 "the variable number #[…] is vacant: a variable numbered by an expression needs a value"};
  }
  // A real number where a whole one is meant is rounded (Fanuc rounds variable numbers).
  const double number = std::round(*value.value());
  if (number < 0 || number > kMaxVariableNumber) {
    return Error{context.line, variable.column, fmt::format("#{:g} is not a variable number", *value.value())};
  }
  return static_cast<int>(number);
}

Result<Value> evaluate(const Expression& expression, const EvaluationContext& context) {
  switch (expression.kind) {
    case Expression::Kind::Number: return Value{expression.number};
    case Expression::Kind::Variable: {
      auto number = variableNumber(expression, context);
      if (!number.ok()) return number.error();
      return context.variables.read(number.value(), context.line, expression.column);
    }
    case Expression::Kind::Negate: {
      auto operand = evaluate(expression.operands.front(), context);
      if (!operand.ok() || !operand.value()) return operand;  // -<vacant> stays vacant
      return Value{-*operand.value()};
    }
    case Expression::Kind::Binary: {
      auto a = evaluate(expression.operands[0], context);
      if (!a.ok()) return a;
      auto b = evaluate(expression.operands[1], context);
      if (!b.ok()) return b;
      auto result = applyBinary(expression.op, a.value().value_or(0.0), b.value().value_or(0.0));
      if (!result.ok()) return located(result.error(), context, expression.column);
      return Value{result.value()};
    }
    case Expression::Kind::Call: {
      std::vector<double> arguments;
      for (const Expression& operand : expression.operands) {
        auto value = evaluate(operand, context);
        if (!value.ok()) return value;
        arguments.push_back(value.value().value_or(0.0));
      }
      auto result = applyFunction(expression.function, arguments, context.addressIncrement);
      if (!result.ok()) return located(result.error(), context, expression.column);
      return Value{result.value()};
    }
  }
  return Error{context.line, expression.column, "unknown expression"};
}

Result<bool> evaluate(const Condition& condition, const EvaluationContext& context) {
  auto left = evaluate(condition.left, context);
  if (!left.ok()) return left.error();
  auto right = evaluate(condition.right, context);
  if (!right.ok()) return right.error();
  const Value& a = left.value();
  const Value& b = right.value();
  switch (condition.op) {
    case Comparison::Eq: return a == b;  // <vacant> equals only <vacant>
    case Comparison::Ne: return a != b;
    default: break;
  }
  const double x = a.value_or(0.0);
  const double y = b.value_or(0.0);
  switch (condition.op) {
    case Comparison::Gt: return x > y;
    case Comparison::Ge: return x >= y;
    case Comparison::Lt: return x < y;
    case Comparison::Le: return x <= y;
    default: return false;
  }
}

}  // namespace lathesim::interp::macro
