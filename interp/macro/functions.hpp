#pragma once
// The arithmetic of Fanuc Custom Macro B on numbers (a <vacant> operand has already become 0,
// see macro/evaluator.hpp). Angles are in degrees. A call that has no answer fails with the
// reason, which the evaluator locates at the operation.
// Rules (Fanuc 0i/16i custom macro tables; where a rule could not be checked in a manual it
// says so):
//   SIN COS TAN   exact at multiples of 90° (COS[90] is 0, so TAN[90] fails rather than
//                 giving 1.6e16)
//   ASIN ACOS     argument in [-1, 1] (alarm 119 beyond). With parameter NAT (6004#0) at
//                 its default 0: ASIN gives 270°–90° (a negative angle as +360°), ACOS 180°–0°
//   ATAN[a]/[b]   (and ATAN[a,b]) 0°–360° under NAT = 0; ATAN[0]/[0] fails
//   ATAN[a]       one argument (30i/0i-F): the same 270°–90° convention as ASIN (not checked
//                 in a manual)
//   SQRT LN       SQRT of a negative number and LN of a number ≤ 0 fail (alarm 119)
//   ROUND         half away from zero; in an NC address, to the address's least input
//                 increment instead (Fanuc and Haas manuals: G00 X[ROUND[#1]+ROUND[#2]])
//   FIX FUP       toward zero and away from zero: FIX[-1.2] = -1, FUP[-1.2] = -2
//   POW[a,b]      30i/0i-F; a negative base needs a whole exponent, 0 a positive one
//   AND OR XOR    bit by bit on whole numbers; lathesim refuses negative or fractional operands
//                 rather than guess how the control rounds them (not checked in a manual)
//   MOD           30i/0i-F remainder; lathesim takes whole operands only, and the result has
//                 the sign of the dividend as in C (not checked in a manual)
//   /, MOD by 0   fail (alarm 112)
//   every result  within ±1e47 (alarm 111 beyond)

#include <optional>
#include <vector>

#include "interp/text/expression.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp::macro {

/// The largest magnitude a variable holds (Fanuc: ±1e47, alarm 111 beyond).
constexpr double kMaxMagnitude = 1e47;

/// `function` of `arguments` (one, or two for ATAN[a]/[b] and POW). `addressIncrement`: set
/// when the call stands in an NC address, where ROUND rounds to that increment. The Error,
/// if any, carries only a message.
Result<double> applyFunction(Function function, const std::vector<double>& arguments,
                             std::optional<double> addressIncrement);

/// `a op b`. The Error, if any, carries only a message.
Result<double> applyBinary(BinaryOp op, double a, double b);

/// Rounds half away from zero to a multiple of `increment` (1 for a whole number).
double roundToIncrement(double value, double increment);

}  // namespace lathesim::interp::macro
