#pragma once
// A block of Fanuc Custom Macro B as read: either a macro statement, or NC words some of
// whose values are expressions (X#1, Z[#2-3]) or which call a macro (G65). The statements
// (Fanuc 0i/16i "Custom macro: branch and repetition"):
//   #i = expr                  assignment (#3000 = n raises alarm n, #3006 = n stops; the
//                              block's comment is their message)
//   GOTO n                     jump to N n of the same program; n may be an expression
//   IF [cond] GOTO n           jump when the condition holds
//   IF [cond] THEN #i = expr   assign when it holds
//   WHILE [cond] DO m          repeat up to END m while the condition holds (m 1–3)
//   DO m                       without WHILE: repeat forever (Fanuc: an infinite loop)
//   END m
// A statement takes its block alone but for an N number: lathesim found no Fanuc manual that
// lets a statement share a block with NC words, and refuses the mix rather than guess.

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "interp/text/expression.hpp"
#include "interp/text/lexer.hpp"

namespace lathesim::interp::macro {

struct Assignment {
  Expression variable;  // a Variable node: #1, #[#2]
  Expression value;
  int column = 0;  // of the '#'
};

struct Jump {  // GOTO n
  Expression target;
  int column = 0;  // of GOTO
};

struct IfStatement {
  Condition condition;
  std::variant<Jump, Assignment> then;
  int column = 0;  // of IF
};

/// WHILE [cond] DO m, or DO m alone (no condition: it always repeats).
struct LoopStart {
  std::optional<Condition> condition;
  int loopNumber = 0;
  int column = 0;        // of WHILE, or of DO when alone
  int numberColumn = 0;  // of m
};

struct LoopEnd {  // END m
  int loopNumber = 0;
  int column = 0;
  int numberColumn = 0;
};

using Statement = std::variant<Assignment, Jump, IfStatement, LoopStart, LoopEnd>;

/// An NC word of a macro block: a plain word (G65, P9010, A1.5), or a letter whose value an
/// expression gives (X#1: word.letter and word.column set, the value not yet known).
struct MacroWord {
  Word word;
  std::optional<Expression> expression;
};

struct MacroBlock {
  std::optional<Statement> statement;
  std::vector<MacroWord> words;  // the NC words; for a statement, only its N number if any
  std::string message;           // the block's first comment: the message of #3000 and #3006
};

/// Loop numbers of DO and END: 1 to 3 (Fanuc alarm 126 otherwise).
constexpr int kMaxLoopNumber = 3;

}  // namespace lathesim::interp::macro
