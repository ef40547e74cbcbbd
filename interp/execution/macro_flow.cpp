#include "interp/execution/macro_flow.hpp"

#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "interp/macro/evaluator.hpp"

namespace lathesim::interp {
namespace {

constexpr int kMaxSequenceNumber = 99999;

}  // namespace

MacroFlow::MacroFlow(const Program& program, macro::VariableStore& variables, StepGuard& guard)
    : program_(program), variables_(variables), guard_(guard), pairs_(macro::pairLoops(program)), loops_(1) {}

void MacroFlow::programGrew() { pairs_ = macro::pairLoops(program_); }

void MacroFlow::cameTo(std::size_t index) {
  auto& running = loops_.back();
  while (!running.empty() && (index < running.back().start || index > running.back().end)) running.pop_back();
}

void MacroFlow::enterProgram() {
  loops_.emplace_back();
  guard_.enterProgram();
}

void MacroFlow::leaveProgram() {
  loops_.pop_back();
  guard_.leaveProgram();
}

Result<std::size_t> MacroFlow::run(std::size_t index, std::vector<Error>& stops) {
  const ProgramBlock& block = program_.block(index);
  const macro::MacroBlock& macroBlock = *block.macroBlock();
  const macro::Statement& statement = *macroBlock.statement;
  if (const auto* assignment = std::get_if<macro::Assignment>(&statement)) {
    if (auto status = assign(*assignment, block.line, macroBlock.message, stops); !status.ok()) return status.error();
    return index + 1;
  }
  if (const auto* jumpTo = std::get_if<macro::Jump>(&statement)) return jump(*jumpTo, index);
  if (const auto* start = std::get_if<macro::LoopStart>(&statement)) return loopStart(*start, index);
  if (const auto* end = std::get_if<macro::LoopEnd>(&statement)) return loopEnd(*end, index);
  const auto& ifStatement = std::get<macro::IfStatement>(statement);
  auto holds = macro::evaluate(ifStatement.condition, {variables_, block.line, std::nullopt});
  if (!holds.ok()) return holds.error();
  if (!holds.value()) return index + 1;
  if (const auto* jumpTo = std::get_if<macro::Jump>(&ifStatement.then)) return jump(*jumpTo, index);
  auto status = assign(std::get<macro::Assignment>(ifStatement.then), block.line, macroBlock.message, stops);
  if (!status.ok()) return status.error();
  return index + 1;
}

Status MacroFlow::assign(const macro::Assignment& assignment, int line, const std::string& message,
                         std::vector<Error>& stops) {
  const macro::EvaluationContext context{variables_, line, std::nullopt};
  auto number = macro::variableNumber(assignment.variable, context);
  if (!number.ok()) return number.error();
  auto value = macro::evaluate(assignment.value, context);
  if (!value.ok()) return value.error();
  const double code = std::round(value.value().value_or(0.0));
  if (number.value() == macro::kAlarmVariable) {
    return Error{line, assignment.column,
                 fmt::format("the program raises alarm {:.0f} with #3000 = {:.0f}: {}", macro::kAlarmVariable + code,
                             code, message.empty() ? "no message given" : message)};
  }
  if (number.value() == macro::kStopVariable) {
    stops.push_back({line, assignment.column,
                        fmt::format("program stop (#3006 = {:.0f}): {} — the control waits here for cycle start; "
                                    "lathesim goes on",
                                    code, message.empty() ? "no message given" : message)});
    return success();
  }
  return variables_.write(number.value(), value.value(), line, assignment.column);
}

Result<std::size_t> MacroFlow::jump(const macro::Jump& jump, std::size_t index) {
  const int line = program_.block(index).line;
  auto target = macro::evaluate(jump.target, {variables_, line, std::nullopt});
  if (!target.ok()) return target.error();
  if (!target.value()) {
    return Error{line, jump.target.column, "GOTO's sequence number is vacant: it needs a value"};
  }
  const double number = std::round(*target.value());
  if (number < 1 || number > kMaxSequenceNumber) {
    return Error{line, jump.target.column,
                 fmt::format("GOTO {:g}: sequence numbers run from 1 to {} (alarm 128)", *target.value(),
                             kMaxSequenceNumber)};
  }
  const SequenceBlocks found = program_.findSequence(static_cast<int>(number), index);
  if (found.count == 0) {
    return Error{line, jump.target.column,
                 fmt::format("GOTO {}: there is no block N{} in this program (alarm 128)", number, number)};
  }
  // Which of two blocks numbered alike a control jumps to (the first, the next one down …)
  // could not be checked in a manual: refuse rather than guess.
  if (found.count > 1) {
    return Error{line, jump.target.column,
                 fmt::format("GOTO {}: this program has N{} twice (lines {} and {}); number the blocks apart",
                             number, number, program_.block(found.first).line, program_.block(found.second).line)};
  }
  const std::size_t to = found.first;
  cameTo(to);
  if (to <= index) guard_.jumpedBack(index, to, {index, jump.column});
  return to;
}

Result<std::size_t> MacroFlow::partnerOf(std::size_t index) const {
  const auto found = pairs_.partner.find(index);
  return found->second;  // every DO and END has an entry
}

Result<std::size_t> MacroFlow::loopStart(const macro::LoopStart& start, std::size_t index) {
  auto end = partnerOf(index);
  if (!end.ok()) return end;
  bool repeat = true;  // DO alone repeats forever
  if (start.condition) {
    auto holds = macro::evaluate(*start.condition, {variables_, program_.block(index).line, std::nullopt});
    if (!holds.ok()) return holds.error();
    repeat = holds.value();
  }
  auto& running = loops_.back();
  const bool active = !running.empty() && running.back().start == index;
  if (!repeat) {
    if (active) running.pop_back();
    return end.value() + 1;
  }
  if (!active) running.push_back({index, end.value()});
  return index + 1;
}

Result<std::size_t> MacroFlow::loopEnd(const macro::LoopEnd& end, std::size_t index) {
  auto start = partnerOf(index);
  if (!start.ok()) return start;
  const auto& running = loops_.back();
  if (running.empty() || running.back().start != start.value()) {
    return Error{program_.block(index).line, end.column,
                 fmt::format("END {} is reached, but its loop (DO {} of line {}) is not running: a GOTO may jump "
                             "out of a loop, not into one",
                             end.loopNumber, end.loopNumber, program_.block(start.value()).line)};
  }
  const ProgramBlock loopBlock = program_.block(start.value());
  const auto& loop = std::get<macro::LoopStart>(*loopBlock.macroBlock()->statement);
  guard_.jumpedBack(index, start.value(), {start.value(), loop.column});
  return start.value();
}

}  // namespace lathesim::interp
