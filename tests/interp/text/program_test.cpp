// A program keeps a block of plain words by where it starts and reads it again when asked
// (program.hpp): the words read again are the words a single pass through the text reads,
// wherever the block stands — after a tape leader or a byte order mark, after ';' on a line
// shared with others, behind comments, with a '/' skip, among macro blocks and subprograms.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "interp/text/block_parser.hpp"
#include "interp/text/lexer.hpp"
#include "interp/text/program.hpp"

namespace lathesim::interp {
namespace {

// "G1@1 X10@4 …": each code and word with its column, to compare two readings of a block.
std::string describe(const ParsedBlock& block) {
  std::string text = std::to_string(block.line) + ":" + std::to_string(block.column);
  for (const auto& [group, code] : block.gCodes) text += " " + code.text + "@" + std::to_string(code.column);
  for (const auto& [group, code] : block.mCodes) text += " " + code.text + "@" + std::to_string(code.column);
  for (const auto& [letter, word] : block.words) text.append(" ").append(word.text()).append("@").append(std::to_string(word.column));
  return text;
}

// The plain blocks of `text` as one pass of a BlockReader reads them, in order.
std::vector<std::string> readInOnePass(const std::string& text, bool blockDelete) {
  std::vector<std::string> blocks;
  BlockReader reader(text);
  for (auto next = reader.next(); next.ok() && next.value(); next = reader.next()) {
    RawBlock raw = *next.value();
    if (raw.deleted && blockDelete) continue;
    if (raw.skipFrom && blockDelete) raw.chars.resize(*raw.skipFrom);
    auto words = tokenize(raw);
    if (!words.ok()) continue;  // a macro block
    auto parsed = parseBlock(words.value(), raw.line, raw.column);
    if (parsed.ok()) blocks.push_back(describe(parsed.value()));
  }
  return blocks;
}

std::vector<std::string> readAgain(const Program& program) {
  std::vector<std::string> blocks;
  for (std::size_t ordinal = 0; ordinal < program.blockCount(); ++ordinal)
    if (const auto words = program.plainWords(program.block(ordinal))) blocks.push_back(describe(*words));
  return blocks;
}

TEST(ProgramBlocks, ReadAgainAsInOnePass) {
  const std::vector<std::string> texts = {
      "G0 X10 Z2\nG1 Z-5 F0.2\nM30\n",
      "\xEF\xBB\xBFG0 X10\nZ1\n",                            // a byte order mark
      "\x1b\x12  G0 X10\n\x14Z1\n",                          // a tape leader, an error after it
      "%\nO0001\n(ROUGH)\n  G0 X42 Z0.5; G94 X25.5 Z-5 F100; Z-10;\nM30\n%\n",  // ';' blocks on a line
      "T0101 ;turning tool\n(a comment) G1 X20 (another) Z-3\n",  // prose after ';', comments first
      "/G0 X5\nG1 X10 /Z-5\n  /  G1 X30\n",                 // block delete, a '/' skip inside
      "#1=5\nG0 X#1\nG1 X20 Z-1\nWHILE[#1GT0]DO1\n#1=#1-1\nEND1\nG0 X50\n",  // among macro blocks
      "G1 X10 (Ø20 — ünïcode) Z-2\nG1 X12 Z-4\r\nG1\tX14 Z-6\n",  // code points, CR LF, tabs
      "O1\nG0 X1\nM99\nO2\nN10 G1 X2\nN20 G1 Z-2\nM99\n",
  };
  for (const std::string& text : texts) {
    for (const bool blockDelete : {false, true}) {
      const Program program = readProgram(text, blockDelete, Dialect::FanucA);
      EXPECT_EQ(readAgain(program), readInOnePass(text, blockDelete)) << text;
    }
  }
}

// A block's words read again, checked by hand: the second block on the line starts at column
// 9, its Z at column 9, its F at column 15.
TEST(ProgramBlocks, ReadAgainWhereTheyStand) {
  const Program program = readProgram("G1 X10 ;Z-5.5 F0.1 (c)\n", false, Dialect::FanucA);
  ASSERT_EQ(program.blockCount(), 2u);
  const auto second = program.plainWords(program.block(1));
  ASSERT_TRUE(second);
  EXPECT_EQ(second->line, 1);
  EXPECT_EQ(second->column, 9);
  EXPECT_EQ(second->words.at('Z').number, "-5.5");
  EXPECT_EQ(second->words.at('Z').column, 9);
  EXPECT_EQ(second->words.at('F').column, 15);
  EXPECT_FALSE(program.plainWords(program.block(0))->has('Z'));
}

// Skipped blocks, blocks that do not read and macro blocks have no plain words.
TEST(ProgramBlocks, OnlyPlainBlocksHaveWords) {
  const Program program = readProgram("/G0 X5\nG1 X1.2.3\n#1=2\nG0 X1\n", true, Dialect::FanucA);
  ASSERT_EQ(program.blockCount(), 4u);
  EXPECT_FALSE(program.plainWords(program.block(0)));
  EXPECT_FALSE(program.plainWords(program.block(1)));
  EXPECT_FALSE(program.plainWords(program.block(2)));
  EXPECT_TRUE(program.plainWords(program.block(3)));
}

// Comments and errors are found for the blocks that have them, and only those, in programs
// where such blocks stand first, last, in a row and apart, with and without block delete.
TEST(ProgramBlocks, CommentsAndErrorsOfTheirBlocks) {
  const Program program = readProgram(
      "(OP 10)\n(T1 ROUGH)\nT0101 (CNMG)\nG0 X1\nG1 X1.2.3\n/G1 X2 (SKIP)\nG0 X3 (A) (B)\nG1 Q\nG1 X4 (LAST",
      true, Dialect::FanucA);
  ASSERT_EQ(program.blockCount(), 7u);
  const std::vector<std::vector<std::string>> own = {{"CNMG"}, {}, {}, {"SKIP"}, {"A", "B"}, {}, {}};
  const std::vector<std::vector<std::string>> above = {{"OP 10", "T1 ROUGH"}, {}, {}, {}, {}, {}, {}};
  const std::vector<int> errorLines = {0, 0, 5, 0, 0, 8, 9};  // 0: none
  for (std::size_t i = 0; i < program.blockCount(); ++i) {
    const ProgramBlock block = program.block(i);
    EXPECT_EQ(block.ordinal, static_cast<int>(i));
    EXPECT_EQ(program.commentsOf(block).own, own[i]) << i;
    EXPECT_EQ(program.commentsOf(block).above, above[i]) << i;
    const Error* error = program.errorOf(block);
    EXPECT_EQ(error != nullptr ? error->line : 0, errorLines[i]) << i;
    EXPECT_EQ(error == nullptr && !block.skipped, block.plain()) << i;
  }
  EXPECT_TRUE(program.block(3).skipped);
  EXPECT_NE(program.errorOf(program.block(6))->message.find("comment"), std::string::npos);
}

// A subprogram file's text is held by the Program: read again after the caller's copy is gone.
TEST(ProgramBlocks, SubprogramFileHeldByTheProgram) {
  Program program = readProgram("M98 P1234\nM30\n", false, Dialect::FanucA);
  {
    std::string file = "O1234\nG1 X7 Z-3 (FILE)\nM99\n";
    (void)appendProgramFile(program, "O1234.nc", FileText(std::move(file)), 1234, false, Dialect::FanucA);
  }
  ASSERT_EQ(program.blockCount(), 5u);
  const auto words = program.plainWords(program.block(3));
  ASSERT_TRUE(words);
  EXPECT_EQ(words->words.at('X').number, "7");
  EXPECT_EQ(program.commentsOf(program.block(3)).own, std::vector<std::string>{"FILE"});
  EXPECT_EQ(program.programStart(1234), 2u);
}

// The blocks with a T word and comments, told as the text is read through (readProgram's
// ToolBlockVisitor, for the tools named in comments): those and only those, in order, with the
// words and comments the Program gives when the block is read again.
TEST(ProgramBlocks, ToolBlocksWithCommentsAreToldAsTheTextIsReadThrough) {
  const std::string text =
      "O1000\n"
      "(ROUGHING CNMG 120408)\n"
      "T0101\n"                    // 3: told, its comment above
      "G00 X40. Z2.\n"
      "T0202 (DRILL 12)\n"         // 5: told, its own comment
      "T0303\n"                    // no comment
      "/T0404 (GROOVE 3MM)\n"      // 7: told unless block delete skips it
      "M06 T05 (THREAD P1.5)\n"    // 8: told, beside M06
      "G00 X50. (NO TOOL HERE)\n"  // a comment, no T word
      "T#1 (TOOL BY VARIABLE)\n"   // Custom Macro B: no plain words
      "T06 N5 (A B) (C)\n"         // 11: told, two comments
      "M06 T07\n"                  // sorted for its M code, but no comment
      "M30\n";
  for (const bool blockDelete : {false, true}) {
    SCOPED_TRACE(blockDelete ? "block delete on" : "block delete off");
    std::vector<int> lines;
    std::vector<std::string> told;
    const Program program = readProgram(text, blockDelete, Dialect::FanucA, MachineMCodes::Gsk980tdi,
                                        [&](const ReadBlock& read) {
                                          lines.push_back(read.block.line);
                                          std::string comments;
                                          for (const auto& c : read.comments.own) comments += "(" + c + ")";
                                          for (const auto& c : read.comments.above) comments += "^(" + c + ")";
                                          told.push_back(describe(*read.words) + " " + comments);
                                        });
    EXPECT_EQ(lines, (blockDelete ? std::vector<int>{3, 5, 8, 11} : std::vector<int>{3, 5, 7, 8, 11}));
    // The same blocks read again, one by one, as the Program gives them to the interpreter.
    std::vector<std::string> again;
    for (std::size_t ordinal = 0; ordinal < program.blockCount(); ++ordinal) {
      const ProgramBlock block = program.block(ordinal);
      const auto words = program.plainWords(block);
      const BlockComments& comments = program.commentsOf(block);
      if (!words || !words->has('T') || (comments.own.empty() && comments.above.empty())) continue;
      std::string said;
      for (const auto& c : comments.own) said += "(" + c + ")";
      for (const auto& c : comments.above) said += "^(" + c + ")";
      again.push_back(describe(*words) + " " + said);
    }
    EXPECT_EQ(told, again);
    ASSERT_FALSE(told.empty());
    EXPECT_NE(told.front().find("^(ROUGHING CNMG 120408)"), std::string::npos) << told.front();
  }
}

}  // namespace
}  // namespace lathesim::interp
