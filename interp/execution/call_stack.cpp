#include "interp/execution/call_stack.hpp"

#include <string>

#include <fmt/format.h>

namespace lathesim::interp {
namespace {

std::string programName(int number) { return fmt::format("O{:04}", number); }

}  // namespace

Result<std::size_t> CallStack::call(const SubprogramCall& call, std::size_t index) {
  const int line = program_.blocks[index].line;
  const auto start = program_.programStart.find(call.programNumber);
  if (start == program_.programStart.end()) {
    return Error{line, call.column,
                 fmt::format("M98 calls {} but the program has no block O{}: a subprogram "
                             "starts with its O number and ends with M99",
                             programName(call.programNumber), call.programNumber)};
  }
  // The chain of programs running: the main program's own O number if it has one, then
  // every subprogram called.
  std::vector<int> chain;
  if (const auto main = program_.programNumberOf(0)) chain.push_back(*main);
  for (const Frame& frame : frames_) chain.push_back(frame.programNumber);
  bool recursive = false;
  std::string shown;
  for (int number : chain) {
    recursive = recursive || number == call.programNumber;
    shown += programName(number) + " → ";
  }
  if (recursive) {
    return Error{line, call.column,
                 fmt::format("M98 calls {} while it is already running ({}{}): a subprogram "
                             "may not call itself, directly or through others",
                             programName(call.programNumber), shown,
                             programName(call.programNumber))};
  }
  if (static_cast<int>(frames_.size()) >= kMaxSubprogramNesting) {
    return Error{line, call.column,
                 fmt::format("M98 calls {} from {} levels of subprograms ({}{}): the control "
                             "nests at most {} levels",
                             programName(call.programNumber), frames_.size(), shown,
                             programName(call.programNumber), kMaxSubprogramNesting)};
  }
  frames_.push_back({call.programNumber, start->second, index, call.column, call.repeats - 1});
  return start->second;
}

Result<std::size_t> CallStack::giveBack(const SubprogramReturn& giveBack, std::size_t index) {
  Frame& frame = frames_.back();
  if (frame.repeatsLeft > 0) {
    --frame.repeatsLeft;
    return frame.start;
  }
  std::size_t next = frame.callFrom + 1;
  if (giveBack.sequence) {
    const std::vector<std::size_t> found = program_.findSequence(*giveBack.sequence, frame.callFrom);
    if (found.empty()) {
      return Error{program_.blocks[index].line, giveBack.sequenceColumn,
                   fmt::format("M99 P{0} returns to N{0} of the calling program, which has no block N{0}",
                               *giveBack.sequence)};
    }
    next = found.front();
  }
  frames_.pop_back();
  return next;
}

std::optional<Error> CallStack::unfinished() const {
  if (frames_.empty()) return std::nullopt;
  const Frame& frame = frames_.back();
  return Error{program_.blocks[frame.callFrom].line, frame.column,
               fmt::format("{} called here has no M99: the program text ends inside it",
                           programName(frame.programNumber))};
}

}  // namespace lathesim::interp
