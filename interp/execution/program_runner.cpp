#include "interp/execution/program_runner.hpp"

#include <algorithm>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>

#include <fmt/format.h>

#include "interp/execution/block_executor.hpp"
#include "interp/execution/call_stack.hpp"
#include "interp/execution/macro_flow.hpp"
#include "interp/execution/move_sources.hpp"
#include "interp/state/modal_state.hpp"
#include "interp/state/move_limit.hpp"
#include "interp/state/step_guard.hpp"
#include "interp/macro/block_words.hpp"
#include "interp/macro/macro_call.hpp"
#include "interp/macro/variables.hpp"
#include "interp/text/program_library.hpp"
#include "interp/text/word_units.hpp"

namespace lathesim::interp {
namespace {

class ProgramRunner {
 public:
  ProgramRunner(Program& program, const InterpreterOptions& options, Toolpath& toolpath, MovePipeline& moves,
                std::vector<Error>& warnings, std::vector<Error>& notes, std::vector<SkippedBlock>& skipped)
      : program_(program),
        options_(options),
        toolpath_(toolpath),
        moves_(moves),
        warnings_(warnings),
        notes_(notes),
        skipped_(skipped),
        calls_(program),
        sources_(program, toolpath),
        variables_(options.macroVariables),
        guard_(options.maxSteps),
        flow_(program, variables_, guard_) {
    state_.frame.offsets = options.workOffsets;
    state_.position = options.startPosition - state_.frame.shift();
    state_.feedMode = options.control.powerOnFeedMode;
    state_.inch = !options.control.powerOnMetric;
    state_.compound = CompoundCycleParams::of(options.control);
    if (!options.toolNumbers.empty()) state_.tool = options.toolNumbers.front();
    state_.toolCalled = options.mountedToolStated;
  }

  Status run();

 private:
  Result<std::size_t> runBlock(std::size_t index);
  Error stepLimitError(std::size_t index) const;
  Result<std::size_t> runMacroWords(std::size_t index, const macro::MacroBlock& block);
  Result<std::size_t> runWords(std::size_t index, const ParsedBlock& words);
  Result<std::size_t> callMacro(std::size_t index, const std::vector<Word>& words);
  Result<std::size_t> giveBack(const SubprogramReturn& giveBack, std::size_t index);
  void listStop(std::size_t index, const ParsedBlock& words);
  void notePartsCatcher(std::size_t index, const ParsedBlock& words);
  Status passBlockMoves();
  std::pair<int, int> listedAt(std::size_t index, int column) const;
  Status loadProgram(int programNumber, std::string_view code, int column, std::size_t caller);
  void warnLeftOut(std::size_t index, const std::vector<macro::VacantWord>& leftOut);
  // A block that runs again (a loop, a repeated call) says the same thing once.
  void warn(Error warning, std::size_t index) {
    Error located = inFile(std::move(warning), index);
    if (warned_.insert({located.file, located.line, located.column, located.message}).second)
      warnings_.push_back(std::move(located));
  }
  // An error or warning of block `index`, naming its file when it is a subprogram's own.
  Error inFile(Error error, std::size_t index) const {
    const ProgramBlock& block = program_.block(index);
    if (block.source != 0) error.file = program_.sources[static_cast<std::size_t>(block.source)].name;
    return error;
  }

