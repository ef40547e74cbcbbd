#pragma once
// Evaluates expressions and conditions against the variables, with Fanuc's rules for
// <vacant> (Fanuc 0i/16i "Undefined variable", the same in the Mitsubishi and Haas manuals):
//   #2 = #1        copies <vacant>
//   #1 + 5, #1 * 5, SIN[#1] …   an operation takes <vacant> as 0 and gives a number
//   -#1, [#1]      a sign or brackets leave <vacant> as it is (so X-#1 is left out like X#1;
//                  not checked in a manual)
//   EQ, NE         <vacant> differs from 0: [#1 EQ #0] holds when #1 is vacant, [#1 EQ 0] not
//   GT GE LT LE    <vacant> counts as 0
// A variable numbered by an expression (#[#1+2]) needs a value, rounded to a whole number.

#include <optional>

#include "interp/text/expression.hpp"
#include "interp/macro/variables.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp::macro {

struct EvaluationContext {
  const VariableStore& variables;
  int line = 0;
  /// Set when the expression gives an NC address its value: ROUND then rounds to this, the
  /// address's least input increment (1 for a whole-number address such as S or M).
  std::optional<double> addressIncrement;
};

Result<Value> evaluate(const Expression& expression, const EvaluationContext& context);

Result<bool> evaluate(const Condition& condition, const EvaluationContext& context);

/// The number of the variable a Variable node names (#1 → 1, #[#2] → the value of #2).
Result<int> variableNumber(const Expression& variable, const EvaluationContext& context);

}  // namespace lathesim::interp::macro
