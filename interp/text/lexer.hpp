#pragma once
// Source text → blocks of words, each located by line and column (columns count UTF-8
// code points). Two stages, so a deleted block is skipped without being tokenized:
//   BlockReader::next()  splits the text at ';' and newlines, drops spaces, tabs,
//                        ( ... ) comments and '%' lines, and notes a leading '/';
//   tokenize()           turns a block's remaining characters into words like X20.0.
// The lexer knows nothing of modal state.

#include <optional>
#include <utility>
#include <string>
#include <string_view>
#include <vector>

#include "interp/result.hpp"

namespace lathesim::interp {

/// One significant character of a block (a whole code point), with its column.
struct SourceChar {
  std::string text;  // one code point, usually a single ASCII byte
  int column = 0;    // 1-based, in code points
};

/// A block as written, minus spaces and comments.
struct RawBlock {
  int line = 0;          // 1-based line of the block
  int column = 0;        // 1-based column of its first significant character
  bool deleted = false;  // it started with '/' (block delete)
  std::vector<SourceChar> chars;  // everything after the '/', spaces and comments removed
  // A '/' inside the block (Fanuc's optional block skip mid-block ⚠): the index into chars where
  // the words it skips start; with block skip on, they are dropped.
  std::optional<std::size_t> skipFrom;
};

/// A letter and its number: "X20 .0" is the word X20.0. Fanuc's comma words (",A-45.", ",C1.")
/// have the letter in lower case ('a'), so that they never meet the plain letter's word.
struct Word {
  char letter = 0;     // upper case; lower case for a comma word
  std::string number;  // as written without spaces, e.g. "-5.5", ".5", "0101"
  double value = 0.0;  // the number as read, in the program's units
  int column = 0;      // column of the letter (of the comma for a comma word)
  std::string text() const {
    const bool comma = letter >= 'a' && letter <= 'z';
    return (comma ? std::string(",") + static_cast<char>(letter - 'a' + 'A') : std::string(1, letter)) + number;
  }
};

/// Splits program text into blocks, one at a time, so nothing after M30 is ever read. A '%'
/// line before the first block opens the program; one after it closes it: the text ends there.
class BlockReader {
 public:
  explicit BlockReader(std::string_view text) : text_(text) {}

  /// The next block holding anything but spaces and comments; std::nullopt at the end.
  /// Fails on a comment that is not closed on its line.
  Result<std::optional<RawBlock>> next();

  /// Where the closing '%' is (line, column), and where the first text after it starts, if
  /// there is any (known once next() returned the end).
  std::optional<std::pair<int, int>> closingPercent() const { return closingPercent_; }
  std::optional<std::pair<int, int>> textAfterClosing() const { return textAfterClosing_; }

 private:
  bool skipPercentLine();  // at a line start: skips a '%' line, returns whether it did
  void closeAt(std::size_t percent);  // the '%' at `percent` ends the program

  std::string_view text_;
  std::size_t at_ = 0;  // byte offset of the next character
  int line_ = 1;
  int column_ = 1;
  bool atLineStart_ = true;
  bool readBlock_ = false;  // a block was returned: the next '%' closes the program
  std::optional<std::pair<int, int>> closingPercent_;
  std::optional<std::pair<int, int>> textAfterClosing_;
};

/// The words of a block. Fails on an unexpected character, an unknown letter, a letter
/// with no number, or a malformed number such as "20.3.".
Result<std::vector<Word>> tokenize(const RawBlock& block);

}  // namespace lathesim::interp
