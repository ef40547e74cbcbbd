#pragma once
// A program as a control in DNC mode reads it: through a bounded window, never whole. A block
// is known by its ordinal (its 0-based place among the blocks of the program's text, then of
// each subprogram file in the order they were read) and found again where it starts in its
// source: the next block is read on from the last; a block further off is read on from the
// nearest of a bounded set of checkpoints (where a block starts, a line, a column). A jump
// searches the text for its label, as a control does: M98 for an O number (Program::
// programStart), GOTO, M99 P, M97 and the P…Q of G70–G73 for an N number in the same program
// (between the same O blocks: Program::findSequence); what a search found is remembered in a
// bounded table. Nothing is kept for every block: a million-block program holds what a
// thousand-block one does (Program::held).
//
// Each source is read through once when it is handed over (readProgram, appendProgramFile) to
// count its blocks, place the checkpoints and say what concerns the whole text: the notes of
// the tape leader and of prose after ';', the machine M codes ignored, text after the closing
// '%'. A block is read again, tokenized and checked each time it is reached: an error in it is
// reported only if execution reaches it (text after M30 that never runs is never checked). A
// block of Custom Macro B (a statement, an expression in an address, a G65 call) is kept as
// read, its words sorted each time it runs, since their values may change between runs.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "interp/text/statement.hpp"
#include "interp/text/block_parser.hpp"
#include "interp/text/file_text.hpp"
#include "interp/text/lexer.hpp"
#include "interp/base/paged_text.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp {

/// A block of plain words, read again from where it starts in its source when it runs.
struct PlainBlock {
  ReadPosition start;
};

/// A block with nothing to run: one block delete skips (never read), or one that cannot be read
/// (why: Program::errorOf).
struct UnreadBlock {};

/// What a block says: plain words, or a block of Custom Macro B.
using BlockContent = std::variant<UnreadBlock, PlainBlock, std::shared_ptr<const macro::MacroBlock>>;

/// A block as read from its source (Program::block).
struct ProgramBlock {
  BlockContent content;   // what the block says
  int ordinal = 0;        // 0-based position among the blocks of the program and its files
  int line = 0;           // 1-based line where the block starts
  int column = 0;         // 1-based column where the block starts
  int source = 0;         // the file it is in: Program::sources (0: the program's own)
  int program = -1;       // the ordinal of the O block it follows (the program it belongs to); −1 before any
  bool deleted = false;   // it starts with '/'
  bool skipped = false;   // deleted while block delete is on: never runs, never checked
  std::optional<int> sequenceNumber;  // its N word
  std::optional<int> programNumber;   // its O word: a program starts here

  /// Whether it is a block of plain words that reads (Program::plainWords gives them).
  bool plain() const { return std::holds_alternative<PlainBlock>(content); }
  /// The block of Custom Macro B; nullptr for a block of plain words or one not read.
  const macro::MacroBlock* macroBlock() const {
    const auto* held = std::get_if<std::shared_ptr<const macro::MacroBlock>>(&content);
    return held != nullptr ? held->get() : nullptr;
  }
};

/// The comments of a block.
struct BlockComments {
  std::vector<std::string> own;    // its own comments (lexer.hpp: RawBlock)
  std::vector<std::string> above;  // comment-only lines directly above it
};

/// The N and O numbers written in a run of blocks, each as one bit of 64 (labelBit): a search
/// for a label passes over the runs that cannot hold it without reading them.
struct LabelBits {
  std::uint64_t sequences = 0;
  std::uint64_t programs = 0;
};

/// Where a reader of a source stood at the start of one of its blocks: a reader started there
/// reads on as the one that passed it did.
struct ReadCheckpoint {
  int ordinal = 0;    // of the block starting there
  ReadPosition at;
  int program = -1;   // the program that block belongs to (ProgramBlock::program)
  LabelBits labels;   // of its blocks up to the next checkpoint
};

/// A text the blocks are read from: the program's own (name empty) or a subprogram's file,
/// and how it is read. The program's own text is the caller's; a file M98 reads is the
/// Program's. Each is read where it lies (paged_text.hpp: the readers say where they read).
struct SourceText {
  std::string name;
  PagedText text;                        // the program's own (readProgram), or *file's
  std::shared_ptr<const FileText> file;  // a subprogram file's text; null for the program's own
  bool blockDelete = false;
  Dialect dialect = Dialect::FanucA;
  MachineMCodes machine = MachineMCodes::Gsk980tdi;
  // Found when it was read through once:
  int firstOrdinal = 0;  // of its first block
  int blockCount = 0;
  int leadingProgram = -1;  // the program its blocks before any O block belong to
  std::optional<int> namedProgram;  // a file without an O line for the program it was read for
  LabelBits headLabels;  // of its blocks before the first checkpoint
  std::vector<ReadCheckpoint> checkpoints;  // in order, at most kMaxCheckpoints
  int checkpointSpacing = 0;                // blocks at least between two checkpoints
};

/// A block read, with what only reading it tells.
struct ReadBlock {
  ProgramBlock block;
  BlockComments comments;
  std::optional<Error> error;        // why it cannot run
  std::optional<ParsedBlock> words;  // of a block of plain words
  bool endsText = false;             // a comment left open: nothing after it is read
};

/// Told of each block of plain words that holds a T word and has comments (its own or comment
/// lines directly above it), in order, as the program's own text is read through (readProgram):
/// what a reader of the tools named in comments needs, without a pass of its own.
using ToolBlockVisitor = std::function<void(const ReadBlock&)>;

/// How many blocks of one program an N number labels, and the first two of them.
struct SequenceBlocks {
  std::size_t count = 0;
  std::size_t first = 0;   // when count ≥ 1
  std::size_t second = 0;  // when count ≥ 2
};

