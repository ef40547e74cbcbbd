#pragma once
// The T word as the control reads it (control parameter tool_word, a list of forms tried in
// order; the first whose digit count fits reads the word):
//   "2+2"  up to four digits: the last two the offset, the rest the tool. T0101 and T101 are
//          tool 1 with offset 1, T0 and T00 offset 0 (the offset cancelled) with no tool change
//   "3+3"  up to six digits: the last three the offset, T001001
//   "haas" as "2+2", but one or two digits name the tool with its own offset: T1 is T101
// Tool 0 changes no tool: the one mounted stays. A word with a sign, a point or more digits than
// every form holds (T01001 under "2+2") fits none and is an error, never a tool read wrongly.

#include <optional>
#include <string>
#include <vector>

#include "interp/base/result.hpp"
#include "interp/text/lexer.hpp"

namespace lathesim::interp {

struct ToolWord {
  int tool = 0;    // 0: no tool change
  int offset = 0;  // 0: no offset
  std::optional<std::string> note;  // a short form read by the rule, worth a warning
};

/// Reads T `word` of the block on `line` by `forms`. `besideToolChange`: the block holds M06,
/// so a word no longer than the offset digits names the tool and its own offset, as the
/// trainers read it (M06 T01 is tool 1 with offset 1), without a note.
Result<ToolWord> readToolWord(const Word& word, const std::vector<std::string>& forms, int line,
                              bool besideToolChange = false);

}  // namespace lathesim::interp
