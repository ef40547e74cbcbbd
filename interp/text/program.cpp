#include "interp/text/program.hpp"

#include <algorithm>
#include <set>

#include <utility>

#include <fmt/format.h>

#include "interp/macro/block_syntax.hpp"
#include "interp/text/label_number.hpp"
#include "interp/text/lexer.hpp"

namespace lathesim::interp {
namespace {

const Word* wordOf(const std::vector<Token>& tokens, char letter) {
  for (const Token& token : tokens)
    if (token.kind == TokenKind::Word && token.word.letter == letter) return &token.word;
  return nullptr;
}

// The block's N or O number; an error for one too long or not a number (the block then
// carries it, reported if the block runs).
Status readLabel(const std::vector<Token>& tokens, char letter, int line, std::optional<int>& number) {
  const Word* word = wordOf(tokens, letter);
  if (word == nullptr) return success();
  auto read = letter == 'N' ? labelNumberOf(*word, line, kMaxSequenceDigits, "a sequence number")
                            : labelNumberOf(*word, line, kMaxProgramDigits, "a program number");
  if (!read.ok()) return read.error();
  number = read.value();
  return success();
}

// What a block says, sorted: its plain words, or its Custom Macro B.
using SortedContent = std::variant<ParsedBlock, std::shared_ptr<const macro::MacroBlock>>;

Result<SortedContent> contentOf(const std::vector<Token>& tokens, const RawBlock& raw, Dialect dialect,
                                MachineMCodes machine) {
  if (macro::needsMacroReader(tokens)) {
    auto macroBlock = macro::readMacroBlock(tokens, raw);
    if (!macroBlock.ok()) return macroBlock.error();
    return SortedContent{std::make_shared<const macro::MacroBlock>(std::move(macroBlock).value())};
  }
  std::vector<Word> words;
  for (const Token& token : tokens) words.push_back(token.word);
  auto parsed = parseBlock(words, raw.line, raw.column, dialect, machine);
  if (!parsed.ok()) return parsed.error();
  return SortedContent{std::move(parsed).value()};
}

// A block as the program keeps it: a block of plain words by where it starts.
BlockContent kept(SortedContent content, ReadPosition start) {
  if (auto* macroBlock = std::get_if<std::shared_ptr<const macro::MacroBlock>>(&content))
    return BlockContent{std::move(*macroBlock)};
  return BlockContent{PlainBlock{start}};
}

// The entry of `table` (sorted by ordinal) for the block `ordinal`, or nullptr.
template <class Entry>
const Entry* entryOf(const std::vector<Entry>& table, int ordinal) {
  const auto found = std::lower_bound(table.begin(), table.end(), ordinal,
                                      [](const Entry& entry, int wanted) { return entry.ordinal < wanted; });
  return found != table.end() && found->ordinal == ordinal ? &*found : nullptr;
}

}  // namespace

std::vector<std::size_t> Program::findSequence(int sequenceNumber, std::size_t from) const {
  const int program = programOf[from];
  std::vector<std::size_t> found;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    if (programOf[i] == program && !blocks[i].skipped && blocks[i].sequenceNumber == sequenceNumber)
      found.push_back(i);
  }
  return found;
}

std::optional<int> Program::programNumberOf(std::size_t index) const {
  const int start = programOf[index];
  if (start < 0) return std::nullopt;
  return blocks[static_cast<std::size_t>(start)].programNumber;
}

const BlockComments& Program::commentsOf(const ProgramBlock& block) const {
  static const BlockComments none;
  const BlockComments* found = entryOf(comments, block.ordinal);
  return found != nullptr ? *found : none;
}

const Error* Program::errorOf(const ProgramBlock& block) const {
  const BlockError* found = entryOf(errors, block.ordinal);
  return found != nullptr ? &found->error : nullptr;
}

std::optional<ParsedBlock> Program::plainWords(const ProgramBlock& block) const {
  if (block.skipped || !block.plain()) return std::nullopt;
  const SourceText& source = sources[static_cast<std::size_t>(block.source)];
  // It read when the program was read, the same way: it reads again.
  BlockReader reader(source.text, std::get<PlainBlock>(block.content).start);
  RawBlock raw = *reader.next().value();
  if (raw.skipFrom && source.blockDelete) raw.chars.resize(*raw.skipFrom);
  auto content = contentOf(lexBlock(raw).value(), raw, source.dialect, source.machine);
  return std::get<ParsedBlock>(std::move(content).value());
}

