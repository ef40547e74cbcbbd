// A program is read through a bounded window (program.hpp): a block read anywhere, in any
// order, is the block one pass reads there; a label is found by searching the text; and what
// the Program holds stays within its bounds however long the program and however many labels
// it searches. The expected blocks are worked out from how the texts are written, not by
// reading them.

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <map>
#include <string>
#include <vector>

#include "../test_support.hpp"
#include "interp/text/program.hpp"

namespace lathesim::interp {
namespace {

// A block as the text below is written: where it is, which program it belongs to.
struct Written {
  int line = 0;
  int column = 0;
  int program = -1;  // ordinal of its O block
  std::optional<int> sequence;
  std::vector<std::string> above;  // comment lines directly above it
  std::vector<std::string> own;
};

// `programs` programs O1… of `blocks` blocks each (the O block and blocks N1…), with comment
// lines above some blocks, two blocks on one line after ';', a prose tail, a deleted block
// and a macro statement among them.
struct LongText {
  std::string text;
  std::vector<Written> blocks;
};

LongText longText(int programs, int blocks) {
  LongText made;
  int line = 1;
  for (int p = 1; p <= programs; ++p) {
    const int start = static_cast<int>(made.blocks.size());
    made.text += fmt::format("O{}\n", p);
    made.blocks.push_back({line++, 1, start, std::nullopt, {}, {}});
    for (int n = 1; n < blocks; ++n) {
      const int ordinal = static_cast<int>(made.blocks.size());
      std::vector<std::string> above;
      if (ordinal % 7 == 0) {  // a comment line above it
        above.push_back(fmt::format("C{}", ordinal));
        made.text += fmt::format("(C{})\n", ordinal);
        ++line;
      }
      if (n % 11 == 0) {  // this block and the next share a line
        made.text += fmt::format("N{} G1 X{} ; N{} Z-{}\n", n, n % 40, n + 1, n % 30);
        made.blocks.push_back({line, 1, start, n, above, {}});
        const int second = 1 + static_cast<int>(fmt::format("N{} G1 X{} ; ", n, n % 40).size());
        made.blocks.push_back({line++, second, start, n + 1, {}, {}});
        ++n;
      } else if (n % 13 == 0) {  // indented, with a comment of its own and a prose tail
        made.text += fmt::format("  N{} G0 X{} (OWN) ;rapid away\n", n, n % 40);
        made.blocks.push_back({line++, 3, start, n, above, {"OWN", "rapid away"}});
      } else if (n % 17 == 0) {
        made.text += fmt::format("N{} #1=#1+1\n", n);
        made.blocks.push_back({line++, 1, start, n, above, {}});
      } else {
        made.text += fmt::format("N{} G1 Z-{} F0.1\n", n, n % 30);
        made.blocks.push_back({line++, 1, start, n, above, {}});
      }
    }
  }
  made.text += "M30\n";
  made.blocks.push_back({line, 1, made.blocks.back().program, std::nullopt, {}, {}});
  return made;
}

void expectWritten(const Program& program, std::size_t ordinal, const Written& written) {
  const ProgramBlock block = program.block(ordinal);
  EXPECT_EQ(block.ordinal, static_cast<int>(ordinal));
  EXPECT_EQ(block.line, written.line) << ordinal;
  EXPECT_EQ(block.column, written.column) << ordinal;
  EXPECT_EQ(block.program, written.program) << ordinal;
  EXPECT_EQ(block.sequenceNumber, written.sequence) << ordinal;
  EXPECT_EQ(program.commentsOf(block).above, written.above) << ordinal;
  EXPECT_EQ(program.commentsOf(block).own, written.own) << ordinal;
  EXPECT_EQ(program.errorOf(block), nullptr) << ordinal;
}

// Blocks asked for in order, backwards, and in strides that jump across the checkpoints are
// the blocks as written, in programs long enough that the checkpoints were thinned.
TEST(ProgramWindow, ABlockReadAnywhereIsTheBlockWritten) {
  for (const auto& [programs, blocks] : {std::pair{3, 40}, std::pair{20, 500}, std::pair{9, 20000}}) {
    const LongText made = longText(programs, blocks);
    const Program program = readProgram(made.text, false, Dialect::FanucA);
    ASSERT_EQ(program.blockCount(), made.blocks.size());
    const std::size_t count = made.blocks.size();
    for (std::size_t i = 0; i < count; ++i) expectWritten(program, i, made.blocks[i]);
    for (std::size_t i = count; i-- > count - std::min<std::size_t>(count, 3000);)
      expectWritten(program, i, made.blocks[i]);
    for (const std::size_t stride : {std::size_t{7919}, std::size_t{104729}}) {
      for (std::size_t k = 0; k < std::min<std::size_t>(count, 400); ++k) {
        const std::size_t i = (k * stride) % count;
        expectWritten(program, i, made.blocks[i]);
      }
    }
  }
}

// Searched N numbers and O numbers are the blocks written with them, in their own program
// only; a number written twice in one program is found twice.
TEST(ProgramWindow, LabelsAreFoundInTheirProgram) {
  const int programs = 30;
  const int blocks = 300;
  LongText made = longText(programs, blocks);
  made.text += "O99\nN5 G0 X1\nN5 G0 X2\nM99\n";  // N5 twice
  const Program program = readProgram(made.text, false, Dialect::FanucA);
  for (int p = 0; p < programs; ++p) {
    const std::size_t start = static_cast<std::size_t>(p * blocks);
    EXPECT_EQ(program.programStart(p + 1), start);
    for (const int n : {1, 11, 12, 13, 17, blocks - 1}) {
      const SequenceBlocks found = program.findSequence(n, start + 5);
      ASSERT_EQ(found.count, 1u) << p << " N" << n;
      EXPECT_EQ(made.blocks[found.first].sequence, n);
      EXPECT_EQ(made.blocks[found.first].program, static_cast<int>(start));
    }
    EXPECT_EQ(program.findSequence(blocks, start).count, 0u);
  }
  const std::size_t o99 = made.blocks.size();
  EXPECT_EQ(program.programStart(99), o99);
  const SequenceBlocks twice = program.findSequence(5, o99 + 3);
  EXPECT_EQ(twice.count, 2u);
  EXPECT_EQ(twice.first, o99 + 1);
  EXPECT_EQ(twice.second, o99 + 2);
  EXPECT_EQ(program.findSequence(5, 0).count, 1u);
  EXPECT_FALSE(program.programStart(100));
}

// Labels written far apart in a long program, which the searches find by passing over the
// runs of blocks that cannot hold them: each N number where it is written, in its program; an
// N number written in no run, none; an O number in the last run.
TEST(ProgramWindow, SparseLabelsAreFoundWhereverTheyStand) {
  std::string text;
  std::vector<std::pair<int, std::size_t>> labels;  // N number, ordinal
  const std::size_t count = 60000;
  for (std::size_t i = 0; i < count; ++i) {
    if (i % 997 == 500) {
      const int n = static_cast<int>(i / 997) * 10 + 10;
      labels.emplace_back(n, i);
      text += fmt::format("N{} G1 X{} Z-1\n", n, i % 40);
    } else {
      text += fmt::format("G1 X{} Z-{}\n", i % 40, i % 30);
    }
  }
  text += "O77\nN10 G1 X1\nM99\n";
  const Program program = readProgram(text, false, Dialect::FanucA);
  ASSERT_EQ(program.blockCount(), count + 3);
  for (const auto& [n, ordinal] : labels) {
    for (const std::size_t from : {std::size_t{0}, ordinal, count - 1}) {
      const SequenceBlocks found = program.findSequence(n, from);
      ASSERT_EQ(found.count, 1u) << n;
      EXPECT_EQ(found.first, ordinal) << n;
    }
    EXPECT_EQ(program.findSequence(n + 5, ordinal).count, 0u) << n;
  }
  EXPECT_EQ(program.findSequence(10, count + 2).first, count + 1);  // O77's own N10
  EXPECT_EQ(program.findSequence(10, count + 2).count, 1u);
  EXPECT_EQ(program.programStart(77), count);
  EXPECT_FALSE(program.programStart(78));
}

// However long the program and however many labels are searched, the Program holds at most
// its window of blocks, its checkpoints and its table of labels found.
TEST(ProgramWindow, WhatItHoldsIsBoundedWhateverTheLength) {
  const int blocks = 50;
  for (const int programs : {40, 2000}) {  // 2 000 and 100 000 blocks, 5 000 labels searched
    const LongText made = longText(programs, blocks);
    const Program program = readProgram(made.text, false, Dialect::FanucA);
    for (std::size_t i = 0; i < program.blockCount(); ++i) program.block(i);
    for (int k = 0; k < 5000; ++k) {
      const int p = (k * 37) % programs;
      const std::size_t start = static_cast<std::size_t>(p * blocks);
      const int n = 1 + (k * 7) % (blocks - 1);
      const SequenceBlocks found = program.findSequence(n, start + (k % blocks));
      ASSERT_EQ(found.count, 1u);
      ASSERT_EQ(made.blocks[found.first].sequence, n);
      ASSERT_EQ(made.blocks[found.first].program, static_cast<int>(start));
    }
    const Program::Held held = program.held();
    EXPECT_LE(held.windowBlocks, Program::kWindowBlocks);
    EXPECT_LE(held.checkpoints, Program::kMaxCheckpoints);
    EXPECT_LE(held.rememberedLabels, 2 * Program::kMaxRememberedLabels);
    EXPECT_LE(held.recentReaders, Program::kRecentReaders);
  }
}

// A program far longer than the window: a G70 thousands of blocks after its contour, a
// subprogram at its end called from its middle, and a GOTO back over thousands of blocks. Each
// block's moves are counted by its line: once, the looped ones twice; the G70 finishes as it
// does right after its contour.
TEST(ProgramWindow, JumpsFarBeyondTheWindowRunAsWritten) {
  const int filler = 3000;  // blocks of one rapid each, alternating X44 and X46
  const auto fill = [&](std::string& text, int& line, std::vector<int>& lines) {
    for (int i = 0; i < filler; ++i) {
      text += i % 2 == 0 ? "G00 X46. Z2.\n" : "G00 X44. Z2.\n";
      lines.push_back(line++);
    }
  };
  const std::string contour = "G00 X44. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X30.\n"
                              "N20 G01 Z-10. F0.1\n";
  std::string text = "#1=0\nG99\n" + contour;
  int line = 8;
  std::vector<int> once;
  std::vector<int> twice;
  fill(text, line, once);
  const int g70 = line++;
  text += "G70 P10 Q20\nM98 P1000\nN5 #1=#1+1\n";
  line += 2;
  fill(text, line, twice);
  text += "IF[#1LT2]GOTO5\nM30\nO1000\nG01 U-2. F0.1\nG00 U2.\nM99\n";
  const int subprogram = line + 3;  // its G01; its G00 follows
  once.insert(once.end(), {subprogram, subprogram + 1});
  const InterpretResult result = test::run(text);
  ASSERT_TRUE(result.ok()) << test::messageOf(result);
  std::map<int, int> movesOfLine;
  std::vector<Move> upToG70;  // the moves of the blocks before the filler, then of the G70
  for (const Move& move : result.toolpath.moves) {
    ++movesOfLine[move.line];
    if (move.line < 8 || move.line == g70) upToG70.push_back(move);
  }
  for (const int l : once) EXPECT_EQ(movesOfLine[l], 1) << l;
  for (const int l : twice) EXPECT_EQ(movesOfLine[l], 2) << l;
  const InterpretResult near = test::run("#1=0\nG99\n" + contour + "G70 P10 Q20\nM30\n");
  ASSERT_TRUE(near.ok()) << test::messageOf(near);
  test::expectSameMoves(upToG70, near.toolpath.moves);
  // The G70 made moves of its own (its contour's lines, its return at its line).
  EXPECT_GT(movesOfLine[g70] + movesOfLine[6] + movesOfLine[7], 2);
}

}  // namespace
}  // namespace lathesim::interp
