#include "interp/text/block_parser.hpp"

#include <array>
#include <cmath>
#include <utility>

#include <fmt/format.h>

namespace lathesim::interp {
namespace {

// A G or M number: an integer written without a fractional part ("G1.5" is not a code).
std::optional<int> codeNumber(const Word& word) {
  if (word.value < 0 || word.value > 999 || std::floor(word.value) != word.value) {
    return std::nullopt;
  }
  return static_cast<int>(word.value);
}

std::string codeText(char letter, int number) { return fmt::format("{}{:02}", letter, number); }

// The cure of a G code `dialect` does not know: the dialects that read it, the first named
// with its flag ("G95 is feed per revolution in fanuc-b and hnc: run with --dialect fanuc-b"),
// or "" when none does.
std::string otherDialectsReading(int written, Dialect dialect) {
  std::string readers;
  const GCodeInfo* first = nullptr;
  Dialect firstDialect = dialect;
  for (Dialect other : kDialects) {
    const GCodeInfo* info = other == dialect ? nullptr : findGCode(written, other);
    if (info == nullptr || !info->supported) continue;
    readers += fmt::format("{}{}", readers.empty() ? "" : " and ", dialectName(other));
    if (first == nullptr) {
      first = info;
      firstDialect = other;
    }
  }
  if (first == nullptr) return "";
  return fmt::format("; {} is {} in {}: run with --dialect {}", codeText('G', written), first->meaning, readers,
                     dialectName(firstDialect));
}

// The cure of an M code `machine` does not list: the controls whose lists have it.
// A known, supported code, or the error saying why the word is not one. `info` is the table
// entry found for the word's number (nullptr when none); `known()` lists valid codes, only
// when needed: listing them walks the whole table, which every G word of a long program
// would pay for.
template <class Info, class ListKnown>
Result<Code> checkedCode(const Word& word, std::optional<int> written, int line, const Info* info,
                         const ListKnown& known, const std::string& cure = "") {
  if (info == nullptr) {
    return Error{line, word.column,
                 fmt::format("unknown {} code {}: expected one of {}{}", word.letter, word.text(), known(),
                             cure)};
  }
  const std::string text = codeText(word.letter, *written);
  if (!info->lacks.empty()) {
    return Error{line, word.column,
                 fmt::format("{} ({}) needs {}, which this lathe does not have: it turns with two "
                             "axes, X and Z, one spindle and a turret",
                             text, info->meaning, info->lacks)};
  }
  if (!info->supported) {
    return Error{line, word.column,
                 fmt::format("{} ({}) is not supported by lathesim yet", text, info->meaning)};
  }
  return Code{info->number, text, word.column};
}

// A second code of one group replaces the first (Fanuc: the last one wins), with a warning.
template <class Group>
void keepLast(std::map<Group, Code>& codes, Group group, const Code& code, ParsedBlock& block) {
  const auto [where, inserted] = codes.emplace(group, code);
  if (inserted) return;
  block.warnings.push_back({block.line, code.column,
                            fmt::format("{} and {} are both {} codes: the last, {}, is in force (as on a Fanuc); "
                                        "give one of them",
                                        where->second.text, code.text, groupName(group), code.text)});
  where->second = code;
}

}  // namespace

std::optional<Word> ParsedBlock::take(char letter) {
  const auto found = words.find(letter);
  if (found == words.end()) return std::nullopt;
  Word word = found->second;
  words.erase(found);
  return word;
}

std::optional<Code> ParsedBlock::gCode(GGroup group) const {
  const auto found = gCodes.find(group);
  if (found == gCodes.end()) return std::nullopt;
  return found->second;
}

std::optional<Code> ParsedBlock::mCode(MGroup group) const {
  const auto found = mCodes.find(group);
  if (found == mCodes.end()) return std::nullopt;
  return found->second;
}

Result<ParsedBlock> parseBlock(const std::vector<Word>& words, int line, int column, Dialect dialect,
                               MachineMCodes machine) {
  ParsedBlock block;
  block.line = line;
  block.column = column;
  for (const Word& word : words) {
    if (word.letter == 'G') {
      const auto number = codeNumber(word);
      const GCodeInfo* info = number ? findGCode(*number, dialect) : nullptr;
      auto code = checkedCode(
          word, number, line, info,
          [dialect] { return fmt::format("{} (dialect {})", supportedGCodes(dialect), dialectName(dialect)); },
          info == nullptr && number ? otherDialectsReading(*number, dialect) : "");
      if (!code.ok()) return code.error();
      keepLast(block.gCodes, info->group, code.value(), block);
    } else if (word.letter == 'M') {
      const auto number = codeNumber(word);
      if (const MachineMCode* own = number ? findMachineMCode(*number, machine) : nullptr) {
        block.machineCodes.push_back(Code{own->number, codeText('M', *number), word.column});
        continue;
      }
      const MCodeInfo* info = number ? findMCode(*number) : nullptr;
      auto code = checkedCode(word, number, line, info, [machine, number] {
        // The cure, where another control's table holds the code: that control's name, which is
        // both its m_codes table and its --control preset.
        std::string elsewhere;
        for (const MachineMCodes other : machineMCodeFamilies()) {
          const MachineMCode* theirs = number && other != machine ? findMachineMCode(*number, other) : nullptr;
          if (theirs == nullptr) continue;
          const std::string_view name = machineMCodeFamilyName(other);
          elsewhere += fmt::format("; the {} table has M{:02} ({}): set [control] m_codes = \"{}\", or run with --control {}",
                                   name, *number, theirs->meaning, name, name);
        }
        return fmt::format("{}, or a machine code of this control's table, m_codes = {} ({}){}", supportedMCodes(),
                           machineMCodeFamilyName(machine), machineMCodeList(machine),
                           elsewhere.empty() ? std::string("; no machine table lathesim has holds it") : elsewhere);
      });
      if (!code.ok()) return code.error();
      keepLast(block.mCodes, info->group, code.value(), block);
    } else {
      const auto [where, inserted] = block.words.emplace(word.letter, word);
      if (!inserted) {
        return Error{line, word.column,
                     fmt::format("{} is given twice in this block ({} and {}); give it once",
                                 word.letter, where->second.text(), word.text())};
      }
    }
  }
  return block;
}

}  // namespace lathesim::interp
