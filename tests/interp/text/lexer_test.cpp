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
  const Error error = tokenizeError("G00 X20 V5");
  EXPECT_EQ(error.column, 9);
  EXPECT_NE(error.message.find("unknown letter 'V'"), std::string::npos);
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
  EXPECT_EQ(blocks[0].comments, (std::vector<std::string>{"TOO BIG", "second"}));
}

}  // namespace
}  // namespace lathesim::interp

namespace lathesim::interp {
namespace {

TEST(Tokenize, ColonIsTheIsoProgramNumberAddress) {
  const auto words = wordsOf(":0100");
  ASSERT_EQ(words.size(), 1u);
  EXPECT_EQ(words[0].letter, 'O');
  EXPECT_EQ(words[0].number, "0100");
  EXPECT_EQ(words[0].column, 1);
}

}  // namespace
}  // namespace lathesim::interp

namespace lathesim::interp {
namespace {

// The ';' rule of lexer.hpp, on the cases where a reader could hesitate.
struct ProseCase {
  std::string_view text;
  std::size_t blocks;           // blocks read
  std::vector<std::string> comments;  // of the first block
};

TEST(SemicolonProse, ProseAfterASemicolonIsACommentOfItsBlock) {
  const std::vector<ProseCase> cases{
      {"T0505 ;parting tool 3mm\n", 1, {"parting tool 3mm"}},
      {"T0505;PARTING TOOL\n", 1, {"PARTING TOOL"}},
      {"G00 X10 ; X AXIS CLEAR\n", 1, {"X AXIS CLEAR"}},   // a letter, then a letter: prose
      {"G00 X10 ; 3mm clearance\n", 1, {"3mm clearance"}},  // cannot begin a block
      {"G00 X10 ; -- next op\n", 1, {"-- next op"}},
      {"G00 X10 ; 粗车\n", 1, {"粗车"}},
      {"G00 X10 ; Do not touch\n", 1, {"Do not touch"}},   // DO not followed by a number
      {"G00 X10 ; End of roughing\n", 1, {"End of roughing"}},
      {"G00 X42 Z0.5; G94 X25.5 Z-5 F100; Z-10;\n", 3, {}},  // the seeds' end of block
      {"G00 X10 ; X 20\n", 2, {}},                  // X20: a word, spaces aside
      {"G00 X10 ; (COMMENT)\n", 1, {}},             // a ( ) comment follows; no block
      {"#1=2; IF [#1 GT 1] GOTO 10\n", 2, {}},      // macro statements are not prose
      {"#1=2; WHILE [#1 GT 1] DO 1\n", 2, {}},
      {"#1=2; GOTO 10\n", 2, {}},
      {"#1=2; END 1\n", 2, {}},
      {"G00 X10 ;\nG01 Z5\n", 2, {}},
  };
  for (const ProseCase& c : cases) {
    SCOPED_TRACE(std::string(c.text));
    const auto blocks = readAll(c.text);
    ASSERT_EQ(blocks.size(), c.blocks);
    EXPECT_EQ(blocks[0].comments, c.comments);
  }
}

TEST(SemicolonProse, AWordThenProseIsAnErrorNotAComment) {
  // `; M08 coolant on` starts with a word: it is a block, and "coolant" is not a word.
  const auto blocks = readAll("G00 X10 ; M08 coolant on\n");
  ASSERT_EQ(blocks.size(), 2u);
  auto words = tokenize(blocks[1]);
  ASSERT_FALSE(words.ok());
  EXPECT_EQ(words.error().column, 15);
  EXPECT_NE(words.error().message.find("C has no number"), std::string::npos);
}

TEST(SemicolonProse, OneNoteSaysItOnce) {
  BlockReader reader("T0101 ;rough\nG00 X10\nT0202 ;finish\n");
  while (true) {
    auto next = reader.next();
    ASSERT_TRUE(next.ok());
    if (!next.value()) break;
  }
  const auto notes = reader.notes();
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0].line, 1);
  EXPECT_EQ(notes[0].column, 8);
  EXPECT_NE(notes[0].message.find("'rough' (and 1 more like it)"), std::string::npos) << notes[0].message;
}

TEST(Comments, CommentLinesDirectlyAboveABlockAreKeptWithIt) {
  const auto blocks = readAll("(T1 OD ROUGH)\n(CNMG 120408)\nT0101\n(LIST)\n\nT0202 (GROOVE 3MM)\n");
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[0].commentsAbove, (std::vector<std::string>{"T1 OD ROUGH", "CNMG 120408"}));
  EXPECT_TRUE(blocks[1].commentsAbove.empty());  // the empty line parts "(LIST)" from it
  EXPECT_EQ(blocks[1].comments, (std::vector<std::string>{"GROOVE 3MM"}));
}

TEST(TapeLeader, ControlBytesAndHeaderLinesBeforeTheProgramAreSkippedWithANote) {
  BlockReader reader("\x1b\x12&HE:1234 PART\n\x12%\nO1000\nG00 X10\n");
  std::vector<RawBlock> blocks;
  while (true) {
    auto next = reader.next();
    ASSERT_TRUE(next.ok());
    if (!next.value()) break;
    blocks.push_back(*next.value());
  }
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[0].line, 3);
  const auto notes = reader.notes();
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0].message,
            "skipped the tape/DNC leader before the program: ESC, DC2 and the header line '&HE:1234 PART'");
}

TEST(TapeLeader, AControlCharacterInsideTheProgramIsAnError) {
  const Error error = tokenizeError("G00 X10\x12 Z5");
  EXPECT_EQ(error.column, 8);
  EXPECT_NE(error.message.find("control character DC2 (0x12) inside the program"), std::string::npos);
}

TEST(LookAlikes, EachIsNamedWithWhatWasMeant) {
  struct Case {
    std::string_view text;
    int column;
    std::string_view part;
  };
  const std::vector<Case> cases{
      {"G00 X\xe2\x80\x93" "5", 6, "'–' (U+2013 EN DASH) looks like '-' but is not"},
      {"G00 X\xe2\x80\x94" "5", 6, "U+2014 EM DASH"},
      {"G00 X\xe2\x88\x92" "5", 6, "U+2212 MINUS SIGN"},
      {"G00 X\xef\xbc\x95", 6, "U+FF15 FULLWIDTH DIGIT) looks like '5'"},
      {"\xd0\x9e" "100", 1, "U+041E CYRILLIC CAPITAL LETTER O) looks like 'O'"},
      {"G00\xc2\xa0X5", 4, "looks like a space but is not: controls read ASCII only; retype it as a plain space"},
      {"G00 X5\xef\xbc\x9b", 7, "looks like ';'"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(c.text));
    const Error error = tokenizeError(c.text);
    EXPECT_EQ(error.column, c.column);
    EXPECT_NE(error.message.find(c.part), std::string::npos) << error.message;
  }
}

TEST(LookAlikes, LetterOTypedForZero) {
  Error error = tokenizeError("GO X0.");
  EXPECT_EQ(error.column, 2);
  EXPECT_NE(error.message.find("the letter 'O' right after G, where a number belongs; did you mean the digit 0 (G0)?"),
            std::string::npos);
  error = tokenizeError("G00 X1O.5");
  EXPECT_EQ(error.column, 7);
  EXPECT_NE(error.message.find("inside the number X1; did you mean the digit 0 (X10.5)?"), std::string::npos)
      << error.message;
  // An O word of its own (a program number) is not a zero.
  EXPECT_EQ(wordsOf("O0100").size(), 1u);
}

}  // namespace
}  // namespace lathesim::interp
