#include "interp/macro/macro_call.hpp"

#include <array>
#include <cmath>
#include <optional>
#include <string>

#include <fmt/format.h>

namespace lathesim::interp::macro {
namespace {

constexpr int kMacroCallCode = 65;
constexpr int kMaxProgramNumber = 9999;
constexpr int kMaxArgumentSets = 10;  // argument specification II: I1 J1 K1 … I10 J10 K10

// Argument specification I: the variable each letter sets, 0 for a letter that is no argument.
constexpr std::array<int, 26> kArgumentVariable{
    1,  2,  3,  7,  8,  9,  0,  11, 4,  5,  6,  0,  13,  // A B C D E F G H I J K L M
    0,  0,  0,  17, 18, 19, 20, 21, 22, 23, 24, 25, 26,  // N O P Q R S T U V W X Y Z
};

bool isWholeNumber(const Word& word) { return std::floor(word.value) == word.value; }

Result<int> wholeNumberIn(const Word& word, int from, int to, int line, std::string_view meaning) {
  if (!isWholeNumber(word) || word.value < from || word.value > to) {
    return Error{line, word.column,
                 fmt::format("{} is not {}: expected a whole number from {} to {}", word.text(), meaning, from, to)};
  }
  return static_cast<int>(word.value);
}

}  // namespace

Result<MacroCall> readMacroCall(const std::vector<Word>& words, int line) {
  MacroCall call;
  std::optional<Word> p;
  std::optional<Word> l;
  std::array<std::optional<Word>, 26> given;  // argument-specification-I letters already given
  int set = -1;                               // the I J K set being filled
  int lastPosition = 3;                       // I 0, J 1, K 2 of the last I J K word
  int g65Column = 0;
  for (const Word& word : words) {
    switch (word.letter) {
      case 'G':
        if (word.value == kMacroCallCode && g65Column == 0) {
          g65Column = word.column;
          continue;
        }
        return Error{line, word.column,
                     fmt::format("{} in a G65 block: a macro call takes only P, L and arguments; give {} in a "
                                 "block of its own",
                                 word.text(), word.text())};
      case 'N': continue;
      case 'O':
        return Error{line, word.column, fmt::format("{} in a G65 block: O starts a program; G65 calls one with P", word.text())};
      case 'P':
      case 'L': {
        std::optional<Word>& slot = word.letter == 'P' ? p : l;
        if (slot) {
          return Error{line, word.column,
                       fmt::format("{} is given twice in this G65 block ({} and {}); give it once", word.letter,
                                   slot->text(), word.text())};
        }
        slot = word;
        continue;
      }
      default: break;
    }
    if (word.letter < 'A' || word.letter > 'Z') {  // a comma word (",A30."): its letter is kept in lower case
      return Error{line, word.column,
                   fmt::format("'{}' in a G65 block: a macro call's arguments are letters and numbers one after "
                               "another, with no comma between them (D40 A30.)",
                               word.text())};
    }
    const int letterIndex = word.letter - 'A';
    if (word.letter == 'I' || word.letter == 'J' || word.letter == 'K') {
      const int position = word.letter - 'I';
      if (position <= lastPosition) ++set;
      lastPosition = position;
      if (set >= kMaxArgumentSets) {
        return Error{line, word.column,
                     fmt::format("{}: a macro call takes at most {} sets of I J K (#4 to #33)", word.text(),
                                 kMaxArgumentSets)};
      }
      call.arguments[static_cast<std::size_t>(3 + set * 3 + position)] = word.value;
      continue;
    }
    std::optional<Word>& earlier = given[static_cast<std::size_t>(letterIndex)];
    if (earlier) {
      return Error{line, word.column,
                   fmt::format("{} is given twice in this G65 block ({} and {}); give each argument once",
                               word.letter, earlier->text(), word.text())};
    }
    earlier = word;
    call.arguments[static_cast<std::size_t>(kArgumentVariable[static_cast<std::size_t>(letterIndex)] - 1)] = word.value;
  }
  if (!p) {
    return Error{line, g65Column, "G65 needs P: the number of the macro program to call (G65 P9010 calls O9010)"};
  }
  auto program = wholeNumberIn(*p, 1, kMaxProgramNumber, line, "a program number");
  if (!program.ok()) return program.error();
  call.programNumber = program.value();
  call.column = p->column;
  if (l) {
    auto repeats = wholeNumberIn(*l, 1, kMaxMacroRepeats, line, "a repeat count");
    if (!repeats.ok()) return repeats.error();
    call.repeats = repeats.value();
  }
  return call;
}

}  // namespace lathesim::interp::macro
