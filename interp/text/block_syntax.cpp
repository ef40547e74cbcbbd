#include "interp/text/block_syntax.hpp"

#include <cmath>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "interp/text/expression_parser.hpp"
#include "interp/text/typing_slips.hpp"

namespace lathesim::interp::macro {
namespace {

constexpr int kMacroCallCode = 65;

bool startsStatement(const TokenCursor& cursor) {
  return cursor.nextIs(TokenKind::Hash) || cursor.nextIsName("IF") || cursor.nextIsName("GOTO") ||
         cursor.nextIsName("WHILE") || cursor.nextIsName("DO") || cursor.nextIsName("END");
}

// m of DO m and END m: a plain whole number 1–3.
Result<int> loopNumber(TokenCursor& cursor, std::string_view keyword) {
  if (!cursor.nextIs(TokenKind::Number)) {
    return cursor.errorHere(fmt::format("{} needs its loop number: 1, 2 or 3 (e.g. {}1)", keyword, keyword));
  }
  const Token& number = cursor.take();
  if (number.value != std::floor(number.value) || number.value < 1 || number.value > kMaxLoopNumber) {
    return Error{cursor.line(), number.column,
                 fmt::format("{}{}: loop numbers are 1, 2 and 3 (alarm 126)", keyword, number.text)};
  }
  return static_cast<int>(number.value);
}

Result<Assignment> readAssignment(TokenCursor& cursor) {
  const int column = cursor.column();
  auto variable = parseVariable(cursor);
  if (!variable.ok()) return variable.error();
  if (!cursor.nextIs(TokenKind::Equals)) {
    return cursor.errorHere("expected '=' and a value after the variable (#1 = 5); to use a variable as a "
                            "word's value, write it after the letter (X#1)");
  }
  cursor.take();
  auto value = parseExpression(cursor);
  if (!value.ok()) return value.error();
  return Assignment{std::move(variable).value(), std::move(value).value(), column};
}

Result<Jump> readJump(TokenCursor& cursor) {
  const int column = cursor.take().column;  // GOTO
  auto target = parseExpression(cursor);
  if (!target.ok()) return target.error();
  return Jump{std::move(target).value(), column};
}

Result<Statement> readStatement(TokenCursor& cursor) {
  if (cursor.nextIs(TokenKind::Hash)) {
    auto assignment = readAssignment(cursor);
    if (!assignment.ok()) return assignment.error();
    return Statement{std::move(assignment).value()};
  }
  if (cursor.nextIsName("GOTO")) {
    auto jump = readJump(cursor);
    if (!jump.ok()) return jump.error();
    return Statement{std::move(jump).value()};
  }
  if (cursor.nextIsName("IF")) {
    const int column = cursor.take().column;
    auto condition = parseCondition(cursor);
    if (!condition.ok()) return condition.error();
    IfStatement statement{std::move(condition).value(), Jump{}, column};
    if (cursor.nextIsName("GOTO")) {
      auto jump = readJump(cursor);
      if (!jump.ok()) return jump.error();
      statement.then = std::move(jump).value();
    } else if (cursor.nextIsName("THEN")) {
      cursor.take();
      if (!cursor.nextIs(TokenKind::Hash)) {
        return cursor.errorHere("THEN takes an assignment, e.g. IF [#1 GT 5] THEN #1 = 5");
      }
      auto assignment = readAssignment(cursor);
      if (!assignment.ok()) return assignment.error();
      statement.then = std::move(assignment).value();
    } else {
      return cursor.errorHere("expected GOTO n or THEN #i = … after the condition of IF");
    }
    return Statement{std::move(statement)};
  }
  LoopStart loop;
  loop.column = cursor.column();
  if (cursor.nextIsName("WHILE")) {
    cursor.take();
    auto condition = parseCondition(cursor);
    if (!condition.ok()) return condition.error();
    loop.condition = std::move(condition).value();
    if (!cursor.nextIsName("DO")) return cursor.errorHere("expected DO and a loop number after WHILE's condition");
  }
  if (cursor.nextIsName("DO")) {
    cursor.take();
    loop.numberColumn = cursor.column();
    auto number = loopNumber(cursor, "DO");
    if (!number.ok()) return number.error();
    loop.loopNumber = number.value();
    return Statement{std::move(loop)};
  }
  LoopEnd end;  // END m
  end.column = cursor.take().column;
  end.numberColumn = cursor.column();
  auto number = loopNumber(cursor, "END");
  if (!number.ok()) return number.error();
  end.loopNumber = number.value();
  return Statement{end};
}

Error mixedBlock(const TokenCursor& cursor, bool statementFirst) {
  return cursor.errorHere(
      statementFirst
          ? fmt::format("{} after a macro statement: a statement takes its block alone (but for N); put it in a "
                        "block of its own",
                        describe(*cursor.peek()))
          : std::string("a macro statement after NC words: a statement takes its block alone (but for N); put it "
                        "in a block of its own"));
}

// The NC words of the block from the cursor on.
Status readWords(TokenCursor& cursor, MacroBlock& block) {
  while (!cursor.atEnd()) {
    const Token& token = *cursor.peek();
    if (token.kind == TokenKind::Word) {
      block.words.push_back({cursor.take().word, std::nullopt});
      continue;
    }
    if (token.kind == TokenKind::Address) {
      cursor.take();
      if (token.word.letter == 'N' || token.word.letter == 'O') {
        return Error{cursor.line(), token.column,
                     fmt::format("{} takes no variable or expression: write its number plainly (a Fanuc control "
                                 "allows none in O and N)",
                                 token.word.letter)};
      }
      auto value = parseAddressValue(cursor);
      if (!value.ok()) return value.error();
      if (!cursor.atEnd() && cursor.peek()->kind != TokenKind::Word && cursor.peek()->kind != TokenKind::Address &&
          !startsStatement(cursor)) {
        return cursor.errorHere(fmt::format("{} after {}'s value: an expression in an address is written in "
                                            "brackets, e.g. {}[#1+2]",
                                            describe(*cursor.peek()), token.text, token.text));
      }
      block.words.push_back({token.word, std::move(value).value()});
      continue;
    }
    if (startsStatement(cursor)) return mixedBlock(cursor, false);
    if (token.kind == TokenKind::Open || token.kind == TokenKind::Close)
      return strayBracket(cursor.line(), token.text, token.column);
    return cursor.errorHere(fmt::format("unexpected {}: expected a word, a letter followed by a number such as X20",
                                        describe(token)));
  }
  return success();
}

}  // namespace

bool needsMacroReader(const std::vector<Token>& tokens) {
  for (const Token& token : tokens) {
    if (token.kind != TokenKind::Word) return true;
    if (token.word.letter == 'G' && token.word.value == kMacroCallCode) return true;
  }
  return false;
}

Result<MacroBlock> readMacroBlock(const std::vector<Token>& tokens, const RawBlock& raw) {
  const int endColumn = raw.chars.empty() ? raw.column : raw.chars.back().column + 1;
  TokenCursor cursor(tokens, raw.line, endColumn);
  if (!tokens.empty() && tokens.front().kind == TokenKind::Number)
    if (auto slip = zeroForLetterO(raw.line, tokens.front().text, tokens.front().column)) return *slip;
  MacroBlock block;
  if (!raw.comments.empty()) block.message = raw.comments.front();
  // A statement may follow the block's N number.
  while (cursor.nextIs(TokenKind::Word) && cursor.peek()->word.letter == 'N') block.words.push_back({cursor.take().word, {}});
  if (startsStatement(cursor)) {
    auto statement = readStatement(cursor);
    if (!statement.ok()) return statement.error();
    block.statement = std::move(statement).value();
    if (!cursor.atEnd()) return mixedBlock(cursor, true);
    return block;
  }
  if (auto status = readWords(cursor, block); !status.ok()) return status.error();
  return block;
}

}  // namespace lathesim::interp::macro
