#include "interp/execution/program_runner.hpp"

#include <algorithm>
#include <set>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "interp/execution/block_executor.hpp"
#include "interp/execution/call_stack.hpp"
#include "interp/execution/macro_flow.hpp"
#include "interp/execution/modal_state.hpp"
#include "interp/execution/step_guard.hpp"
#include "interp/macro/block_words.hpp"
#include "interp/macro/macro_call.hpp"
#include "interp/macro/variables.hpp"

namespace lathesim::interp {
namespace {

class ProgramRunner {
 public:
  ProgramRunner(const Program& program, const InterpreterOptions& options, Toolpath& toolpath,
                std::vector<Error>& warnings)
      : program_(program),
        options_(options),
        toolpath_(toolpath),
        warnings_(warnings),
        calls_(program),
        variables_(options.macroVariables),
        guard_(options.maxSteps, program.blocks.size()),
        flow_(program, variables_, guard_) {
    state_.position = options.startPosition;
    state_.feedMode = options.initialFeedMode;
    if (!options.toolNumbers.empty()) state_.tool = options.toolNumbers.front();
  }

  Status run();

 private:
  Error stepLimitError(std::size_t index) const;
  Result<std::size_t> runMacroWords(std::size_t index, const macro::MacroBlock& block);
  Result<std::size_t> runWords(std::size_t index, const ParsedBlock& words);
  Result<std::size_t> callMacro(std::size_t index, const std::vector<Word>& words);
  Result<std::size_t> giveBack(int column, std::size_t index);
  void warnLeftOut(int line, const std::vector<macro::VacantWord>& leftOut);

  const Program& program_;
  const InterpreterOptions& options_;
  Toolpath& toolpath_;
  std::vector<Error>& warnings_;
  ModalState state_;
  CallStack calls_;
  macro::VariableStore variables_;
  StepGuard guard_;
  MacroFlow flow_;
  std::set<std::pair<int, int>> warnedLeftOut_;  // (line, column): each said once
};

Status ProgramRunner::run() {
  std::size_t next = 0;
  while (!state_.ended && next < program_.blocks.size()) {
    const std::size_t index = next;
    const ProgramBlock& block = program_.blocks[index];
    toolpath_.blockCount = std::max(toolpath_.blockCount, block.ordinal + 1);
    if (block.skipped) {
      ++next;
      continue;
    }
    if (!block.content.ok()) return block.content.error();
    if (guard_.step(index)) return stepLimitError(index);

    Result<std::size_t> after = index + 1;
    if (const ParsedBlock* words = block.plainWords()) {
      after = runWords(index, *words);
    } else if (const macro::MacroBlock* macroBlock = block.macroBlock(); macroBlock->statement) {
      after = flow_.run(index, warnings_);
    } else {
      after = runMacroWords(index, *macroBlock);
    }
    if (!after.ok()) return after.error();
    next = after.value();
  }
  if (!state_.ended) {
    if (auto error = calls_.unfinished()) return *error;
  }
  return success();
}

Error ProgramRunner::stepLimitError(std::size_t index) const {
  const std::string limit = fmt::format("{} blocks run again", guard_.maxSteps());
  const std::string raise = "raise the step limit with --max-steps or [macro] max_steps if the program is meant to "
                            "run longer";
  if (const auto loop = guard_.stuckLoop()) {
    const ProgramBlock& block = program_.blocks[loop->block];
    return Error{block.line, loop->column,
                 fmt::format("the program is still in this loop after {}: it never ends, or runs longer than "
                             "the step limit; {}",
                             limit, raise)};
  }
  const ProgramBlock& block = program_.blocks[index];
  return Error{block.line, block.column, fmt::format("the program has reached {} and is not finished; {}", limit, raise)};
}

void ProgramRunner::warnLeftOut(int line, const std::vector<macro::VacantWord>& leftOut) {
  for (const macro::VacantWord& word : leftOut) {
    if (!warnedLeftOut_.insert({line, word.column}).second) continue;
    warnings_.push_back({line, word.column,
                         fmt::format("{}: {} is vacant, so {} is left out of this block, as a Fanuc control does",
                                     word.written, word.written.substr(word.written.find('#')), word.letter)});
  }
}

Result<std::size_t> ProgramRunner::runMacroWords(std::size_t index, const macro::MacroBlock& block) {
  const ProgramBlock& placed = program_.blocks[index];
  auto evaluated = macro::evaluateWords(block, variables_, placed.line, state_.inch);
  if (!evaluated.ok()) return evaluated.error();
  const macro::BlockWords& words = evaluated.value();
  warnLeftOut(placed.line, words.leftOut);
  Result<std::size_t> after = index + 1;
  if (words.macroCall) {
    after = callMacro(index, words.words);
  } else if (auto parsed = parseBlock(words.words, placed.line, placed.column, options_.dialect); parsed.ok()) {
    after = runWords(index, parsed.value());
  } else {
    after = parsed.error();
  }
  if (!after.ok()) return macro::withLeftOutNote(after.error(), words.leftOut);
  return after;
}

Result<std::size_t> ProgramRunner::runWords(std::size_t index, const ParsedBlock& words) {
  const ProgramBlock& block = program_.blocks[index];
  const BlockPlace place{program_, index, &variables_};
  auto outcome = executeBlock(words, state_, options_, block.ordinal, &place);
  if (!outcome.ok()) return outcome.error();

  BlockOutcome& done = outcome.value();
  const ProgramFlow& flow = done.flow;
  std::size_t next = index + 1;
  if (flow.call) {
    auto target = calls_.call(*flow.call, index);
    if (!target.ok()) return target.error();
    flow_.enterProgram();
    next = target.value();
  } else if (flow.returnColumn) {
    auto target = giveBack(*flow.returnColumn, index);
    if (!target.ok()) return target.error();
    next = target.value();
  } else if (flow.continueAfter) {
    next = *flow.continueAfter + 1;
  }
  state_ = std::move(done.state);
  toolpath_.moves.insert(toolpath_.moves.end(), done.moves.begin(), done.moves.end());
  toolpath_.cycleStarts.insert(toolpath_.cycleStarts.end(), done.cycleStarts.begin(), done.cycleStarts.end());
  warnings_.insert(warnings_.end(), done.warnings.begin(), done.warnings.end());
  return next;
}

Result<std::size_t> ProgramRunner::callMacro(std::size_t index, const std::vector<Word>& words) {
  auto call = macro::readMacroCall(words, program_.blocks[index].line);
  if (!call.ok()) return call.error();
  auto target = calls_.callMacro(call.value(), index);
  if (!target.ok()) return target.error();
  variables_.pushLevel(call.value().arguments);
  flow_.enterProgram();
  return target;
}

Result<std::size_t> ProgramRunner::giveBack(int column, std::size_t index) {
  auto back = calls_.giveBack(column, index);
  if (!back.ok()) return back.error();
  const CallReturn& done = back.value();
  if (done.repeat) {
    flow_.restartProgram();
    guard_.jumpedBack(index, done.next, {done.callBlock, done.callColumn});
    return done.next;
  }
  if (done.leftMacro) variables_.popLevel();
  flow_.leaveProgram();
  return done.next;
}

}  // namespace

Status runProgram(const Program& program, const InterpreterOptions& options, Toolpath& toolpath,
                  std::vector<Error>& warnings) {
  return ProgramRunner(program, options, toolpath, warnings).run();
}

}  // namespace lathesim::interp
