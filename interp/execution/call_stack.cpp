#include "interp/execution/call_stack.hpp"

#include <algorithm>
#include <string>

#include <fmt/format.h>

namespace lathesim::interp {
namespace {

std::string programName(int number) { return fmt::format("O{:04}", number); }
std::string localName(int sequence) { return fmt::format("N{}", sequence); }

}  // namespace

Result<std::size_t> CallStack::programStart(int programNumber, const char* code, int column,
                                            std::size_t index) const {
  const auto start = program_.programStart(programNumber);
  if (!start) {
    return Error{program_.block(index).line, column,
                 fmt::format("{} calls {} but the program has no block O{}: a {} starts with its O "
                             "number and ends with M99",
                             code, programName(programNumber), programNumber,
                             std::string(code) == "G65" ? "macro" : "subprogram")};
  }
  return *start;
}

// M97's target: the one block N… of the program the call is in.
Result<std::size_t> CallStack::localStart(const SubprogramCall& call, std::size_t index) const {
  const SequenceBlocks found = program_.findSequence(call.programNumber, index);
  if (found.count == 1) return found.first;
  return Error{program_.block(index).line, call.column,
               found.count == 0 ? fmt::format("M97 calls N{0} but this program has no block N{0}: a local subprogram "
                                           "starts at its N number and ends with M99",
                                           call.programNumber)
                             : fmt::format("M97 calls N{0} but this program has {1} blocks N{0} (lines {2} and {3})",
                                           call.programNumber, found.count, program_.block(found.first).line,
                                           program_.block(found.second).line)};
}

std::string CallStack::chainTo(const std::string& called) const {
  std::string shown;
  if (const auto main = program_.programNumberOf(0)) shown += programName(*main) + " → ";
  for (const Frame& frame : frames_)
    shown += (frame.local ? localName(frame.programNumber) : programName(frame.programNumber)) + " → ";
  return shown + called;
}

int CallStack::framesOfKind(bool macro) const {
  return static_cast<int>(std::count_if(frames_.begin(), frames_.end(),
                                        [macro](const Frame& frame) { return frame.macro == macro; }));
}

Result<std::size_t> CallStack::call(const SubprogramCall& call, std::size_t index) {
  const int line = program_.block(index).line;
  const char* code = call.local ? "M97" : "M98";
  auto start = call.local ? localStart(call, index) : programStart(call.programNumber, code, call.column, index);
  if (!start.ok()) return start;
  const std::string called = call.local ? localName(call.programNumber) : programName(call.programNumber);
  // The chain of programs running: the main program's own O number if it has one, then
  // every subprogram and macro called.
  bool recursive = !call.local && program_.programNumberOf(0) == call.programNumber;
  for (const Frame& frame : frames_)
    recursive = recursive || (call.local ? frame.start == start.value() : !frame.local && frame.programNumber == call.programNumber);
  if (recursive) {
    return Error{line, call.column,
                 fmt::format("{} calls {} while it is already running ({}): a subprogram "
                             "may not call itself, directly or through others",
                             code, called, chainTo(called))};
  }
  const int levels = framesOfKind(false);
  if (levels >= kMaxSubprogramNesting) {
    return Error{line, call.column,
                 fmt::format("{} calls {} from {} levels of subprograms ({}): the control "
                             "nests at most {} levels",
                             code, called, levels, chainTo(called), kMaxSubprogramNesting)};
  }
  frames_.push_back({call.programNumber, false, call.local, start.value(), index, call.column, call.repeats - 1});
  return start;
}

Result<std::size_t> CallStack::callMacro(const macro::MacroCall& call, std::size_t index) {
  auto start = programStart(call.programNumber, "G65", call.column, index);
  if (!start.ok()) return start;
  // A macro may call itself (Fanuc allows it); the nesting limit bounds the recursion.
  const int levels = framesOfKind(true);
  if (levels >= kMaxMacroNesting) {
    return Error{program_.block(index).line, call.column,
                 fmt::format("G65 calls {} from {} levels of macro calls ({}): the control nests at most {} "
                             "(local variable levels 0–{})",
                             programName(call.programNumber), levels, chainTo(programName(call.programNumber)),
                             kMaxMacroNesting, kMaxMacroNesting)};
  }
  frames_.push_back({call.programNumber, true, false, start.value(), index, call.column, call.repeats - 1});
  return start;
}

Result<CallReturn> CallStack::giveBack(const SubprogramReturn& giveBack, std::size_t index) {
  Frame& frame = frames_.back();
  if (frame.repeatsLeft > 0) {
    --frame.repeatsLeft;
    return CallReturn{frame.start, true, false, frame.callFrom, frame.column};
  }
  std::size_t next = frame.callFrom + 1;
  if (giveBack.sequence) {
    const SequenceBlocks found = program_.findSequence(*giveBack.sequence, frame.callFrom);
    if (found.count == 0) {
      return Error{program_.block(index).line, giveBack.sequenceColumn,
                   fmt::format("M99 P{0} returns to N{0} of the calling program, which has no block N{0}",
                               *giveBack.sequence)};
    }
    next = found.first;
  }
  const CallReturn back{next, false, frame.macro, frame.callFrom, frame.column};
  frames_.pop_back();
  return back;
}

std::optional<Error> CallStack::unfinished() const {
  if (frames_.empty()) return std::nullopt;
  const Frame& frame = frames_.back();
  return Error{program_.block(frame.callFrom).line, frame.column,
               fmt::format("{} called here has no M99: the program text ends inside it",
                           frame.local ? localName(frame.programNumber) : programName(frame.programNumber))};
}

}  // namespace lathesim::interp
