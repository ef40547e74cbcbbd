#pragma once
// Source text → blocks of tokens, each located by line and column (columns count UTF-8
// code points). Two stages, so a deleted block is skipped without being tokenized:
//   BlockReader::next()  splits the text at ';' and newlines, drops spaces, tabs and '%'
//                        lines, keeps ( ... ) comments aside, and notes a leading '/';
//   lexBlock()           turns a block's remaining characters into tokens: words like X20.0,
//                        and the pieces of Fanuc Custom Macro B (# [ ] = + - * / , numbers,
//                        and names such as SIN, GT, WHILE); tokenize() is the same for a
//                        block of plain words only.
// The lexer knows nothing of modal state.
//
// Text as shops and DNC links send it:
//   - Before the program's first block or '%' line, tape and DNC leftovers are skipped: control
//     characters (ESC, DC2, XON … any C0 code but tab and line ends, and DEL) and header lines
//     that start with '&' (`&HE:…`). Inside the program a control character is an error.
//   - `;` ends a block, as in the seeds (`G00 X42 Z0.5; G94 X25.5 Z-5 F100; Z-10;`). The rest
//     of its line is a comment instead when it reads as prose (`T0505 ;parting tool 3mm`):
//     when its first character cannot begin a block (anything but an ASCII letter and
//     # / : % [ ( ), or when its first letter is followed — spaces aside — by another letter,
//     as in words of prose but never in G-code (`X AXIS`, `turn od`). Macro statements are not
//     prose: IF or WHILE followed by '[', GOTO, END or DO followed by a number, '#' or '['.
//     A word followed by prose (`; M08 coolant on`) is not a comment: it is an error at the
//     first letter that is not a word.
//   - A line that opens with '[' is a school trainer's directive (`[BILLET X56.4 Z84`), not a
//     block: skipped with a note (setup/ reads the billet as the bar); a Macro B block never
//     opens with '['.
//   - A '%' line before the first block opens the program; one after it closes it: the text
//     ends there (what follows is not run, and the interpreter says so).
//   - A '/' inside a block marks where the optional block skip drops the rest of it (Fanuc ⚠),
//     but within a Macro B expression's [ ] or right of an assignment's '=' it divides
//     (`X[#1/2]`, `#1=#2/2`), as the Fanuc macro manual has it for a '/' in an expression.

#include <optional>
#include <utility>
#include <string>
#include <string_view>
#include <vector>

#include "interp/base/result.hpp"

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
  std::vector<std::string> comments;       // its ( … ) comments and a prose tail after its ';'
                                           // (#3000's alarm message is the first)
  std::vector<std::string> commentsAbove;  // comment-only lines directly above it
  std::optional<std::size_t> skipFrom;     // a '/' inside the block: the index into chars where
                                           // the words it skips start
  /// The first of its comments that holds a '(' (comments do not nest: the first ')' closes
  /// the comment, and a ')' meant for the outer one is then left over in the block).
  struct ParenInComment {
    int openColumn = 0;   // the comment's '('
    int innerColumn = 0;  // the '(' inside it
    int closeColumn = 0;  // the ')' that closed it
  };
  std::optional<ParenInComment> parenInComment;
};

/// Something the reader skipped that the user should know of, located like an error.
struct ReadNote {
  int line = 0;
  int column = 0;
  std::string message;
  bool warning = false;  // a warning rather than a note (a machine code that moves something)
};

/// A letter and its number: "X20 .0" is the word X20.0. Fanuc's comma words (",A-45.", ",C1.")
/// have the letter in lower case ('a'), so that they never meet the plain letter's word.
struct Word {
  char letter = 0;     // upper case; lower case for a comma word
  std::string number;  // as written without spaces, e.g. "-5.5", ".5", "0101"; for a value a
                       // macro expression gave, as the control reads it (macro/block_words.hpp)
  double value = 0.0;  // the number as read, in the program's units
  int column = 0;      // column of the letter (of the comma for a comma word)
  bool evaluated = false;  // the value came from a macro expression (X#1, X[#1+2]): Fanuc reads
                           // it as a real number, as if written with a decimal point
  std::string text() const {
    const bool comma = letter >= 'a' && letter <= 'z';
    return (comma ? std::string(",") + static_cast<char>(letter - 'a' + 'A') : std::string(1, letter)) + number;
  }
};

