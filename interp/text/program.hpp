#pragma once
// The whole program text read into blocks before any runs, so that execution can jump:
// M98 to an O number, G70–G73 to the N numbers of their contour, GOTO and WHILE of Custom
// Macro B. Each block is tokenized and checked as it is read. A block of plain words keeps
// only where it starts in the text, and is read again each time it is asked for
// (Program::plainWords): holding every block's sorted words took ~600 B a block, 600 MB for a
// program of a million blocks. A block of Custom Macro B (a statement, an expression in an
// address, a G65 call) is kept as read, its words sorted each time it runs, since their values
// may change between runs. An error in a block is kept (by the block's ordinal, apart from the
// blocks, as comments are) and reported only if execution reaches it (text after M30 that
// never runs is never checked, as when the program was read block by block).

#include <cstddef>
#include <map>
#include <set>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "interp/macro/statement.hpp"
#include "interp/text/block_parser.hpp"
#include "interp/text/lexer.hpp"
#include "interp/result.hpp"

namespace lathesim::interp {

/// A block of plain words, read again from where it starts in its source when it runs.
struct PlainBlock {
  ReadPosition start;
};

/// A block with nothing to run: one block delete skips (never read), or one that cannot be read
/// (why: Program::errorOf).
struct UnreadBlock {};

/// What a block says: plain words, or a block of Custom Macro B (held apart, so that the many
/// plain blocks of a long program stay small).
using BlockContent = std::variant<UnreadBlock, PlainBlock, std::shared_ptr<const macro::MacroBlock>>;

/// What every block needs, kept for each of a program's blocks. What few blocks have, their
/// comments and the error of a block that cannot be read, the Program keeps apart by ordinal
/// (Program::commentsOf, Program::errorOf): with them inline a block took 168 B, 168 MB for a
/// program of a million blocks.
struct ProgramBlock {
  BlockContent content;   // what the block says
  int ordinal = 0;        // 0-based position among the blocks read: its index in Program::blocks
  int line = 0;           // 1-based line where the block starts
  int column = 0;         // 1-based column where the block starts
  // The file and the two flags share a word: a run reads one file a program number the text
  // lacks, and program numbers have at most 8 digits, so fewer than 10^8 + 1 < 2^30 files.
  unsigned source : 30 = 0;  // the file it is in: Program::sources (0: the program's own)
  bool deleted : 1 = false;  // it starts with '/'
  bool skipped : 1 = false;  // deleted while block delete is on: never runs, never checked
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

/// The comments of a block that has any.
struct BlockComments {
  int ordinal = 0;                 // the block's
  std::vector<std::string> own;    // its own comments (lexer.hpp: RawBlock)
  std::vector<std::string> above;  // comment-only lines directly above it
};

/// Why a block cannot run, reported only if execution reaches it.
struct BlockError {
  int ordinal = 0;  // the block's
  Error error;
};

/// A text the blocks were read from: the program's own (name empty) or a subprogram's file,
/// and how it was read. The program's own text is the caller's, read where it lies (a program
/// of a million blocks is 18 MB of text: held twice, it was 18 B a line more); a file M98
/// reads is held by the Program.
struct SourceText {
  std::string name;
  std::string_view text;                    // the program's own (readProgram), or *file
  std::shared_ptr<const std::string> file;  // a subprogram file's text; null for the program's own
  bool blockDelete = false;
  Dialect dialect = Dialect::FanucA;
  MachineMCodes machine = MachineMCodes::Gsk980tdi;
};

struct Program {
  std::vector<SourceText> sources;
  std::vector<ProgramBlock> blocks;
  std::map<int, std::size_t> programStart;  // O number → index of the first block with it
  std::vector<int> programOf;  // per block: the index of the O block it follows, −1 before any
  std::vector<ReadNote> notes;  // what the reader skipped (a tape leader, prose after ';')
  std::set<int> notedMachineCodes;  // machine M codes noted as ignored, in any of its files
  std::optional<Error> textAfterEnd;  // a warning at text after the closing '%', which never runs
  std::vector<BlockComments> comments;  // of the blocks that have any, by ordinal (commentsOf)
  std::vector<BlockError> errors;       // of the blocks that cannot be read, by ordinal (errorOf)

  /// The comments of `block`: empty for most blocks.
  const BlockComments& commentsOf(const ProgramBlock& block) const;
  /// Why `block` cannot run; nullptr for a block that reads or one block delete skips.
  const Error* errorOf(const ProgramBlock& block) const;

  /// The indices of the blocks numbered N`sequenceNumber` in the same program (between the
  /// same O blocks) as block `from`, in order.
  std::vector<std::size_t> findSequence(int sequenceNumber, std::size_t from) const;
  /// The O number of the program that block `index` belongs to, if it has one.
  std::optional<int> programNumberOf(std::size_t index) const;
  /// The words of `block` sorted into codes, read again from its source; nullopt unless it is
  /// a block of plain words that reads and is not skipped.
  std::optional<ParsedBlock> plainWords(const ProgramBlock& block) const;
};

/// Splits, tokenizes and sorts every block of `text`. Never fails: a block that cannot be read
/// carries its error; a comment left open ends the text with a block carrying that error. The
/// Program reads `text` again as it runs (Program::plainWords) and does not copy it: the caller
/// keeps `text` alive as long as the Program.
Program readProgram(std::string_view text, bool blockDelete, Dialect dialect,
                    MachineMCodes machine = MachineMCodes::Gsk980tdi);
/// A temporary string would be gone before the Program reads it again.
template <class Text>
  requires std::is_same_v<Text, std::string>
Program readProgram(Text&& text, bool blockDelete, Dialect dialect,
                    MachineMCodes machine = MachineMCodes::Gsk980tdi) = delete;

/// Reads the file `name` holding subprogram O`number` into `program` after its blocks. The
/// subprogram starts at the file's O`number` block, or at its first block when the file has
/// none (a file named for its program often leaves the O line out). Returns the notes of the
/// machine M codes the file names first (each code is noted once, in whichever file names it
/// first), located in the file.
std::vector<ReadNote> appendProgramFile(Program& program, const std::string& name, std::string text, int number,
                       bool blockDelete, Dialect dialect, MachineMCodes machine = MachineMCodes::Gsk980tdi);

}  // namespace lathesim::interp
