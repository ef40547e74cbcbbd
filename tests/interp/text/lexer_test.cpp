// Block splitting and tokenizing: the syntax rules of lathe-gcode.md "Blocks and words".

#include "interp/text/lexer.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace lathesim::interp {
namespace {

std::vector<RawBlock> readAll(std::string_view text) {
  BlockReader reader(text);
  std::vector<RawBlock> blocks;
  while (true) {
    auto next = reader.next();
    EXPECT_TRUE(next.ok()) << (next.ok() ? "" : next.error().message);
    if (!next.ok() || !next.value()) break;
    blocks.push_back(*next.value());
  }
  return blocks;
}

std::vector<Word> wordsOf(std::string_view text) {
  auto blocks = readAll(text);
  EXPECT_EQ(blocks.size(), 1u);
  if (blocks.size() != 1) return {};
  auto words = tokenize(blocks[0]);
  EXPECT_TRUE(words.ok()) << (words.ok() ? "" : words.error().message);
  return words.ok() ? words.value() : std::vector<Word>{};
}

Error tokenizeError(std::string_view text) {
  auto blocks = readAll(text);
  EXPECT_EQ(blocks.size(), 1u);
  auto words = tokenize(blocks.at(0));
  EXPECT_FALSE(words.ok());
  return words.ok() ? Error{} : words.error();
}

TEST(BlockReader, SemicolonAndNewlineBothEndABlock) {
  const auto blocks = readAll("G00 X42 Z0.5; G94 X25.5 Z-5 F100; Z-10;\nM30\n");
  ASSERT_EQ(blocks.size(), 4u);
  EXPECT_EQ(blocks[0].line, 1);
  EXPECT_EQ(blocks[0].column, 1);
  EXPECT_EQ(blocks[1].line, 1);
  EXPECT_EQ(blocks[1].column, 15);
  EXPECT_EQ(blocks[2].column, 35);
  EXPECT_EQ(blocks[3].line, 2);
  EXPECT_EQ(blocks[3].column, 1);
}

TEST(BlockReader, EmptyBlocksCommentsAndPercentLinesAreNotBlocks) {
  const auto blocks = readAll("%\n\n;;  ;\n(only a comment)\n  % trailing words\nO1234\n");
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].line, 6);
  ASSERT_EQ(blocks[0].chars.size(), 5u);
  EXPECT_EQ(blocks[0].chars[0].text, "O");
}

TEST(BlockReader, CommentMayHoldAnyUtf8AndSemicolons) {
  const auto blocks = readAll("(粗车端面; 外圆 Φ120) G00 (中) X10\n");
  ASSERT_EQ(blocks.size(), 1u);
  // '(' is column 1; the comment holds 15 code points including its parentheses, then a space.
  EXPECT_EQ(blocks[0].column, 17);
  auto words = tokenize(blocks[0]);
  ASSERT_TRUE(words.ok());
  ASSERT_EQ(words.value().size(), 2u);
  EXPECT_EQ(words.value()[1].text(), "X10");
  EXPECT_EQ(words.value()[1].column, 25);  // after "G00 (中) " = columns 17..24
}

TEST(BlockReader, SlashAtBlockStartMarksBlockDelete) {
  const auto blocks = readAll("/G00 X10\n  / G01 X5; G00 X3\n");
  ASSERT_EQ(blocks.size(), 3u);
  EXPECT_TRUE(blocks[0].deleted);
  EXPECT_EQ(blocks[0].column, 1);
  EXPECT_TRUE(blocks[1].deleted);
  EXPECT_EQ(blocks[1].column, 3);
  EXPECT_FALSE(blocks[2].deleted);
}