/// What a token of a block is. A plain G-code block is all Words; the rest belong to
/// Fanuc Custom Macro B.
enum class TokenKind {
  Word,     // a letter and its number, X20.0
  Address,  // a letter whose value follows as a macro expression: the X of X#1, X-#1, X[#1+2]
  Name,     // a macro keyword, function or operator: IF GOTO THEN WHILE DO END, SIN …, EQ …, AND …
  Number,   // a number inside a macro expression or statement: the 1 of #1, the 2.5 of #1=2.5
  Hash,     // #
  Open,     // [
  Close,    // ]
  Equals,   // =
  Plus,     // +
  Minus,    // -
  Times,    // *
  Divide,   // /
  Comma,    // , (POW[a,b], ATAN[a,b])
};

struct Token {
  TokenKind kind = TokenKind::Word;
  int column = 0;
  Word word;         // Word: the word; Address: the letter (word.letter) alone
  std::string text;  // as written: the upper-cased name, the number's digits, the character
  double value = 0.0;  // Number: its value
};

/// Where a BlockReader stood when it began a block: a reader started there reads that block
/// again (interp/text/program.hpp keeps this instead of the block's words).
struct ReadPosition {
  std::size_t at = 0;  // byte offset into the text
  int line = 1;
  int column = 1;
  bool inProgram = false;  // past the tape leader
};

/// Splits program text into blocks, one at a time, so nothing after M30 is ever read.
class BlockReader {
 public:
  explicit BlockReader(std::string_view text) : text_(text) {}
  /// Reads on from `from`, a blockStart() of a reader of the same text.
  BlockReader(std::string_view text, ReadPosition from)
      : text_(text), at_(from.at), line_(from.line), column_(from.column), atLineStart_(false),
        inProgram_(from.inProgram) {}

  /// Where the block next() returned last began.
  ReadPosition blockStart() const { return blockStart_; }

  /// The next block holding anything but spaces and comments; std::nullopt at the end.
  /// Fails on a comment that is not closed on its line.
  Result<std::optional<RawBlock>> next();

  /// What was skipped so far: the tape leader and the prose comments after ';'.
  std::vector<ReadNote> notes() const;

  /// Where the closing '%' is (line, column), and where the first text after it starts, if
  /// there is any (known once next() returned the end).
  std::optional<std::pair<int, int>> closingPercent() const { return closingPercent_; }
  std::optional<std::pair<int, int>> textAfterClosing() const { return textAfterClosing_; }

 private:
  bool skipPercentLine();  // at a line start: skips a '%' line, returns whether it did
  bool skipLeaderLine();   // before the program: skips an '&' header line
  bool skipDirectiveLine();  // a '[' line
  void noteLeaderControl(char c, int column);
  void advance(std::size_t bytes);  // within the line
  void endLine();                   // past the newline at at_
  void takeProseTail(RawBlock& block);
  void closeAt(std::size_t percent);  // the '%' at `percent` ends the program

  std::string_view text_;
  std::size_t at_ = 0;  // byte offset of the next character
  int line_ = 1;
  int column_ = 1;
  bool atLineStart_ = true;
  bool inProgram_ = false;  // a block or '%' line has been read: the leader is over
  bool readBlock_ = false;  // a block was returned: the next '%' closes the program
  ReadPosition blockStart_;
  std::optional<std::pair<int, int>> closingPercent_;
  std::optional<std::pair<int, int>> textAfterClosing_;
  std::vector<std::string> pendingAbove_;  // comment-only lines since the last block
  std::vector<std::string> leaderSkipped_;  // what the leader held, e.g. "ESC", "the line '&HE:1'"
  std::optional<ReadNote> leaderAt_;
  // The first ';' tail read as a comment and the first '[' line skipped, and how many there
  // were: a reader holds as much after a million of them as after one.
  std::optional<ReadNote> firstProse_;
  std::size_t prose_ = 0;
  std::optional<ReadNote> firstDirective_;
  std::size_t directives_ = 0;
};

/// The tokens of a block. Fails on an unexpected character, an unknown letter, a letter with
/// no number, or a malformed number such as "20.3.". A block holding G65 (a macro call) may
/// use every letter but G L N O P as an argument (A, B, Y …); others only the letters of lathe
/// G-code.
Result<std::vector<Token>> lexBlock(const RawBlock& block);

/// The words of a block of plain words; fails like lexBlock, and at the first token that is
/// not a word.
Result<std::vector<Word>> tokenize(const RawBlock& block);

}  // namespace lathesim::interp