  Program& program_;
  const InterpreterOptions& options_;
  Toolpath& toolpath_;
  MovePipeline& moves_;
  std::vector<Move> blockMoves_;  // the moves of the block that ran last, not yet in moves_
  std::optional<ContourPass> blockContourPass_;  // and the contour it finished or roughed
  bool blockLegsCompensated_ = false;  // and whether its cycle offset its own legs
  std::optional<PartsCatcherCommand> catcher_;  // its parts catcher command, not yet listed
  std::size_t movesMade_ = 0;  // by the blocks, before corners and dog-legs
  std::vector<Error>& warnings_;
  std::vector<Error>& notes_;
  std::vector<SkippedBlock>& skipped_;
  ModalState state_;
  CallStack calls_;
  MoveSources sources_;
  macro::VariableStore variables_;
  StepGuard guard_;
  MacroFlow flow_;
  std::set<std::tuple<std::string, int, int, std::string>> warned_;  // (file, line, column, message)
  std::set<std::size_t> notedStops_;             // blocks whose #3006 stop is listed: once each
  std::set<std::size_t> skippedListed_;          // '/' blocks listed as skipped: once each
};

Status ProgramRunner::run() {
  if (program_.textAfterEnd) warnings_.push_back(*program_.textAfterEnd);
  std::size_t next = 0;
  while (!state_.ended && next < program_.blockCount()) {
    const std::size_t index = next;
    auto after = runBlock(index);
    if (!after.ok()) return after.error();
    if (auto passed = passBlockMoves(); !passed.ok()) return passed.error();
    next = after.value();
  }
  if (!state_.ended) {
    if (auto error = calls_.unfinished()) return *error;
  }
  if (auto mixed = state_.lengthWriting.mixedWarning(NumberReading::of(options_.control, state_.inch)))
    warnings_.push_back(*mixed);
  return success();
}

// Runs block `index`; the block to run next, or the error located in its file.
Result<std::size_t> ProgramRunner::runBlock(std::size_t index) {
  const ProgramBlock& block = program_.block(index);
  toolpath_.blockCount = std::max(toolpath_.blockCount, block.ordinal + 1);
  if (block.skipped) {
    if (skippedListed_.insert(index).second) {
      const Error at = inFile(Error{block.line, block.column, {}}, index);
      skipped_.push_back({at.line, at.column, at.file});
    }
    return index + 1;
  }
  if (const Error* error = program_.errorOf(block)) return inFile(*error, index);
  if (guard_.step(index)) return stepLimitError(index);

  Result<std::size_t> after = index + 1;
  if (const auto words = program_.plainWords(block)) {
    after = runWords(index, *words);
  } else if (const macro::MacroBlock* macroBlock = block.macroBlock(); macroBlock->statement) {
    std::vector<Error> stops;
    after = flow_.run(index, stops);
    for (Error& stop : stops)
      if (notedStops_.insert(index).second) notes_.push_back(inFile(std::move(stop), index));
  } else {
    after = runMacroWords(index, *macroBlock);
  }
  if (!after.ok()) return after.error().file.empty() ? inFile(after.error(), index) : after.error();
  return after;
}

Error ProgramRunner::stepLimitError(std::size_t index) const {
  const std::string limit = fmt::format("{} blocks run again", guard_.maxSteps());
  const std::string raise = "raise the step limit with --max-steps or [macro] max_steps if the program is meant to "
                            "run longer";
  if (const auto loop = guard_.stuckLoop()) {
    const ProgramBlock& block = program_.block(loop->block);
    return inFile(Error{block.line, loop->column,
                        fmt::format("the program is still in this loop after {}: it never ends, or runs longer than "
                                    "the step limit; {}",
                                    limit, raise)},
                  loop->block);
  }
  const ProgramBlock& block = program_.block(index);
  return inFile(Error{block.line, block.column,
                      fmt::format("the program has reached {} and is not finished; {}", limit, raise)},
                index);
}

void ProgramRunner::warnLeftOut(std::size_t index, const std::vector<macro::VacantWord>& leftOut) {
  const int line = program_.block(index).line;
  for (const macro::VacantWord& word : leftOut) {
    warn({line, word.column,
          fmt::format("{}: {} is vacant, so {} is left out of this block, as a Fanuc control does", word.written,
                      word.written.substr(word.written.find('#')), word.letter)},
         index);
  }
}

Result<std::size_t> ProgramRunner::runMacroWords(std::size_t index, const macro::MacroBlock& block) {
  const int line = program_.block(index).line;
  const int column = program_.block(index).column;
  auto evaluated = macro::evaluateWords(block, variables_, line, NumberReading::of(options_.control, state_.inch));
  if (!evaluated.ok()) return evaluated.error();
  const macro::BlockWords words = std::move(evaluated).value();  // owned: a call may read another file
  warnLeftOut(index, words.leftOut);
  Result<std::size_t> after = index + 1;
  if (words.macroCall) {
    // A length argument written without a decimal point is read like any such length.
    for (const macro::MacroWord& word : block.words)
      if (!word.expression && macro::isLengthArgument(word.word.letter))
        state_.lengthWriting.note(word.word, line, program_.block(index).ordinal);
    after = callMacro(index, words.words);
  } else if (auto parsed = parseBlock(words.words, line, column, options_.dialect, options_.control.machineMCodes); parsed.ok()) {
    after = runWords(index, parsed.value());
  } else {
    after = parsed.error();
  }
  if (!after.ok()) return macro::withLeftOutNote(after.error(), words.leftOut);
  return after;
}

Result<std::size_t> ProgramRunner::runWords(std::size_t index, const ParsedBlock& words) {
  const int source = program_.block(index).source;
  const BlockPlace place{program_, index, blockExecutor(), &variables_};
  auto outcome = executeBlock(words, state_, options_, program_.block(index).ordinal, &place);
  if (!outcome.ok()) return outcome.error();

  BlockOutcome& done = outcome.value();
  if (source != 0) {  // a subprogram's own file: its moves name their lines there
    const std::uint16_t from = sources_.of(source, calls_.callBlocks());
    for (Move& move : done.moves) move.source = from;
    for (CycleStart& start : done.cycleStarts) start.source = from;
  }
  for (Error& warning : done.warnings) warn(std::move(warning), index);
  const ProgramFlow flow = done.flow;
  state_ = std::move(done.state);
  notePartsCatcher(index, words);
  movesMade_ += done.moves.size();
  blockMoves_ = std::move(done.moves);
  blockContourPass_ = done.contourPass;
  blockLegsCompensated_ = done.legsCompensated;
  const ProgramBlock& made = program_.block(index);
  if (auto tooMany = moveLimitError(movesMade_, options_.maxMoves, made.line, made.column)) return *tooMany;
  toolpath_.cycleStarts.insert(toolpath_.cycleStarts.end(), done.cycleStarts.begin(), done.cycleStarts.end());
  listStop(index, words);
  if (flow.call) {
    if (!flow.call->local) {  // M97 calls a block of this program: nothing to load
      if (auto loaded = loadProgram(flow.call->programNumber, "M98", flow.call->column, index); !loaded.ok())
        return loaded.error();
    }
    auto target = calls_.call(*flow.call, index);
    if (!target.ok()) return target.error();
    flow_.enterProgram();
    return target;
  }
  if (flow.giveBack && !calls_.inSubprogram()) {
    // M99 in the main program: the control starts it over, forever; it is simulated once.
    warn({program_.block(index).line, flow.giveBack->column,
          "M99 ends the main program: the control runs it again from the start, forever; lathesim simulates it "
          "once"},
         index);
    state_.ended = true;
    return index + 1;
  }
  if (flow.giveBack) return giveBack(*flow.giveBack, index);
  if (flow.continueAfter) return *flow.continueAfter + 1;
  return index + 1;
}

Result<std::size_t> ProgramRunner::callMacro(std::size_t index, const std::vector<Word>& words) {
  auto call = macro::readMacroCall(words, program_.block(index).line);
  if (!call.ok()) return call.error();
  if (auto loaded = loadProgram(call.value().programNumber, "G65", call.value().column, index); !loaded.ok()) {
    return loaded.error();
  }
  auto target = calls_.callMacro(call.value(), index);
  if (!target.ok()) return target.error();
  variables_.pushLevel(call.value().arguments);
  flow_.enterProgram();
  return target;
}

// Where a code of block `index` at `column` is listed in the report: at its line; in a
// subprogram's own file, at the line of the main program's call that led there.
std::pair<int, int> ProgramRunner::listedAt(std::size_t index, int column) const {
  const ProgramBlock& block = program_.block(index);
  if (block.source == 0 || !calls_.outermostCall()) return {block.line, column};
  const ProgramBlock& call = program_.block(*calls_.outermostCall());
  return {call.line, call.column};
}

// M00/M01 are listed in the report.
void ProgramRunner::listStop(std::size_t index, const ParsedBlock& words) {
  const auto stop = words.mCode(MGroup::Stop);
  if (!stop) return;
  const auto [line, column] = listedAt(index, stop->column);
  toolpath_.stops.push_back({line, column, stop->text});
}

// The parts catcher's commands are listed with the moves made before them (passBlockMoves).
void ProgramRunner::notePartsCatcher(std::size_t index, const ParsedBlock& words) {
  const auto catcher = words.mCode(MGroup::PartsCatcher);
  if (!catcher) return;
  const auto [line, column] = listedAt(index, catcher->column);
  catcher_ = PartsCatcherCommand{0, line, column, catcher->text, catcher->number != 37};
}

// The moves of the block that ran, into the pipeline; a parts catcher command of the block
// acts before them, so it is listed with the toolpath's moves before them: the pipeline first
// lets go what it holds, so that the count is of the moves as they end up (dog-legs and
// corners counted). Inside a G41/G42 chain, which cannot be cut, the moves held count as made.
Status ProgramRunner::passBlockMoves() {
  if (catcher_) {
    if (auto released = moves_.release(true); !released.ok()) return released;
    catcher_->movesBefore = moves_.passed() + moves_.held();
    toolpath_.partsCatcher.push_back(*std::exchange(catcher_, std::nullopt));
  }
  moves_.add(blockMoves_, std::exchange(blockContourPass_, std::nullopt), std::exchange(blockLegsCompensated_, false));
  blockMoves_.clear();
  return moves_.release();
}

Result<std::size_t> ProgramRunner::giveBack(const SubprogramReturn& giveBack, std::size_t index) {
  auto back = calls_.giveBack(giveBack, index);
  if (!back.ok()) return back.error();
  const CallReturn& done = back.value();
  if (done.repeat) {
    flow_.restartProgram();
    guard_.jumpedBack(index, done.next, {done.callBlock, done.callColumn});
    return done.next;
  }
  if (done.leftMacro) variables_.popLevel();
  flow_.leaveProgram();
  // M99 P to a block of the caller at or before its call: the caller loops through the call,
  // a loop of its own as a GOTO back would be (the M99's P is where it is written).
  flow_.cameTo(done.next);
  if (done.next <= done.callBlock) guard_.jumpedBack(done.callBlock, done.next, {index, giveBack.sequenceColumn});
  return done.next;
}

// A program M98 or G65 calls that the text does not hold: read it from its file
// (program_library.hpp), or say which names were looked for where.
Status ProgramRunner::loadProgram(int programNumber, std::string_view code, int column, std::size_t caller) {
  if (program_.programStart(programNumber)) return success();
  if (auto file = findProgramFile(programNumber, options_.programDirectories)) {
    const std::string name = file->path.string();
    for (ReadNote& note : appendProgramFile(program_, name, std::move(file->text), programNumber, options_.control.blockSkip,
                                            options_.dialect, options_.control.machineMCodes))
      (note.warning ? warnings_ : notes_).push_back(Error{note.line, note.column, std::move(note.message), name});
    flow_.programGrew();
    return success();
  }
  const auto names = programFileNames(programNumber);
  std::string directories;
  for (const auto& directory : options_.programDirectories)
    directories += (directories.empty() ? "" : ", ") + directory.string();
  return inFile(Error{program_.block(caller).line, column,
                      fmt::format("{} calls O{:04}, which is neither in this program nor in a file: "
                                  "looked for {}, {}, {} … {} in {}; give the directory of the "
                                  "control's programs with --programs DIR",
                                  code, programNumber, names[0], names[1], names[2], names.back(),
                                  directories.empty() ? "no directory" : directories)},
                caller);
}

}  // namespace

Status runProgram(Program& program, const InterpreterOptions& options, Toolpath& toolpath, MovePipeline& moves,
                  std::vector<Error>& warnings, std::vector<Error>& notes, std::vector<SkippedBlock>& skipped) {
  return ProgramRunner(program, options, toolpath, moves, warnings, notes, skipped).run();
}

}  // namespace lathesim::interp