TEST(BlockReader, UnclosedCommentIsAnErrorAtItsParenthesis) {
  BlockReader reader("G00 X10\nG01 (中文 Z5 F0.1\n");
  ASSERT_TRUE(reader.next().ok());
  auto second = reader.next();
  ASSERT_FALSE(second.ok());
  EXPECT_EQ(second.error().line, 2);
  EXPECT_EQ(second.error().column, 5);
  EXPECT_NE(second.error().message.find("not closed"), std::string::npos);
}

TEST(Tokenize, SpacesInsideNumbersAreInsignificant) {
  const auto words = wordsOf("G94X20 .0 Z0.1 R-5 .5");
  ASSERT_EQ(words.size(), 4u);
  EXPECT_EQ(words[0].letter, 'G');
  EXPECT_DOUBLE_EQ(words[0].value, 94.0);
  EXPECT_EQ(words[1].text(), "X20.0");
  EXPECT_DOUBLE_EQ(words[1].value, 20.0);
  EXPECT_EQ(words[1].column, 4);
  EXPECT_DOUBLE_EQ(words[2].value, 0.1);
  EXPECT_EQ(words[3].text(), "R-5.5");
  EXPECT_DOUBLE_EQ(words[3].value, -5.5);
}

TEST(Tokenize, LowerCaseLettersAreUpperCased) {
  const auto words = wordsOf("g94 x30 z0 r-24 f0.1");
  ASSERT_EQ(words.size(), 5u);
  EXPECT_EQ(words[1].letter, 'X');
  EXPECT_DOUBLE_EQ(words[3].value, -24.0);
  EXPECT_EQ(words[4].letter, 'F');
}

TEST(Tokenize, NumbersWithoutDecimalPointAreMillimetres) {
  const auto words = wordsOf("X20 Z-.5 U+3. W0101");
  ASSERT_EQ(words.size(), 4u);
  EXPECT_DOUBLE_EQ(words[0].value, 20.0);
  EXPECT_DOUBLE_EQ(words[1].value, -0.5);
  EXPECT_DOUBLE_EQ(words[2].value, 3.0);
  EXPECT_DOUBLE_EQ(words[3].value, 101.0);
  EXPECT_EQ(words[3].number, "0101");
}

TEST(Tokenize, MalformedNumberIsAnErrorAtItsLetter) {
  const Error error = tokenizeError("G00 X20.3. Z5");
  EXPECT_EQ(error.column, 5);
  EXPECT_NE(error.message.find("malformed number in X20.3."), std::string::npos);
  EXPECT_EQ(tokenizeError("X5-3").column, 1);
}

TEST(Tokenize, LetterWithoutNumberIsAnError) {
  const Error error = tokenizeError("G00 X Z5");
  EXPECT_EQ(error.column, 5);
  EXPECT_NE(error.message.find("X has no number"), std::string::npos);
}

TEST(Tokenize, UnknownLetterIsAnError) {
  const Error error = tokenizeError("G00 X20 B5");
  EXPECT_EQ(error.column, 9);
  EXPECT_NE(error.message.find("unknown letter 'B'"), std::string::npos);
}

TEST(Tokenize, YSaysThereIsNoYAxis) {
  const Error error = tokenizeError("G01 Y5");
  EXPECT_EQ(error.column, 5);
  EXPECT_NE(error.message.find("no Y axis"), std::string::npos);
}

TEST(Tokenize, StrayCharacterIsAnError) {
  const Error error = tokenizeError("G00 X10 @ 5");
  EXPECT_EQ(error.column, 9);
  EXPECT_NE(error.message.find("unexpected character '@'"), std::string::npos);
}

std::vector<Token> tokensOf(std::string_view text) {
  auto blocks = readAll(text);
  EXPECT_EQ(blocks.size(), 1u);
  auto tokens = lexBlock(blocks.at(0));
  EXPECT_TRUE(tokens.ok()) << (tokens.ok() ? "" : tokens.error().message);
  return tokens.ok() ? tokens.value() : std::vector<Token>{};
}

