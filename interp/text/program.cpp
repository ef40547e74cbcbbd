#include "interp/text/program.hpp"

#include <utility>

#include "interp/text/lexer.hpp"

namespace lathesim::interp {
namespace {

std::optional<int> numberOf(const std::vector<Word>& words, char letter) {
  for (const Word& word : words) {
    if (word.letter == letter) return static_cast<int>(word.value);
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::size_t> Program::findSequence(int sequenceNumber, std::size_t from) const {
  const int program = programOf[from];
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    if (programOf[i] == program && !blocks[i].skipped &&
        blocks[i].sequenceNumber == sequenceNumber) {
      return i;
    }
  }
  return std::nullopt;
}

std::optional<int> Program::programNumberOf(std::size_t index) const {
  const int start = programOf[index];
  if (start < 0) return std::nullopt;
  return blocks[static_cast<std::size_t>(start)].programNumber;
}

namespace {

// Appends the blocks of source `source` to `program`.
void appendBlocks(Program& program, int source, bool blockDelete, Dialect dialect) {
  BlockReader reader(program.sources[static_cast<std::size_t>(source)].text);
  int currentProgram = -1;
  for (;;) {
    auto next = reader.next();
    ProgramBlock block;
    block.ordinal = static_cast<int>(program.blocks.size());
    block.source = source;
    if (!next.ok()) {  // an unclosed comment: nothing after it can be split into blocks
      block.line = next.error().line;
      block.column = next.error().column;
      block.parsed = next.error();
      program.programOf.push_back(currentProgram);
      program.blocks.push_back(std::move(block));
      break;
    }
    if (!next.value()) break;
    const RawBlock& raw = *next.value();
    block.line = raw.line;
    block.column = raw.column;
    block.deleted = raw.deleted;
    block.comments = raw.comments;
    block.commentsAbove = raw.commentsAbove;
    block.skipped = raw.deleted && blockDelete;
    if (!block.skipped) {
      auto words = tokenize(raw);
      if (words.ok()) {
        block.sequenceNumber = numberOf(words.value(), 'N');
        block.programNumber = numberOf(words.value(), 'O');
        block.parsed = parseBlock(words.value(), raw.line, raw.column, dialect);
      } else {
        block.parsed = words.error();
      }
    }
    const std::size_t index = program.blocks.size();
    if (block.programNumber) {
      currentProgram = static_cast<int>(index);
      program.programStart.emplace(*block.programNumber, index);
    }
    program.programOf.push_back(currentProgram);
    program.blocks.push_back(std::move(block));
  }
  if (source == 0) program.notes = reader.notes();
}

}  // namespace

Program readProgram(std::string_view text, bool blockDelete, Dialect dialect) {
  Program program;
  program.sources.push_back({"", std::string(text)});
  appendBlocks(program, 0, blockDelete, dialect);
  return program;
}

void appendProgramFile(Program& program, const std::string& name, std::string_view text, int number,
                       bool blockDelete, Dialect dialect) {
  const std::size_t first = program.blocks.size();
  program.sources.push_back({name, std::string(text)});
  appendBlocks(program, static_cast<int>(program.sources.size()) - 1, blockDelete, dialect);
  if (program.programStart.count(number) != 0 || first == program.blocks.size()) return;
  // No O line for it: the file is the program; its blocks before any O block belong to it.
  program.programStart.emplace(number, first);
  for (std::size_t i = first; i < program.blocks.size() && program.programOf[i] < 0; ++i)
    program.programOf[i] = static_cast<int>(first);
}

}  // namespace lathesim::interp