class Program {
 public:
  /// The bounds of what a Program holds, whatever the length of its text.
  static constexpr std::size_t kWindowBlocks = 1024;     // blocks read last, held as read
  static constexpr std::size_t kMaxCheckpoints = 1024;   // a source's checkpoints
  static constexpr std::size_t kMaxRememberedLabels = 4096;  // N numbers and O numbers found
  static constexpr std::size_t kRecentReaders = 16;  // readers where jumps left and landed

  std::vector<SourceText> sources;
  std::vector<ReadNote> notes;  // what the reader skipped (a tape leader, prose after ';')
  std::set<int> notedMachineCodes;  // machine M codes noted as ignored, in any of its files
  std::optional<Error> textAfterEnd;  // a warning at text after the closing '%', which never runs
  std::size_t loopBlocks = 0;  // blocks of DO or END, in all its sources (macro/loop_pairs.hpp)

  /// How many blocks its sources hold.
  std::size_t blockCount() const;
  /// Block `ordinal` (< blockCount()), read from its source.
  ProgramBlock block(std::size_t ordinal) const;
  /// The comments of `block`: empty for most blocks.
  const BlockComments& commentsOf(const ProgramBlock& block) const;
  /// Why `block` cannot run; nullptr for a block that reads or one block delete skips. Valid
  /// until the next block is asked for.
  const Error* errorOf(const ProgramBlock& block) const;
  /// The words of `block` sorted into codes; nullopt unless it is a block of plain words that
  /// reads and is not skipped.
  std::optional<ParsedBlock> plainWords(const ProgramBlock& block) const;

  /// The blocks numbered N`sequenceNumber` in the same program (between the same O blocks) as
  /// block `from`.
  SequenceBlocks findSequence(int sequenceNumber, std::size_t from) const;
  /// The first block O`number` of its sources (or the first block of a file read for it that
  /// has no O line for it), if any.
  std::optional<std::size_t> programStart(int number) const;
  /// The O number of the program that block `index` belongs to, if it has one.
  std::optional<int> programNumberOf(std::size_t index) const;

  /// What it holds now, to check that it stays bounded.
  struct Held {
    std::size_t windowBlocks = 0;
    std::size_t checkpoints = 0;
    std::size_t rememberedLabels = 0;
    std::size_t recentReaders = 0;
  };
  Held held() const;

  /// Reads source `source`, the last of `sources`, through once (readProgram and
  /// appendProgramFile call it; `readFor`: the program number a file was read for; `toolBlocks`,
  /// when set, told of its blocks with a T word and comments); returns the notes of the
  /// machine M codes it names first.
  std::vector<ReadNote> readThrough(int source, std::optional<int> readFor = std::nullopt,
                                    const ToolBlockVisitor& toolBlocks = {});

 private:
  // A reader of one source, about to read block `next`.
  struct Cursor {
    int source = 0;
    BlockReader reader;
    int next = 0;
    int program = -1;
  };

  int sourceOf(std::size_t ordinal) const;
  Cursor cursorBefore(int source, std::size_t ordinal) const;
  const ReadBlock& entry(std::size_t ordinal) const;
  void rememberReader(Cursor cursor) const;
  // Which runs of blocks a search reads: those that may hold one of these labels.
  struct LabelFilter {
    LabelBits wanted;
    bool everyProgram = false;  // and those holding any O block (where a program ends)
    bool mayHold(const LabelBits& labels) const {
      return (labels.sequences & wanted.sequences) != 0 || (labels.programs & wanted.programs) != 0 ||
             (everyProgram && labels.programs != 0);
    }
  };
  template <class Visit>
  void scan(int source, std::size_t from, const LabelFilter& filter, Visit visit) const;

  mutable std::deque<ReadBlock> window_;  // consecutive blocks, read last; cursor_ reads on after them
  mutable std::optional<Cursor> cursor_;
  // Readers as they stood where a jump left the window and where it landed: the block after an
  // M98 is read on from where the call left, a subprogram or a loop started again from where
  // it first began, with nothing read twice.
  mutable std::deque<Cursor> recent_;
  mutable std::map<std::pair<int, int>, SequenceBlocks> sequences_;  // (program, N) → blocks found
  mutable std::map<int, std::size_t> programStarts_;                // O number → its block
};

/// Reads `text` through once (see above). Never fails: a block that cannot be read carries its
/// error; a comment left open ends the text with a block carrying that error. The Program
/// reads `text` again as it runs and does not copy it: the caller keeps `text` alive as long
/// as the Program.
Program readProgram(PagedText text, bool blockDelete, Dialect dialect,
                    MachineMCodes machine = MachineMCodes::Gsk980tdi);
/// The same, telling `toolBlocks` of the blocks with a T word and comments as it reads through.
Program readProgram(PagedText text, bool blockDelete, Dialect dialect, MachineMCodes machine,
                    const ToolBlockVisitor& toolBlocks);
/// A temporary string would be gone before the Program reads it again.
template <class Text>
  requires std::is_same_v<Text, std::string>
Program readProgram(Text&& text, bool blockDelete, Dialect dialect,
                    MachineMCodes machine = MachineMCodes::Gsk980tdi) = delete;

/// Adds the file `name` holding subprogram O`number` to `program`, its blocks after the others.
/// The subprogram starts at the file's O`number` block, or at its first block when the file
/// has none (a file named for its program often leaves the O line out). Returns the notes of
/// the machine M codes the file names first (each code is noted once, in whichever file names
/// it first), located in the file.
std::vector<ReadNote> appendProgramFile(Program& program, const std::string& name, FileText text, int number,
                       bool blockDelete, Dialect dialect, MachineMCodes machine = MachineMCodes::Gsk980tdi);

}  // namespace lathesim::interp
