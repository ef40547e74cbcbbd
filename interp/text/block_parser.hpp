#pragma once
// Words → ParsedBlock: G and M codes sorted into their modal groups, every other word
// kept by letter. Checks what needs no modal state: unknown or unsupported codes, a letter
// given twice. Two codes of one group: the last is in force, as on a Fanuc, with a warning.
// Values stay in the program's units.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "interp/control/gcode_table.hpp"
#include "interp/control/machine_m_codes.hpp"
#include "interp/text/lexer.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp {

/// A G or M code: its meaning and how it was written.
struct Code {
  int number = 0;    // the system-A code it means (gcode_table.hpp)
  std::string text;  // as written, e.g. "G79" for fanuc-b's face cycle
  int column = 0;
};

struct ParsedBlock {
  int line = 0;
  int column = 0;  // where the block starts
  std::map<GGroup, Code> gCodes;
  std::map<MGroup, Code> mCodes;
  std::map<char, Word> words;  // every other word, at most one per letter
  std::vector<Code> machineCodes;  // the control's machine M codes (machine_m_codes.hpp): ignored
  std::vector<Error> warnings;  // what the block was read with but may not mean

  /// Removes and returns the word for `letter`. Execution takes each word it uses;
  /// whatever is left at the end was not used, and is an error.
  std::optional<Word> take(char letter);
  bool has(char letter) const { return words.count(letter) != 0; }
  std::optional<Code> gCode(GGroup group) const;
  std::optional<Code> mCode(MGroup group) const;
};

/// Sorts a tokenized block, reading its G codes as `dialect` writes them and its machine M
/// codes by `machine`'s list. `line` and `column` locate the block's start.
Result<ParsedBlock> parseBlock(const std::vector<Word>& words, int line, int column,
                               Dialect dialect = Dialect::FanucA,
                               MachineMCodes machine = MachineMCodes::Gsk980tdi);

}  // namespace lathesim::interp