TEST(LexBlock, MacroStatementTokensKeepTheirColumns) {
  //                                    1234567890123456789012
  const std::vector<Token> tokens = tokensOf("IF [#1 GT -1.5] GOTO 20");
  const std::vector<std::pair<TokenKind, int>> expected{
      {TokenKind::Name, 1},   {TokenKind::Open, 4},    {TokenKind::Hash, 5},   {TokenKind::Number, 6},
      {TokenKind::Name, 8},   {TokenKind::Minus, 11},  {TokenKind::Number, 12}, {TokenKind::Close, 15},
      {TokenKind::Name, 17},  {TokenKind::Number, 22}};
  ASSERT_EQ(tokens.size(), expected.size());
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(tokens[i].kind, expected[i].first);
    EXPECT_EQ(tokens[i].column, expected[i].second);
  }
  EXPECT_EQ(tokens[0].text, "IF");
  EXPECT_EQ(tokens[4].text, "GT");
  EXPECT_DOUBLE_EQ(tokens[6].value, 1.5);  // the sign is the Minus before it
  EXPECT_EQ(tokens[8].text, "GOTO");
}

TEST(LexBlock, AnAddressTakesAVariableOrABracketedValue) {
  const std::vector<Token> tokens = tokensOf("G01 X-#1 Z[#2*2] F0.2");
  ASSERT_EQ(tokens.size(), 13u);  // G01 X - # 1 Z [ # 2 * 2 ] F0.2
  EXPECT_EQ(tokens[0].kind, TokenKind::Word);
  EXPECT_EQ(tokens[1].kind, TokenKind::Address);
  EXPECT_EQ(tokens[1].word.letter, 'X');
  EXPECT_EQ(tokens[1].column, 5);
  EXPECT_EQ(tokens[2].kind, TokenKind::Minus);
  EXPECT_EQ(tokens[3].kind, TokenKind::Hash);
  EXPECT_EQ(tokens[5].kind, TokenKind::Address);  // Z
  EXPECT_EQ(tokens[6].kind, TokenKind::Open);
  EXPECT_EQ(tokens[12].kind, TokenKind::Word);  // F0.2 stays a plain word
  EXPECT_EQ(tokens[12].word.text(), "F0.2");
}

TEST(LexBlock, NamesAreReadInAnyCaseAndNeverAsAddressLetters) {
  const std::vector<Token> tokens = tokensOf("while[#1le#2]do1");
  ASSERT_EQ(tokens.size(), 10u);
  EXPECT_EQ(tokens[0].text, "WHILE");
  EXPECT_EQ(tokens[4].text, "LE");
  EXPECT_EQ(tokens[8].text, "DO");
  // GOTO is a name, G0 a word.
  EXPECT_EQ(tokensOf("GOTO5")[0].kind, TokenKind::Name);
  EXPECT_EQ(tokensOf("G0 X5")[0].kind, TokenKind::Word);
}

TEST(LexBlock, AMacroCallTakesEveryArgumentLetterOthersDoNot) {
  const std::vector<Token> call = tokensOf("G65 P9010 A1. B2. Y3. E4 H5 V6");
  ASSERT_EQ(call.size(), 8u);
  EXPECT_EQ(call[4].word.letter, 'Y');
  auto blocks = readAll("G01 Y5");
  EXPECT_NE(lexBlock(blocks[0]).error().message.find("no Y axis"), std::string::npos);
}

TEST(BlockReader, CommentsAreKeptWithTheirBlock) {
  const auto blocks = readAll("#3000 = 1 (TOO BIG) (second)\n");
  ASSERT_EQ(blocks.size(), 1u);
  ASSERT_EQ(blocks[0].comments.size(), 2u);
  EXPECT_EQ(blocks[0].comments[0].text, "TOO BIG");
  EXPECT_EQ(blocks[0].comments[0].column, 11);
  EXPECT_EQ(blocks[0].comments[1].text, "second");
}

}  // namespace
}  // namespace lathesim::interp
