#include "interp/text/tool_word.hpp"

#include <array>
#include <string_view>

#include <fmt/format.h>

namespace lathesim::interp {
namespace {

struct ToolWordForm {
  std::string_view name;
  std::size_t toolDigits;
  std::size_t offsetDigits;
  std::string_view example;
  bool shortIsTool = false;  // a word no longer than the offset digits names the tool and its
                             // own offset (Haas: T1 is tool 1 with offset 1), not an offset
};

constexpr std::array kForms{ToolWordForm{"2+2", 2, 2, "T0101"}, ToolWordForm{"3+3", 3, 3, "T001001"},
                            ToolWordForm{"haas", 2, 2, "T101 or T1", true}};

const ToolWordForm* formNamed(std::string_view name) {
  for (const ToolWordForm& form : kForms)
    if (form.name == name) return &form;
  return nullptr;
}

}  // namespace

Result<ToolWord> readToolWord(const Word& word, const std::vector<std::string>& forms, int line,
                              bool besideToolChange) {
  const std::string& digits = word.number;
  const bool integral = !digits.empty() && digits.find_first_not_of("0123456789") == std::string::npos;
  std::string expected;
  for (const std::string& name : forms) {
    const ToolWordForm* form = formNamed(name);
    if (form == nullptr) continue;
    expected += fmt::format("{}{} digits of tool and {} of offset ({})", expected.empty() ? "" : ", or ",
                            form->toolDigits, form->offsetDigits, form->example);
    if (!integral || digits.size() > form->toolDigits + form->offsetDigits) continue;
    const std::size_t split = digits.size() > form->offsetDigits ? digits.size() - form->offsetDigits : 0;
    ToolWord read;
    read.tool = split == 0 ? 0 : std::stoi(digits.substr(0, split));
    read.offset = std::stoi(digits.substr(split));
    if (split == 0 && read.offset != 0 && besideToolChange) {
      read.tool = read.offset;
      return read;
    }
    if (split == 0 && read.offset != 0 && form->shortIsTool) {
      read.tool = read.offset;
      read.note = fmt::format("{} is read as tool {} with offset {}, as a Haas control reads a short T word ({})",
                              word.text(), read.tool, read.offset,
                              fmt::format("T{}{:0{}}", read.tool, read.offset, form->offsetDigits));
      return read;
    }
    // T0 and T00 cancel the offset (common); T1 or T12 would pick an offset of the tool in place,
    // which a program meaning "tool 1" (as Haas reads T1) does not intend.
    if (split == 0 && read.offset != 0) {
      read.note = fmt::format("{} is read as offset {} of the tool in place (no tool change): the last {} digits of "
                              "a T word are the offset; write {} for tool and offset",
                              word.text(), read.offset, form->offsetDigits,
                              fmt::format("T{:0{}}{:0{}}", read.offset, form->toolDigits, read.offset, form->offsetDigits));
    }
    return read;
  }
  return Error{line, word.column,
               fmt::format("{} is not a tool word of this control: expected {}", word.text(), expected)};
}

}  // namespace lathesim::interp
