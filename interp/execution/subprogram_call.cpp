#include "interp/execution/subprogram_call.hpp"

#include <string>

#include <fmt/format.h>

#include "interp/text/label_number.hpp"

namespace lathesim::interp {
namespace {

constexpr int kProgramNumberDigits = 4;  // P's last four digits name the program
constexpr int kMaxRepeats = 9999;

bool isPlainInteger(const Word& word) {
  return !word.number.empty() && word.number.find_first_not_of("0123456789") == std::string::npos;
}

// L, the repeat count: 1 when absent.
Result<int> repeatsOf(const std::optional<Word>& l, int line) {
  if (!l) return 1;
  if (const std::string slip = decimalPointSlip(*l); !slip.empty())
    return Error{line, l->column, fmt::format("{} is not a repeat count: {}", l->text(), slip)};
  if (!isPlainInteger(*l) || l->value < 1 || l->value > kMaxRepeats) {
    return Error{line, l->column,
                 fmt::format("{} is not a repeat count: expected a whole number from 1 to {}", l->text(), kMaxRepeats)};
  }
  return static_cast<int>(l->value);
}

}  // namespace

Result<SubprogramCall> takeSubprogramCall(ParsedBlock& block, const Code& m98) {
  const auto p = block.take('P');
  const auto l = block.take('L');
  if (!p) {
    return Error{block.line, m98.column,
                 "M98 needs P: the program number (P1000 calls O1000; P31000 calls it 3 times)"};
  }
  if (const std::string slip = decimalPointSlip(*p); !slip.empty())
    return Error{block.line, p->column, fmt::format("{} is not a program number: {}", p->text(), slip)};
  if (!isPlainInteger(*p)) {
    return Error{block.line, p->column,
                 fmt::format("{} is not a program number: expected digits only, e.g. P1000 "
                             "(O1000) or P31000 (O1000 three times)",
                             p->text())};
  }
  SubprogramCall call;
  call.column = p->column;
  const std::string& digits = p->number;
  const bool countInP = static_cast<int>(digits.size()) > kProgramNumberDigits;
  const std::size_t split = countInP ? digits.size() - kProgramNumberDigits : 0;
  call.programNumber = std::stoi(digits.substr(split));
  if (countInP) {
    if (digits.size() - kProgramNumberDigits > 4 || std::stoi(digits.substr(0, split)) == 0) {
      return Error{block.line, p->column,
                   fmt::format("{}: the digits before the four-digit program number are the "
                               "repeat count, expected 1 to {}",
                               p->text(), kMaxRepeats)};
    }
    call.repeats = std::stoi(digits.substr(0, split));
  }
  if (l && countInP) {
    return Error{block.line, l->column,
                 fmt::format("{} and {} both give the repeat count; give it once", p->text(), l->text())};
  }
  auto repeats = repeatsOf(l, block.line);
  if (!repeats.ok()) return repeats.error();
  if (l) call.repeats = repeats.value();
  return call;
}

Result<SubprogramCall> takeLocalSubprogramCall(ParsedBlock& block, const Code& m97) {
  const auto p = block.take('P');
  if (!p) return Error{block.line, m97.column, "M97 needs P: the N number where the local subprogram starts (M97 P100)"};
  auto sequence = labelNumberOf(*p, block.line, kMaxSequenceDigits, "a sequence number to call");
  if (!sequence.ok()) return sequence.error();
  auto repeats = repeatsOf(block.take('L'), block.line);
  if (!repeats.ok()) return repeats.error();
  return SubprogramCall{sequence.value(), repeats.value(), p->column, true};
}

}  // namespace lathesim::interp
