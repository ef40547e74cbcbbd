#pragma once
// The whole program text read into blocks before any runs, so that execution can jump:
// M98 to an O number, G70–G73 to the N numbers of their contour, GOTO and WHILE of Custom
// Macro B. Each block is tokenized as it is read; a block of plain words is sorted into codes
// then, a block of Custom Macro B (a statement, an expression in an address, a G65 call) is
// kept as read, its words sorted each time it runs, since their values may change between
// runs. An error in a block is kept with the block and reported only if execution reaches it
// (text after M30 that never runs is never checked, as when the program was read block by
// block).

#include <cstddef>
#include <map>
#include <set>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "interp/macro/statement.hpp"
#include "interp/text/block_parser.hpp"
#include "interp/result.hpp"

namespace lathesim::interp {

/// What a block says: plain words sorted into codes, or a block of Custom Macro B (held apart,
/// so that the many plain blocks of a long program stay small).
using BlockContent = std::variant<ParsedBlock, std::shared_ptr<const macro::MacroBlock>>;

struct ProgramBlock {
  int ordinal = 0;        // 0-based position among the blocks read
  int source = 0;         // the file it is in: Program::sources (0: the program's own)
  int line = 0;           // 1-based line where the block starts
  int column = 0;         // 1-based column where the block starts
  bool deleted = false;   // it starts with '/'
  bool skipped = false;   // deleted while block delete is on: never runs, never checked
  std::optional<int> sequenceNumber;  // its N word
  std::optional<int> programNumber;   // its O word: a program starts here
  std::vector<std::string> comments;       // its own comments (lexer.hpp: RawBlock)
  std::vector<std::string> commentsAbove;  // comment-only lines directly above it
  Result<BlockContent> content = Error{};  // what the block says, or why it cannot run

  /// The sorted words of a block of plain words; nullptr for a macro block or a bad one.
  const ParsedBlock* plainWords() const {
    return content.ok() ? std::get_if<ParsedBlock>(&content.value()) : nullptr;
  }
  /// The block of Custom Macro B; nullptr for a block of plain words or a bad one.
  const macro::MacroBlock* macroBlock() const {
    if (!content.ok()) return nullptr;
    const auto* held = std::get_if<std::shared_ptr<const macro::MacroBlock>>(&content.value());
    return held != nullptr ? held->get() : nullptr;
  }
};

/// A text the blocks were read from: the program's own (name empty) or a subprogram's file.
struct SourceText {
  std::string name;
  std::string text;
};

struct Program {
  std::vector<SourceText> sources;
  std::vector<ProgramBlock> blocks;
  std::map<int, std::size_t> programStart;  // O number → index of the first block with it
  std::vector<int> programOf;  // per block: the index of the O block it follows, −1 before any
  std::vector<ReadNote> notes;  // what the reader skipped (a tape leader, prose after ';')
  std::set<int> notedMachineCodes;  // machine M codes noted as ignored, in any of its files
  std::optional<Error> textAfterEnd;  // a warning at text after the closing '%', which never runs

  /// The indices of the blocks numbered N`sequenceNumber` in the same program (between the
  /// same O blocks) as block `from`, in order.
  std::vector<std::size_t> findSequence(int sequenceNumber, std::size_t from) const;
  /// The O number of the program that block `index` belongs to, if it has one.
  std::optional<int> programNumberOf(std::size_t index) const;
};

/// Splits, tokenizes and sorts every block of `text`. Never fails: a block that cannot be read
/// carries its error; a comment left open ends the text with a block carrying that error.
Program readProgram(std::string_view text, bool blockDelete, Dialect dialect,
                    MachineMCodes machine = MachineMCodes::Gsk980tdi);

/// Reads the file `name` holding subprogram O`number` into `program` after its blocks. The
/// subprogram starts at the file's O`number` block, or at its first block when the file has
/// none (a file named for its program often leaves the O line out). Returns the notes of the
/// machine M codes the file names first (each code is noted once, in whichever file names it
/// first), located in the file.
std::vector<ReadNote> appendProgramFile(Program& program, const std::string& name, std::string_view text, int number,
                       bool blockDelete, Dialect dialect, MachineMCodes machine = MachineMCodes::Gsk980tdi);

}  // namespace lathesim::interp
