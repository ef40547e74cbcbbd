#pragma once
// A Fanuc Custom Macro B expression as read: numbers, variables, the four operations and the
// bitwise ones, functions, and the comparisons of IF and WHILE. Each node keeps the column it
// was written at, so an error while evaluating points at the operation at fault.
// Reading: text/expression_parser.hpp; evaluating: macro/evaluator.hpp.

#include <string>
#include <vector>

namespace lathesim::interp::macro {

/// Fanuc's two binary levels (functions bind tighter than both): * / AND MOD, then + - OR XOR.
enum class BinaryOp { Add, Subtract, Or, Xor, Multiply, Divide, And, Mod };

enum class Function { Sin, Cos, Tan, Asin, Acos, Atan, Sqrt, Abs, Round, Fix, Fup, Ln, Exp, Pow };

enum class Comparison { Eq, Ne, Gt, Ge, Lt, Le };

struct Expression {
  enum class Kind {
    Number,    // a constant: number
    Variable,  // #operands[0]: #1, #[#2+1]
    Negate,    // -operands[0]
    Binary,    // operands[0] op operands[1]
    Call,      // function(operands…): one argument, or two for ATAN[a]/[b], ATAN[a,b], POW[a,b]
  };
  Kind kind = Kind::Number;
  int column = 0;       // of the number, '#', '-', operator or function name
  double number = 0.0;  // Number
  std::string text;     // Number: as written; Call: the function's name; Binary: the operator
  BinaryOp op = BinaryOp::Add;
  Function function = Function::Sin;
  std::vector<Expression> operands;
};

/// [left op right], the condition of IF and WHILE.
struct Condition {
  Expression left;
  Comparison op = Comparison::Eq;
  Expression right;
  int column = 0;  // of the comparison's name
};

}  // namespace lathesim::interp::macro
