#pragma once
// Tokens → expressions, with Fanuc's precedence (Fanuc 0i/16i "Custom macro: arithmetic and
// logic operation"): functions first, then * / AND MOD, then + - OR XOR, left to right;
// [ ] change the order and nest at most five deep, a function's own brackets included
// (alarm 118 beyond). A comparison (EQ NE GT GE LT LE) appears only as the bracketed
// condition of IF and WHILE.
//   primary := number | #primary | [expr] | FUNC[expr] | ATAN[expr]/[expr] | ATAN[expr,expr]
//              | POW[expr,expr] | -primary | +primary
// ##1 is not Fanuc's: a variable numbered by a variable is written #[#1].

#include <cstddef>
#include <string_view>
#include <vector>

#include "interp/text/expression.hpp"
#include "interp/base/result.hpp"
#include "interp/text/lexer.hpp"

namespace lathesim::interp::macro {

/// Fanuc allows brackets five deep, counting a function's.
constexpr int kMaxBracketDepth = 5;
/// Operations (signs, operators, functions, variables) one block may hold: far beyond any
/// program a control runs, and a bound on how deep an expression's tree can grow.
constexpr int kMaxOperations = 500;

/// The tokens of one block, read front to back.
class TokenCursor {
 public:
  /// `endColumn`: the column just past the block, where "expected …" points at the end.
  TokenCursor(const std::vector<Token>& tokens, int line, int endColumn)
      : tokens_(tokens), line_(line), endColumn_(endColumn) {}

  bool atEnd() const { return at_ >= tokens_.size(); }
  /// The token `ahead` places on, or nullptr past the end.
  const Token* peek(std::size_t ahead = 0) const {
    return at_ + ahead < tokens_.size() ? &tokens_[at_ + ahead] : nullptr;
  }
  bool nextIs(TokenKind kind) const { return peek() != nullptr && peek()->kind == kind; }
  bool nextIsName(std::string_view name) const { return nextIs(TokenKind::Name) && peek()->text == name; }
  const Token& take() { return tokens_[at_++]; }
  int line() const { return line_; }
  /// The column of the next token, or the end of the block.
  int column() const { return atEnd() ? endColumn_ : peek()->column; }
  Error errorHere(std::string message) const { return Error{line_, column(), std::move(message)}; }

  int bracketDepth = 0;  // '[' open around the token being read
  int operations = 0;    // read so far in the block (kMaxOperations)

 private:
  const std::vector<Token>& tokens_;
  std::size_t at_ = 0;
  int line_;
  int endColumn_;
};

/// An arithmetic expression from the cursor on; stops before a token that cannot continue it.
Result<Expression> parseExpression(TokenCursor& cursor);

/// [left op right]: the bracketed condition of IF and WHILE, brackets included.
Result<Condition> parseCondition(TokenCursor& cursor);

/// '#' then its number: #1, #[#2+1]. The cursor stands on the '#'.
Result<Expression> parseVariable(TokenCursor& cursor);

/// The value an NC address takes from the macro, after its letter: #1, -#1, #[…], […], -[…].
Result<Expression> parseAddressValue(TokenCursor& cursor);

/// How a token is named in a message: "character '#'" or "'SIN'".
std::string describe(const Token& token);

}  // namespace lathesim::interp::macro