namespace {

// Appends the blocks of source `source` to `program`; returns the notes of the machine M codes
// it names first (the main program's go into program.notes, after the reader's own).
std::vector<ReadNote> appendBlocks(Program& program, int source) {
  const SourceText& text = program.sources[static_cast<std::size_t>(source)];
  const bool blockDelete = text.blockDelete;
  const MachineMCodes machine = text.machine;
  BlockReader reader(text.text);
  // Room for a block a line, the usual count, made at once: grown by doubling, the vector of a
  // million blocks would briefly hold its old and new copies, twice its size and more.
  const std::size_t lines = static_cast<std::size_t>(std::count(text.text.begin(), text.text.end(), '\n')) + 1;
  program.blocks.reserve(program.blocks.size() + lines);
  program.programOf.reserve(program.programOf.size() + lines);
  int currentProgram = -1;
  std::vector<ReadNote> machineNotes;  // each machine M code, where it first appears
  for (;;) {
    auto next = reader.next();
    ProgramBlock block;
    block.ordinal = static_cast<int>(program.blocks.size());
    block.source = source;
    if (!next.ok()) {  // an unclosed comment: nothing after it can be split into blocks
      block.line = next.error().line;
      block.column = next.error().column;
      program.errors.push_back({block.ordinal, next.error()});
      program.programOf.push_back(currentProgram);
      program.blocks.push_back(std::move(block));
      break;
    }
    if (!next.value()) break;
    RawBlock& raw = *next.value();
    if (raw.skipFrom && blockDelete) raw.chars.resize(*raw.skipFrom);
    block.line = raw.line;
    block.column = raw.column;
    block.deleted = raw.deleted;
    block.skipped = raw.deleted && blockDelete;
    Result<SortedContent> content = Error{};
    if (!block.skipped) {
      auto tokens = lexBlock(raw);
      if (tokens.ok()) {
        const Status sequence = readLabel(tokens.value(), 'N', raw.line, block.sequenceNumber);
        const Status number = readLabel(tokens.value(), 'O', raw.line, block.programNumber);
        content = !sequence.ok() ? Result<SortedContent>(sequence.error())
                  : !number.ok() ? Result<SortedContent>(number.error())
                                 : contentOf(tokens.value(), raw, text.dialect, machine);
      } else {
        content = tokens.error();
      }
    }
    const std::size_t index = program.blocks.size();
    if (block.programNumber) {
      currentProgram = static_cast<int>(index);
      program.programStart.emplace(*block.programNumber, index);
    }
    if (const ParsedBlock* words = content.ok() ? std::get_if<ParsedBlock>(&content.value()) : nullptr) {
      for (const Code& code : words->machineCodes) {
        if (!program.notedMachineCodes.insert(code.number).second) continue;
        const MachineMCode* own = findMachineMCode(code.number, machine);
        machineNotes.push_back({block.line, code.column,
                                fmt::format("{} ({}) is a machine function that changes nothing simulated: ignored",
                                            code.text, own ? own->meaning : "machine function")});
      }
    }
    if (!block.skipped && content.ok()) block.content = kept(std::move(content).value(), reader.blockStart());
    else if (!block.skipped) program.errors.push_back({block.ordinal, content.error()});
    // Moved out last: a macro block's message is its first comment, read above.
    if (!raw.comments.empty() || !raw.commentsAbove.empty())
      program.comments.push_back({block.ordinal, std::move(raw.comments), std::move(raw.commentsAbove)});
    program.programOf.push_back(currentProgram);
    program.blocks.push_back(std::move(block));
  }
  if (source != 0) return machineNotes;
  program.notes = reader.notes();
  program.notes.insert(program.notes.end(), machineNotes.begin(), machineNotes.end());
  if (const auto after = reader.textAfterClosing()) {
    program.textAfterEnd = Error{after->first, after->second,
                                 fmt::format("the program ends at the % on line {}: this text after it is not run",
                                             reader.closingPercent()->first)};
  }
  return {};
}

}  // namespace

Program readProgram(std::string_view text, bool blockDelete, Dialect dialect, MachineMCodes machine) {
  Program program;
  program.sources.push_back({"", text, nullptr, blockDelete, dialect, machine});
  appendBlocks(program, 0);
  return program;
}

std::vector<ReadNote> appendProgramFile(Program& program, const std::string& name, std::string text, int number,
                                        bool blockDelete, Dialect dialect, MachineMCodes machine) {
  const std::size_t first = program.blocks.size();
  auto file = std::make_shared<const std::string>(std::move(text));
  const std::string_view view = *file;
  program.sources.push_back({name, view, std::move(file), blockDelete, dialect, machine});
  std::vector<ReadNote> notes = appendBlocks(program, static_cast<int>(program.sources.size()) - 1);
  if (program.programStart.count(number) != 0 || first == program.blocks.size()) return notes;
  // No O line for it: the file is the program; its blocks before any O block belong to it.
  program.programStart.emplace(number, first);
  for (std::size_t i = first; i < program.blocks.size() && program.programOf[i] < 0; ++i)
    program.programOf[i] = static_cast<int>(first);
  return notes;
}

}  // namespace lathesim::interp
