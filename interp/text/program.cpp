#include "interp/text/program.hpp"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

#include "interp/text/block_syntax.hpp"
#include "interp/text/label_number.hpp"
#include "interp/text/lexer.hpp"

namespace lathesim::interp {
namespace {

// The first spacing of a source's checkpoints, in blocks; doubled each time they are thinned.
constexpr int kFirstCheckpointSpacing = 64;

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

// What a read needs of a block: all it says; what reading a source through needs (its labels,
// its machine M codes, whether it is a DO or END: the words of a block without an M are not
// sorted), with or without the words of the blocks with a T word and comments (a
// ToolBlockVisitor's); or its N and O numbers alone (a search for a label).
enum class Reading { Whole, Survey, SurveyWithTools, LabelsOnly };

bool holdsLetter(const RawBlock& raw, std::string_view letters) {
  return std::any_of(raw.chars.begin(), raw.chars.end(), [&](const SourceChar& c) {
    return c.text.size() == 1 && letters.find(c.text[0]) != std::string_view::npos;
  });
}

// The next block of `reader`, a reader of `text` (source `source`), as block `ordinal`, which
// an O block makes the start of a `program`; nullopt at the end of the text.
std::optional<ReadBlock> readNext(BlockReader& reader, const SourceText& text, int source, int ordinal, int& program,
                                  Reading reading) {
  auto next = reader.next();
  ReadBlock read;
  ProgramBlock& block = read.block;
  block.ordinal = ordinal;
  block.source = source;
  block.program = program;
  if (!next.ok()) {  // an unclosed comment: nothing after it can be split into blocks
    block.line = next.error().line;
    block.column = next.error().column;
    read.error = next.error();
    read.endsText = true;
    return read;
  }
  if (!next.value()) return std::nullopt;
  text.text.readingAt(reader.blockStart().at);
  RawBlock& raw = *next.value();
  if (raw.skipFrom && text.blockDelete) raw.chars.resize(*raw.skipFrom);
  block.line = raw.line;
  block.column = raw.column;
  block.deleted = raw.deleted;
  block.skipped = raw.deleted && text.blockDelete;
  Result<SortedContent> content = Error{};
  // A search passes quickly over the many blocks that cannot hold an N or O word (':' is O).
  const bool mayHoldLabel = reading != Reading::LabelsOnly || holdsLetter(raw, "NnOo:");
  if (!block.skipped && mayHoldLabel) {
    auto tokens = lexBlock(raw);
    if (tokens.ok()) {
      const Status sequence = readLabel(tokens.value(), 'N', raw.line, block.sequenceNumber);
      const Status number = readLabel(tokens.value(), 'O', raw.line, block.programNumber);
      const bool toolBlock = reading == Reading::SurveyWithTools && holdsLetter(raw, "Tt") &&
                             (!raw.comments.empty() || !raw.commentsAbove.empty());
      const bool sorted =
          reading == Reading::Whole || toolBlock || macro::needsMacroReader(tokens.value()) || holdsLetter(raw, "Mm");
      if (reading != Reading::LabelsOnly && sorted) {
        content = !sequence.ok() ? Result<SortedContent>(sequence.error())
                  : !number.ok() ? Result<SortedContent>(number.error())
                                 : contentOf(tokens.value(), raw, text.dialect, text.machine);
      }
    } else {
      content = tokens.error();
    }
  }
  if (block.programNumber) program = ordinal;
  block.program = program;
  if (reading == Reading::LabelsOnly || block.skipped) {
    read.comments = {std::move(raw.comments), std::move(raw.commentsAbove)};
    return read;
  }
  if (!content.ok()) {
    read.error = content.error();
  } else if (auto* macroBlock = std::get_if<std::shared_ptr<const macro::MacroBlock>>(&content.value())) {
    block.content = std::move(*macroBlock);
  } else {
    block.content = PlainBlock{reader.blockStart()};
    read.words = std::get<ParsedBlock>(std::move(content).value());
  }
  // Moved out last: a macro block's message is its first comment, read above.
  read.comments = {std::move(raw.comments), std::move(raw.commentsAbove)};
  return read;
}

// The bit of 64 that stands for label `number` in LabelBits, spread so that numbers written in
// steps (N10, N20 …) fall on different bits.
std::uint64_t labelBit(int number) {
  return std::uint64_t{1} << ((static_cast<std::uint64_t>(number) * 0x9E3779B97F4A7C15ULL) >> 58);
}

bool isLoopBlock(const ProgramBlock& block) {
  const macro::MacroBlock* macroBlock = block.macroBlock();
  return macroBlock != nullptr && macroBlock->statement &&
         (std::holds_alternative<macro::LoopStart>(*macroBlock->statement) ||
          std::holds_alternative<macro::LoopEnd>(*macroBlock->statement));
}

}  // namespace

std::size_t Program::blockCount() const {
  if (sources.empty()) return 0;
  return static_cast<std::size_t>(sources.back().firstOrdinal + sources.back().blockCount);
}

int Program::sourceOf(std::size_t ordinal) const {
  int source = static_cast<int>(sources.size()) - 1;
  while (source > 0 && static_cast<std::size_t>(sources[static_cast<std::size_t>(source)].firstOrdinal) > ordinal)
    --source;
  return source;
}

// A reader of `source` at its last checkpoint at or before block `ordinal`, or at its start.
Program::Cursor Program::cursorBefore(int source, std::size_t ordinal) const {
  const SourceText& text = sources[static_cast<std::size_t>(source)];
  const auto after = std::upper_bound(text.checkpoints.begin(), text.checkpoints.end(), ordinal,
                                      [](std::size_t wanted, const ReadCheckpoint& checkpoint) {
                                        return wanted < static_cast<std::size_t>(checkpoint.ordinal);
                                      });
  if (after == text.checkpoints.begin())
    return Cursor{source, BlockReader(text.text.view()), text.firstOrdinal, text.leadingProgram};
  const ReadCheckpoint& checkpoint = *std::prev(after);
  return Cursor{source, BlockReader(text.text.view(), checkpoint.at), checkpoint.ordinal, checkpoint.program};
}

// Block `ordinal` as read: from the window, read on from its last block, or read on from the
// nearest reader before it, a recent one or one at a checkpoint (the window then starts again
// there).
const ReadBlock& Program::entry(std::size_t ordinal) const {
  if (!window_.empty()) {
    const auto front = static_cast<std::size_t>(window_.front().block.ordinal);
    if (ordinal >= front && ordinal < front + window_.size()) return window_[ordinal - front];
  }
  const int source = sourceOf(ordinal);
  Cursor start = cursorBefore(source, ordinal);
  const bool readOn = cursor_ && cursor_->source == source && static_cast<std::size_t>(cursor_->next) <= ordinal &&
                      cursor_->next >= start.next;
  if (!readOn) {
    const Cursor* nearest = nullptr;
    for (const Cursor& recent : recent_)
      if (recent.source == source && static_cast<std::size_t>(recent.next) <= ordinal && recent.next > start.next &&
          (nearest == nullptr || recent.next > nearest->next))
        nearest = &recent;
    if (nearest != nullptr) start = *nearest;
    if (cursor_) rememberReader(std::move(*cursor_));
    cursor_ = std::move(start);
    window_.clear();
  }
  const SourceText& text = sources[static_cast<std::size_t>(source)];
  for (;;) {
    if (!readOn && static_cast<std::size_t>(cursor_->next) == ordinal) rememberReader(*cursor_);  // where the jump lands
    // The source was read through: it holds block `ordinal`.
    std::optional<ReadBlock> read = readNext(cursor_->reader, text, source, cursor_->next, cursor_->program, Reading::Whole);
    ++cursor_->next;
    window_.push_back(std::move(*read));
    if (window_.size() > kWindowBlocks) window_.pop_front();
    if (static_cast<std::size_t>(window_.back().block.ordinal) == ordinal) return window_.back();
  }
}

void Program::rememberReader(Cursor cursor) const {
  std::erase_if(recent_, [&](const Cursor& recent) { return recent.source == cursor.source && recent.next == cursor.next; });
  recent_.push_back(std::move(cursor));
  if (recent_.size() > kRecentReaders) recent_.pop_front();
}

ProgramBlock Program::block(std::size_t ordinal) const { return entry(ordinal).block; }

const BlockComments& Program::commentsOf(const ProgramBlock& block) const {
  return entry(static_cast<std::size_t>(block.ordinal)).comments;
}

const Error* Program::errorOf(const ProgramBlock& block) const {
  const ReadBlock& read = entry(static_cast<std::size_t>(block.ordinal));
  return read.error ? &*read.error : nullptr;
}

std::optional<ParsedBlock> Program::plainWords(const ProgramBlock& block) const {
  if (block.skipped || !block.plain()) return std::nullopt;
  return entry(static_cast<std::size_t>(block.ordinal)).words;
}

// Reads the N and O numbers of the blocks of `source` from block `from` on, passing each to
// `visit` until it returns false or the source ends; the runs of blocks between checkpoints
// that `filter` says cannot hold what is searched for are passed over unread. Apart from the
// window: a search leaves the blocks being run where they are.
template <class Visit>
void Program::scan(int source, std::size_t from, const LabelFilter& filter, Visit visit) const {
  const SourceText& text = sources[static_cast<std::size_t>(source)];
  const std::vector<ReadCheckpoint>& checkpoints = text.checkpoints;
  const int end = text.firstOrdinal + text.blockCount;
  // Run k: the blocks before checkpoint k, from checkpoint k − 1 (from the start for k = 0).
  auto run = static_cast<std::size_t>(std::upper_bound(checkpoints.begin(), checkpoints.end(), from,
                                                       [](std::size_t wanted, const ReadCheckpoint& checkpoint) {
                                                         return wanted < static_cast<std::size_t>(checkpoint.ordinal);
                                                       }) -
                                      checkpoints.begin());
  for (;; ++run) {
    const int runEnd = run < checkpoints.size() ? checkpoints[run].ordinal : end;
    if (filter.mayHold(run == 0 ? text.headLabels : checkpoints[run - 1].labels)) {
      Cursor cursor = run == 0 ? Cursor{source, BlockReader(text.text.view()), text.firstOrdinal, text.leadingProgram}
                               : Cursor{source, BlockReader(text.text.view(), checkpoints[run - 1].at),
                                        checkpoints[run - 1].ordinal, checkpoints[run - 1].program};
      for (; cursor.next < runEnd; ++cursor.next) {
        std::optional<ReadBlock> read =
            readNext(cursor.reader, text, source, cursor.next, cursor.program, Reading::LabelsOnly);
        if (static_cast<std::size_t>(cursor.next) >= from && !visit(read->block)) return;
      }
    }
    if (run >= checkpoints.size()) return;
  }
}

SequenceBlocks Program::findSequence(int sequenceNumber, std::size_t from) const {
  const int program = block(from).program;
  const std::pair key{program, sequenceNumber};
  if (const auto known = sequences_.find(key); known != sequences_.end()) return known->second;
  SequenceBlocks found;
  const auto visit = [&](const ProgramBlock& block) {
    if (block.program != program) return false;  // the next program starts
    if (!block.skipped && block.sequenceNumber == sequenceNumber) {
      if (found.count == 0) found.first = static_cast<std::size_t>(block.ordinal);
      if (found.count == 1) found.second = static_cast<std::size_t>(block.ordinal);
      ++found.count;
    }
    return true;
  };
  const LabelFilter filter{{labelBit(sequenceNumber), 0}, true};
  if (program >= 0) {
    scan(sourceOf(static_cast<std::size_t>(program)), static_cast<std::size_t>(program), filter, visit);
  } else {  // the blocks before any O block, in each source whose first blocks have none
    for (std::size_t source = 0; source < sources.size(); ++source)
      if (sources[source].leadingProgram < 0)
        scan(static_cast<int>(source), static_cast<std::size_t>(sources[source].firstOrdinal), filter, visit);
  }
  if (sequences_.size() >= kMaxRememberedLabels) sequences_.clear();
  sequences_.emplace(key, found);
  return found;
}

std::optional<std::size_t> Program::programStart(int number) const {
  if (const auto known = programStarts_.find(number); known != programStarts_.end()) return known->second;
  std::optional<std::size_t> found;
  const LabelFilter filter{{0, labelBit(number)}, false};
  for (std::size_t source = 0; source < sources.size() && !found; ++source) {
    scan(static_cast<int>(source), static_cast<std::size_t>(sources[source].firstOrdinal), filter, [&](const ProgramBlock& block) {
      if (block.programNumber == number) found = static_cast<std::size_t>(block.ordinal);
      return !found;
    });
    if (!found && sources[source].namedProgram == number) found = static_cast<std::size_t>(sources[source].firstOrdinal);
  }
  if (!found) return std::nullopt;
  if (programStarts_.size() >= kMaxRememberedLabels) programStarts_.clear();
  programStarts_.emplace(number, *found);
  return found;
}

std::optional<int> Program::programNumberOf(std::size_t index) const {
  const int start = block(index).program;
  if (start < 0) return std::nullopt;
  return block(static_cast<std::size_t>(start)).programNumber;
}

Program::Held Program::held() const {
  Held held;
  held.windowBlocks = window_.size();
  for (const SourceText& source : sources) held.checkpoints += source.checkpoints.size();
  held.rememberedLabels = sequences_.size() + programStarts_.size();
  held.recentReaders = recent_.size();
  return held;
}

std::vector<ReadNote> Program::readThrough(int source, std::optional<int> readFor, const ToolBlockVisitor& toolBlocks) {
  SourceText& text = sources[static_cast<std::size_t>(source)];
  const int first = source == 0 ? 0 : sources[static_cast<std::size_t>(source) - 1].firstOrdinal +
                                           sources[static_cast<std::size_t>(source) - 1].blockCount;
  text.firstOrdinal = first;
  text.checkpointSpacing = kFirstCheckpointSpacing;
  BlockReader reader(text.text.view());
  int program = -1;
  int ordinal = first;
  int lastCheckpoint = first;  // the source's start serves as one
  std::vector<ReadNote> machineNotes;  // each machine M code, where it first appears
  const Reading reading = toolBlocks ? Reading::SurveyWithTools : Reading::Survey;
  while (std::optional<ReadBlock> read = readNext(reader, text, source, ordinal, program, reading)) {
    const ProgramBlock& block = read->block;
    if (toolBlocks && read->words && read->words->has('T') &&
        (!read->comments.own.empty() || !read->comments.above.empty()))
      toolBlocks(*read);
    if (read->words) {
      for (const Code& code : read->words->machineCodes) {
        if (!notedMachineCodes.insert(code.number).second) continue;
        const MachineMCode* own = findMachineMCode(code.number, text.machine);
        if (own == nullptr) continue;  // the parser takes only the table's codes as machine codes
        machineNotes.push_back({block.line, code.column, machineMCodeMessage(*own, code.text),
                                own->motion != MachineMotion::None});
      }
    }
    if (isLoopBlock(block)) ++loopBlocks;
    ++ordinal;
    if (read->endsText) break;
    // A reader started at a block reads no comment lines above it: a checkpoint stands at a
    // block with none.
    if (block.ordinal - lastCheckpoint >= text.checkpointSpacing && read->comments.above.empty()) {
      text.checkpoints.push_back({block.ordinal, reader.blockStart(), block.program});
      lastCheckpoint = block.ordinal;
      if (text.checkpoints.size() > kMaxCheckpoints) {  // every other one goes, its labels to the one before
        std::vector<ReadCheckpoint> kept;
        for (std::size_t i = 0; i < text.checkpoints.size(); ++i) {
          if (i % 2 == 0) {
            kept.push_back(text.checkpoints[i]);
          } else {
            kept.back().labels.sequences |= text.checkpoints[i].labels.sequences;
            kept.back().labels.programs |= text.checkpoints[i].labels.programs;
          }
        }
        text.checkpoints = std::move(kept);
        text.checkpointSpacing *= 2;
      }
    }
    LabelBits& labels = text.checkpoints.empty() ? text.headLabels : text.checkpoints.back().labels;
    if (block.sequenceNumber) labels.sequences |= labelBit(*block.sequenceNumber);
    if (block.programNumber) labels.programs |= labelBit(*block.programNumber);
  }
  text.blockCount = ordinal - first;
  if (readFor && text.blockCount > 0) {
    std::optional<std::size_t> start;
    scan(source, static_cast<std::size_t>(first), LabelFilter{{0, labelBit(*readFor)}, false}, [&](const ProgramBlock& block) {
      if (block.programNumber == *readFor) start = static_cast<std::size_t>(block.ordinal);
      return !start;
    });
    if (!start) {  // no O line for it: the file is the program; its blocks before any O block belong to it
      start = static_cast<std::size_t>(first);
      text.namedProgram = *readFor;
      text.leadingProgram = first;
      for (ReadCheckpoint& checkpoint : text.checkpoints)
        if (checkpoint.program < 0) checkpoint.program = first;
    }
    if (programStarts_.size() >= kMaxRememberedLabels) programStarts_.clear();
    programStarts_.emplace(*readFor, *start);
  }
  if (source != 0) return machineNotes;
  notes = reader.notes();
  notes.insert(notes.end(), machineNotes.begin(), machineNotes.end());
  if (const auto after = reader.textAfterClosing()) {
    textAfterEnd = Error{after->first, after->second,
                         fmt::format("the program ends at the % on line {}: this text after it is not run",
                                     reader.closingPercent()->first)};
  }
  return {};
}

Program readProgram(PagedText text, bool blockDelete, Dialect dialect, MachineMCodes machine) {
  return readProgram(text, blockDelete, dialect, machine, {});
}

Program readProgram(PagedText text, bool blockDelete, Dialect dialect, MachineMCodes machine,
                    const ToolBlockVisitor& toolBlocks) {
  Program program;
  program.sources.push_back({"", text, nullptr, blockDelete, dialect, machine});
  program.readThrough(0, std::nullopt, toolBlocks);
  return program;
}

std::vector<ReadNote> appendProgramFile(Program& program, const std::string& name, FileText text, int number,
                                        bool blockDelete, Dialect dialect, MachineMCodes machine) {
  auto file = std::make_shared<const FileText>(std::move(text));
  const PagedText paged = file->text();
  program.sources.push_back({name, paged, std::move(file), blockDelete, dialect, machine});
  return program.readThrough(static_cast<int>(program.sources.size()) - 1, number);
}

}  // namespace lathesim::interp
