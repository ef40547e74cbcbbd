#include "interp/execution/block_executor.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "interp/motion/arc_move.hpp"
#include "interp/motion/feed_warnings.hpp"
#include "interp/motion/drawing_angle.hpp"
#include "interp/cycles/compound_cycle.hpp"
#include "interp/cycles/drilling_cycle.hpp"
#include "interp/motion/g28_return.hpp"
#include "interp/compensation/cycle_nose_compensation.hpp"
#include "interp/cycles/g90_cycle.hpp"
#include "interp/cycles/g92_cycle.hpp"
#include "interp/cycles/g94_cycle.hpp"
#include "interp/cycles/thread_cut.hpp"
#include "interp/cycles/thread_words.hpp"
#include "interp/motion/spindle_speed.hpp"
#include "interp/execution/data_setting.hpp"
#include "interp/execution/program_runner.hpp"
#include "interp/execution/subprogram_call.hpp"
#include "interp/text/tool_word.hpp"
#include "interp/execution/work_coordinates.hpp"
#include "interp/text/label_number.hpp"
#include "interp/text/word_units.hpp"

namespace lathesim::interp {
namespace {

constexpr double kMetresPerFoot = 0.3048;  // G96 S under G20 is in ft/min
constexpr double kMsPerS = 1000.0;

// What sets G90 and G94 apart; the rest of a single cycle (modal retention, the checks,
// emitting its legs) is one code path for both.
struct SingleCycle {
  int code;               // the system-A code, 90 or 94 (the dialect may write another)
  bool taperAgainstX;     // the R alarm compares R with U (G90) or with W (G94)
  std::vector<CycleLeg> (*legs)(const RZ& start, const RZ& end, double rMm);
  std::optional<std::string> (*taperProblem)(double travelMm, double rMm);
};

constexpr SingleCycle kAxialCycle{90, true, axialCycleLegs, axialCycleTaperProblem};
constexpr SingleCycle kFaceCycle{94, false, faceCycleLegs, faceCycleTaperProblem};

// The axis words of a block: at most one of X/U and one of Z/W.
struct AxisWords {
  std::optional<Word> x, u, z, w;
  bool any() const { return x || u || z || w; }
};

class Executor {
 public:
  Executor(ParsedBlock block, ModalState state, const InterpreterOptions& options, int ordinal,
           const BlockPlace* place)
      : block_(std::move(block)),
        state_(std::move(state)),
        options_(options),
        ordinal_(ordinal),
        place_(place) {}

  Result<BlockOutcome> run();

 private:
  Error errorAt(int column, std::string message) const {
    return Error{block_.line, column, std::move(message)};
  }
  // Coordinates a move or cycle goes to follow the distance mode (under G91 X and Z are
  // incremental, like U and W); coordinates a block declares (G50) are always absolute.
  enum class Coordinates { Target, Declared };
  Result<AxisWords> takeAxisWords(Coordinates meaning = Coordinates::Target);
  NumberReading reading() const { return NumberReading::of(options_.control, state_.inch); }
  // A length word in mm, noted for the mixed decimal point warning.
  double length(const Word& word) {
    state_.lengthWriting.note(word, block_.line, ordinal_);
    return lengthMm(word, reading());
  }
  Status applyFeed();
  void applySpindleMode();
  Status applySpindleSpeed();
  Status applyTool();
  Status applyOneShot(const Code& code);
  Status applyDwell(const Code& code);
  Status applyCoordinateSetting(const Code& code);
  Status applyReferenceReturn(const Code& code);
  void selectMotion(const Code& code);
  Status applyMachineCoordinateMove(const Code& code);
  void applyWorkSystem(const std::optional<Code>& oneShot);
  void noteDrillingCycleCancel();
  void warnIfCycleRepeatsAfterG80(const std::optional<Code>& code, std::string_view name);
  const ToolOffsets& offsetTable() const {
    return state_.offsetTable ? *state_.offsetTable : options_.offsets;
  }
  Status applyMotion();
  Status applyDrillingCycle(const std::optional<Code>& code);
  Status applyStraightMove(const std::optional<Code>& code);
  Status applyArc(const std::optional<Code>& code);
  RZ endPoint(const AxisWords& axes);
  std::optional<Word> takeAngleWord();
  Result<std::optional<CornerRequest>> takeCornerWord();
  double angleDegrees(const Word& angle) const;
  std::optional<ArcWord> arcWord(char letter);
  Status applySingleCycle(const SingleCycle& cycle, const std::optional<Code>& code);
  Status applyThreadCut(const std::optional<Code>& code);
  Status applyThreadCycle(const std::optional<Code>& code);
  void warnIfThreadTooFast(const std::vector<CycleLeg>& legs, int column);
  Status applyCompoundCycle(const Code& code);
  Status applySubprogramCode();
  Status checkAllWordsUsed() const;
  Status checkToolCalledBeforeCut();
  std::optional<std::string> missingMachineryOf(const Word& word) const;
  void emit(MoveKind kind, const RZ& from, const RZ& to, int cycleStep, const RZ& center = RZ(0, 0),
            const ThreadMotion& thread = {});
  void warnIfSurfaceSpeedUnclamped();
  void warnIfFeedImplausible();
  void emitLegs(const std::vector<CycleLeg>& legs);

  ParsedBlock block_;
  ModalState state_;
  const InterpreterOptions& options_;
  int ordinal_;
  const BlockPlace* place_;
  std::vector<Move> moves_;
  ProgramFlow flow_;
  std::vector<Error> warnings_;
  std::vector<CycleStart> cycleStarts_;
  bool chainedThread_ = false;  // this block continued (or began) a chain of G32 cuts
  bool feedGivenHere_ = false;  // the block gave F
};

Result<BlockOutcome> Executor::run() {
  warnings_ = block_.warnings;
  block_.take('N');  // sequence number: a label only
  block_.take('O');  // program number
  if (auto status = applySubprogramCode(); !status.ok()) return status.error();
  if (auto code = block_.gCode(GGroup::Units)) state_.inch = code->number == 20;
  if (auto code = block_.gCode(GGroup::FeedMode)) {
    state_.feedMode = code->number == 98 ? FeedMode::PerMinute : FeedMode::PerRevolution;
  }
  if (auto code = block_.gCode(GGroup::Distance)) state_.incremental = code->number == kIncrementalDistance;
  if (auto code = block_.gCode(GGroup::Plane)) {
    state_.plane = code->number == 17 ? Plane::XY : code->number == 19 ? Plane::YZ : Plane::ZX;
  }
  applySpindleMode();
  if (auto code = block_.gCode(GGroup::NoseRadius)) {
    state_.noseSide = code->number == 41   ? NoseSide::Left
                      : code->number == 42 ? NoseSide::Right
                                           : NoseSide::None;
  }

  // A one-shot code takes the block's axis words; a motion code beside it (G28 G00 U0 W0) only
  // becomes the modal motion, as on the controls.
  const auto oneShot = block_.gCode(GGroup::NonModal);
  applyWorkSystem(oneShot);
  noteDrillingCycleCancel();
  if (const auto motion = block_.gCode(GGroup::Motion); oneShot && motion) selectMotion(*motion);
  // G81–G84 stay in force until G80 or a motion code; a block that gives an axis word drills again
  // (at X0 only: a hole elsewhere needs live tooling, and is refused rather than moved to).
  const auto drillCode = block_.gCode(GGroup::DrillingCycle);
  if ((drillCode && drillCode->number == 80) || block_.gCode(GGroup::Motion)) state_.drillingCycle = 0;
  const bool drills = !oneShot && ((drillCode && drillCode->number != 80) ||
                                   (!drillCode && state_.drillingCycle != 0 &&
                                    (block_.has('X') || block_.has('U') || block_.has('Z') || block_.has('W'))));
  const bool compound = oneShot && isCompoundCycle(*oneShot);  // G70–G75: after F, S, T
  if (oneShot && !compound) {
    if (auto status = applyOneShot(*oneShot); !status.ok()) return status.error();
  }
  if (auto status = applyFeed(); !status.ok()) return status.error();
  if (auto status = applySpindleSpeed(); !status.ok()) return status.error();
  if (auto status = applyTool(); !status.ok()) return status.error();

  // M03/M04/M08 act before the block's motion, M05/M09 after it (as on the controls).
  const auto spindle = block_.mCode(MGroup::Spindle);
  const auto coolant = block_.mCode(MGroup::Coolant);
  if (spindle && spindle->number != 5) {
    state_.spindleOn = true;
    state_.spindleDirection = spindle->number == 3 ? SpindleDirection::Clockwise : SpindleDirection::CounterClockwise;
  }
  if (coolant && coolant->number == 8) state_.coolantOn = true;

  const Status moved = compound   ? applyCompoundCycle(*oneShot)
                       : oneShot  ? success()
                       : drills   ? applyDrillingCycle(drillCode)
                                  : applyMotion();
  if (!moved.ok()) return moved.error();
  if (auto status = checkAllWordsUsed(); !status.ok()) return status.error();
  if (auto status = checkToolCalledBeforeCut(); !status.ok()) return status.error();
  if (!chainedThread_) {  // any other block ends a chain of G32 cuts
    state_.threadChainAngleDeg.reset();
    state_.threadChainRunout = {};
  }

  if (spindle && spindle->number == 5) state_.spindleOn = false;
  if (coolant && coolant->number == 9) state_.coolantOn = false;
  if (block_.mCode(MGroup::ProgramEnd)) state_.ended = true;
  return BlockOutcome{std::move(state_), std::move(moves_), std::move(warnings_), std::move(cycleStarts_), flow_};
}

Status Executor::applySubprogramCode() {
  const auto code = block_.mCode(MGroup::Subprogram);
  if (!code) return success();
  if (code->number == 99) {
    SubprogramReturn giveBack{code->column, std::nullopt, 0};
    if (const auto p = block_.take('P')) {
      auto sequence = labelNumberOf(*p, block_.line, kMaxSequenceDigits, "a sequence number to return to");
      if (!sequence.ok()) return sequence.error();
      giveBack.sequence = sequence.value();
      giveBack.sequenceColumn = p->column;
    }
    flow_.giveBack = giveBack;
    return success();
  }
  if (code->number == 97 && options_.dialect != Dialect::Haas) {
    return errorAt(code->column, fmt::format("M97 is Haas's local subprogram call, not a code of dialect {}: choose "
                                             "--dialect haas, or call an O program with M98",
                                             dialectName(options_.dialect)));
  }
  auto call = code->number == 97 ? takeLocalSubprogramCall(block_, *code) : takeSubprogramCall(block_, *code);
  if (!call.ok()) return call.error();
  flow_.call = call.value();
  return success();
}

Result<AxisWords> Executor::takeAxisWords(Coordinates meaning) {
  AxisWords axes{block_.take('X'), block_.take('U'), block_.take('Z'), block_.take('W')};
  if (state_.incremental && meaning == Coordinates::Target) {
    // Under G91 an X word is a distance like U (and U stays one): both given is the
    // same two-words-for-one-axis mistake as X with U, and is caught below.
    if (axes.x && !axes.u) std::swap(axes.x, axes.u);
    if (axes.z && !axes.w) std::swap(axes.z, axes.w);
  }
  // X with U (Z with W): the GSK takes the absolute word (§3.2), other controls alarm. Under
  // G91 both are distances: always an error.
  const bool absoluteWins = options_.control.absoluteWithIncremental == AbsoluteWithIncremental::AbsoluteWins &&
                            !state_.incremental;
  for (auto [absolute, incremental, axis] : {std::tuple{&axes.x, &axes.u, 'X'}, std::tuple{&axes.z, &axes.w, 'Z'}}) {
    if (!*absolute || !*incremental) continue;
    if (!absoluteWins) {
      return errorAt(std::max((*absolute)->column, (*incremental)->column),
                     fmt::format("{} and {} both give the {} axis ({} absolute, {} incremental); give one of them",
                                 (*absolute)->text(), (*incremental)->text(), axis, axis, axis == 'X' ? 'U' : 'W'));
    }
    warnings_.push_back({block_.line, (*incremental)->column,
                         fmt::format("{} is ignored: {} in the same block gives the {} axis (the absolute word "
                                     "wins, GSK980TDi §3.2)",
                                     (*incremental)->text(), (*absolute)->text(), axis)});
    incremental->reset();
  }
  return axes;
}

Status Executor::applyFeed() {
  const auto f = block_.take('F');
  if (!f) return success();
  if (f->value < 0) {
    return errorAt(f->column, fmt::format("{} is not a feed rate: expected a number ≥ 0 "
                                          "(mm/rev under G99, mm/min under G98)",
                                          f->text()));
  }
  state_.feed = reading().mm(f->value);  // mm (inch) per minute or revolution
  state_.feedWord = f->text();
  feedGivenHere_ = true;
  return success();
}

// G96 / G97 (lathe-cycles.md §7). G97 with no S after G96 keeps the rpm the spindle turns
// at here, where G96 leaves it; the G96 surface speed is remembered for the next G96.
void Executor::applySpindleMode() {
  const auto code = block_.gCode(GGroup::SpindleMode);
  if (!code) return;
  const SpindleMode mode = code->number == 96 ? SpindleMode::SurfaceSpeed : SpindleMode::Rpm;
  if (mode == SpindleMode::Rpm && state_.spindleMode == SpindleMode::SurfaceSpeed) {
    state_.spindleSpeed = surfaceSpeedRpm(state_.surfaceSpeedMPerMin, state_.position.x(),
                                          state_.spindleLimitRpm, options_.machine);
  }
  if (mode == SpindleMode::SurfaceSpeed && state_.spindleMode == SpindleMode::Rpm)
    state_.surfaceSpeedAwaitingMove = std::pair{block_.line, code->column};
  if (mode == SpindleMode::Rpm) state_.surfaceSpeedAwaitingMove.reset();
  state_.spindleMode = mode;
}

Status Executor::applySpindleSpeed() {
  const auto s = block_.take('S');
  if (!s) return success();
  if (s->value < 0) {
    return errorAt(s->column,
                   fmt::format("{} is not a spindle speed: expected a number ≥ 0", s->text()));
  }
  // Under G96, S is a surface speed: m/min, or ft/min under G20.
  if (state_.spindleMode == SpindleMode::SurfaceSpeed)
    state_.surfaceSpeedMPerMin = state_.inch ? s->value * kMetresPerFoot : s->value;
  else
    state_.spindleSpeed = s->value;
  return success();
}

Status Executor::applyTool() {
  const auto t = block_.take('T');
  const auto toolChange = block_.mCode(MGroup::ToolChange);
  if (toolChange && !t) {
    warnings_.push_back({block_.line, toolChange->column,
                         fmt::format("{} changes to the tool a T word in its block names, and this block has "
                                     "none: the tool in place stays (write {} T0101)",
                                     toolChange->text, toolChange->text)});
  }
  if (!t) return success();
  auto read = readToolWord(*t, options_.control.toolWordForms, block_.line, toolChange.has_value());
  if (!read.ok()) return read.error();
  const auto [tool, offset, note] = read.value();
  if (note) warnings_.push_back({block_.line, t->column, *note});
  state_.toolOffset = offset;
  state_.offset = offsetNumbered(offsetTable(), offset);
  if (tool == 0 && offset == 0) state_.toolCalled = false;  // T0, T00: no tool selected
  if (tool == 0) return success();  // no tool change
  const auto& tools = options_.toolNumbers;
  if (std::find(tools.begin(), tools.end(), tool) == tools.end() && options_.toolDefinitionHint && place_) {
    std::vector<std::string> seen;  // the program's T words, each once, where first written
    std::string used;
    for (std::size_t ordinal = 0; ordinal < place_->program.blockCount(); ++ordinal) {
      const ProgramBlock b = place_->program.block(ordinal);
      const auto words = place_->program.plainWords(b);
      if (!words || !words->has('T')) continue;
      const std::string text = words->words.at('T').text();
      if (std::find(seen.begin(), seen.end(), text) != seen.end()) continue;
      seen.push_back(text);
      used += fmt::format("{}{} (line {})", used.empty() ? "" : ", ", text, b.line);
    }
    return errorAt(t->column,
                   fmt::format("tool {} ({}) is defined neither in the setup nor by a comment on its "
                               "block naming an insert (CNMG 120408) or a kind (GROOVE 3MM, DRILL 12, "
                               "THREAD 60 DEG); the program's tools: {}; add it to the setup:\n{}",
                               tool, t->text(), used, options_.toolDefinitionHint(tool)));
  }
  if (std::find(tools.begin(), tools.end(), tool) == tools.end()) {
    std::string defined;
    for (int number : tools) defined += (defined.empty() ? "" : ", ") + std::to_string(number);
    return errorAt(t->column,
                   fmt::format("tool {} ({}) is not defined in the setup; defined tools: {} "
                               "(T is written tool number then offset number, e.g. T0101)",
                               tool, t->text(), defined.empty() ? "none" : defined));
  }
  state_.tool = tool;
  state_.toolCalled = true;
  return success();
}

// A block that cuts (a feed move, an arc, a thread, a cycle's legs) with no tool selected: no
// T word has named one (and the setup names none mounted), or T0/T00 deselected it. The
// program relies on the tool the turret was left at, without its offset. Refused or warned of
// once, as the control's cut_without_tool says.
Status Executor::checkToolCalledBeforeCut() {
  if (state_.toolCalled || state_.cutWithoutToolSaid) return success();
  const auto cuts = std::find_if(moves_.begin(), moves_.end(), [](const Move& m) {
    return m.kind != MoveKind::Rapid && m.kind != MoveKind::Dwell;
  });
  if (cuts == moves_.end()) return success();
  const bool refused = options_.control.cutWithoutTool == CutWithoutTool::Error;
  const std::string message =
      fmt::format("this block cuts with no tool selected (no T word has named one, or T0/T00 deselected it): {}; "
                  "call the tool first (T0101, or M06 T0101 on a trainer)",
                  refused ? "this control does not cut with no tool selected (cut_without_tool = error)"
                          : fmt::format("the machine cuts with the tool its turret was left at, tool {} assumed",
                                        state_.tool));
  if (refused) return Error{block_.line, block_.column, message};
  warnings_.push_back({block_.line, block_.column, message});
  state_.cutWithoutToolSaid = true;
  return success();
}

Status Executor::applyOneShot(const Code& code) {
  if (code.number == 4) return applyDwell(code);
  // Every other one-shot code ends a G90/G94 cycle's retained values (GSK 3.21.2 note 2).
  state_.cycle = {};
  state_.threadCycle = {};
  if (code.number == 50) return applyCoordinateSetting(code);
  if (code.number == 28 || code.number == 30) return applyReferenceReturn(code);
  if (code.number == 53) return applyMachineCoordinateMove(code);
  if (code.number == 10) return applyDataSetting(block_, code, state_, options_);
  return errorAt(code.column, fmt::format("{} is not supported by lathesim yet", code.text));
}

// G04 (GSK980TDi §3.14): X or U in seconds, P in milliseconds; with several, P wins over X and
// X over U (the others are warned as ignored); none is an exact stop between blocks (no time);
// a negative time dwells 0 s. A Haas control (g04_p = "seconds_with_point") reads a P written
// with a decimal point (or from a macro value) in seconds: G04 P1.5 is 1.5 s, G04 P1500 1.5 s.
Status Executor::applyDwell(const Code&) {
  std::optional<Word> time;
  for (char letter : {'P', 'X', 'U'}) {
    auto word = block_.take(letter);
    if (!word) continue;
    if (time) {
      warnings_.push_back({block_.line, word->column,
                           fmt::format("{} is ignored: {} gives G04's time (P before X before U, GSK980TDi §3.14)",
                                       word->text(), time->text())});
      continue;
    }
    time = word;
  }
  if (!time) return success();
  const bool pInSeconds = options_.control.dwellPWord == DwellPWord::SecondsWithPoint &&
                          (time->evaluated || hasDecimalPoint(*time));
  const double seconds = time->letter != 'P' ? dwellSeconds(*time, reading())
                         : pInSeconds        ? time->value
                                             : time->value / kMsPerS;
  emit(MoveKind::Dwell, state_.position, state_.position, 0);
  moves_.back().dwellS = std::max(seconds, 0.0);
  return success();
}

Status Executor::applyCoordinateSetting(const Code&) {
  // G50 X(U) Z(W) (GSK980TDi §3.18): the tool is declared to stand at these coordinates; it
  // does not move, the program's frame does. An axis not given keeps its coordinate, so a
  // bare G50 changes nothing.
  auto axes = takeAxisWords(Coordinates::Declared);
  if (!axes.ok()) return axes.error();
  const AxisWords& a = axes.value();
  const auto s = block_.take('S');
  RZ declared = state_.position;
  if (a.x) declared.x() = length(*a.x) / 2.0;
  if (a.u) declared.x() += length(*a.u) / 2.0;
  if (a.z) declared.y() = length(*a.z);
  if (a.w) declared.y() += length(*a.w);
  state_.frame.coordinateSetting += state_.position - declared;
  state_.position = declared;
  if (s) state_.spindleLimitRpm = s->value;
  return success();
}

Status Executor::applyReferenceReturn(const Code& code) {
  auto axes = takeAxisWords();
  if (!axes.ok()) return axes.error();
  const AxisWords& a = axes.value();
  // G30 goes to the second reference point (P2, the default; the setup's second_reference).
  const bool second = code.number == 30;
  if (second) {
    if (const auto p = block_.take('P'); p && p->value != 2) {
      return errorAt(p->column, fmt::format("G30 {}: only the second reference point (P2) is known; a third or "
                                            "fourth is not in the setup",
                                            p->text()));
    }
    if (!options_.secondReferencePosition) {
      return errorAt(code.column, "G30 returns to the second reference point, which the setup does not give: add "
                                  "[machine] second_reference = [X, Z]");
    }
  }
  // Haas: G28 with no axis word sends every axis home, straight from where it stands.
  const bool everyAxis = !a.any() && options_.dialect == Dialect::Haas;
  if (!a.any() && !everyAxis) {
    return errorAt(code.column, fmt::format("{} needs X(U) and/or Z(W): the intermediate point of the axes "
                                            "to return ({} U0 W0 returns both straight from here)",
                                            code.text, code.text));
  }
  const RZ& p = state_.position;
  std::optional<double> radiusMm, zMm;
  if (everyAxis) {
    radiusMm = p.x();
    zMm = p.y();
  }
  if (a.x) radiusMm = length(*a.x) / 2.0;
  if (a.u) radiusMm = p.x() + length(*a.u) / 2.0;
  if (a.z) zMm = length(*a.z);
  if (a.w) zMm = p.y() + length(*a.w);
  // The reference point is the machine's: in the program's frame it moves with G54–G59 and G50.
  const RZ machinePoint = second ? *options_.secondReferencePosition
                                 : options_.referencePosition.value_or(options_.startPosition);
  const RZ reference = machinePoint - state_.frame.shift();
  const std::vector<CycleLeg> legs = referenceReturnLegs(p, radiusMm, zMm, reference);
  // Under G41/G42 the compensation is suspended at the intermediate point (lathe-cycles.md §10):
  // the legs are no part of the chain, which ends with the move before them and resumes with a
  // start-up after them.
  const std::size_t first = moves_.size();
  emitLegs(legs);
  // The reference point is a position of the machine: the axes that return reach it without the
  // tool offset (GSK980TDi §3.15 note 4; Fanuc 0i-TC B-64114EN §14.1.6, the vector is not
  // reflected in the G28 block), while the intermediate point is a programmed one and keeps it.
  for (std::size_t i = first; i < moves_.size(); ++i) {
    if (moves_[i].cycleStep != 2) continue;
    if (radiusMm) moves_[i].offsetShift.x() = 0;
    if (zMm) moves_[i].offsetShift.y() = 0;
  }
  if (!legs.empty()) state_.position = legs.back().to;
  // GSK No.182#2: arrived at the reference, the control forgets the tool offset until a T word.
  if (options_.control.offsetAfterReturn == OffsetAfterReturn::Cancelled) {
    state_.toolOffset = 0;
    state_.offset = offsetNumbered(offsetTable(), 0);
  }
  return success();
}

void Executor::selectMotion(const Code& code) {
  const MotionMode mode = code.number == 0    ? MotionMode::Rapid
                          : code.number == 1  ? MotionMode::Linear
                          : code.number == 2  ? MotionMode::ArcCW
                          : code.number == 3  ? MotionMode::ArcCCW
                          : code.number == 32 ? MotionMode::Thread
                          : code.number == 90 ? MotionMode::AxialCycle
                          : code.number == 92 ? MotionMode::ThreadCycle
                                              : MotionMode::FaceCycle;
  // Another group-01 code ends the cycle's retained values (GSK 3.21.2 note 2); G90 and
  // G94 are two such codes, so switching between them clears them too. Only a cycle
  // retains values, so naming the current mode again keeps them.
  if (mode != state_.motion) {
    state_.cycle = {};
    state_.threadCycle = {};
    state_.drillCancelWithCycle.reset();
  }
  state_.motion = mode;
}

Status Executor::applyMachineCoordinateMove(const Code& code) {
  auto target = machineCoordinateTarget(block_, code, state_, options_);
  if (!target.ok()) return target.error();
  state_.noseSide = NoseSide::None;  // G53 cancels G41/G42 (GSK980TDi 3.20): its move is the cancel
  emit(MoveKind::Rapid, state_.position, target.value(), 0);
  state_.position = target.value();
  return success();
}

// G54–G59 before the block's motion, so the block's own move is in the new system. In a G50
// block the selection is ignored and G50 acts (GSK980TDi 3.21 note 6).
void Executor::applyWorkSystem(const std::optional<Code>& oneShot) {
  const auto code = block_.gCode(GGroup::WorkCoordinates);
  if (!code) return;
  if (oneShot && oneShot->number == 50) {
    warnings_.push_back({block_.line, code->column,
                         fmt::format("{} in a G50 block is ignored: G50 sets the coordinates "
                                     "(GSK980TDi 3.21); select the work system in a block of its own",
                                     code->text)});
    return;
  }
  selectWorkSystem(*code, state_);
}

// G80 cancels the drilling cycles (group 10 on Fanuc T and GSK: G83–G89); it does not end
// G90/G92/G94, which only another group-01 code ends. Remember it, so that a block that then
// repeats such a cycle says so.
void Executor::noteDrillingCycleCancel() {
  const auto code = block_.gCode(GGroup::DrillingCycle);
  if (!code) return;
  if (state_.motion == MotionMode::AxialCycle || state_.motion == MotionMode::FaceCycle ||
      state_.motion == MotionMode::ThreadCycle)
    state_.drillCancelWithCycle = std::pair{block_.line, code->column};
}

void Executor::warnIfCycleRepeatsAfterG80(const std::optional<Code>& code, std::string_view name) {
  const auto g80 = state_.drillCancelWithCycle;
  state_.drillCancelWithCycle.reset();
  if (code || !g80) return;
  warnings_.push_back({block_.line, block_.column,
                       fmt::format("this block repeats {}: the G80 on line {} cancels drilling "
                                   "cycles only, and {} stays modal until a G00, G01, G02 or G03 "
                                   "(Fanuc and GSK group 01)",
                                   name, g80->first, name)});
}

Status Executor::applyMotion() {
  const auto code = block_.gCode(GGroup::Motion);
  if (code) selectMotion(*code);
  switch (state_.motion) {
    case MotionMode::AxialCycle: return applySingleCycle(kAxialCycle, code);
    case MotionMode::FaceCycle: return applySingleCycle(kFaceCycle, code);
    case MotionMode::Thread: return applyThreadCut(code);
    case MotionMode::ThreadCycle: return applyThreadCycle(code);
    case MotionMode::ArcCW:
    case MotionMode::ArcCCW: return applyArc(code);
    case MotionMode::Rapid:
    case MotionMode::Linear: break;
  }
  return applyStraightMove(code);
}

Status Executor::applyStraightMove(const std::optional<Code>& code) {
  auto axes = takeAxisWords();
  if (!axes.ok()) return axes.error();
  const AxisWords& a = axes.value();
  const std::optional<Word> angle = takeAngleWord();
  if (angle && !a.any()) {
    return errorAt(angle->column, fmt::format("{} alone starts a drawing dimension of two lines (their "
                                              "intersection found by the control), which lathesim does not read "
                                              "yet; give this line's end X or Z with the angle",
                                              angle->text()));
  }
  if (!a.any()) return success();
  const RZ from = state_.position;
  RZ to = endPoint(a);
  const bool givesX = a.x || a.u;
  const bool givesZ = a.z || a.w;
  if (angle && givesX && givesZ) {
    warnings_.push_back({block_.line, angle->column,
                         fmt::format("{} is ignored: X and Z give the end point (GSK980TDi §3.13)", angle->text())});
  } else if (angle) {
    auto end = lineEndByAngle(from, givesX ? std::optional(to.x()) : std::nullopt,
                              givesZ ? std::optional(to.y()) : std::nullopt, angleDegrees(*angle), *angle,
                              block_.line);
    if (!end.ok()) return end.error();
    to = end.value();
  }
  const bool feed = state_.motion == MotionMode::Linear;
  auto corner = feed ? takeCornerWord() : Result<std::optional<CornerRequest>>(std::nullopt);
  if (!corner.ok()) return corner.error();
  if (feed && !state_.feed) {
    return errorAt(code ? code->column : block_.column,
                   "feed rate F is not set: give F (e.g. F0.2 mm/rev) before the first G01 move");
  }
  if (auto problem = feed ? zeroFeedProblem(state_.feed, "G01") : std::nullopt)
    return errorAt(code ? code->column : block_.column, *problem);
  const std::size_t before = moves_.size();
  emit(feed ? MoveKind::Feed : MoveKind::Rapid, from, to, 0);
  if (corner.value() && moves_.size() > before)
    moves_.back().cornerAfter = std::make_shared<const CornerRequest>(std::move(*corner.value()));
  state_.position = to;
  return success();
}

// L / D (GSK §3.11) or ,C / ,R (Fanuc): a chamfer or a corner radius after this block's move.
Result<std::optional<CornerRequest>> Executor::takeCornerWord() {
  const bool gsk = options_.control.cornerWords == CornerWords::LD;
  const auto chamfer = block_.take(gsk ? 'L' : 'c');
  const auto round = block_.take(gsk ? 'D' : 'r');
  if (chamfer && round) {
    return errorAt(round->column, fmt::format("{} and {} both ask for a corner; give one of them", chamfer->text(),
                                              round->text()));
  }
  const std::optional<Word>& word = chamfer ? chamfer : round;
  if (!word) return std::optional<CornerRequest>();
  if (word->value <= 0) {
    return errorAt(word->column, fmt::format("{} is not a {}: expected a size > 0", word->text(),
                                             chamfer ? "chamfer" : "corner radius"));
  }
  const bool chamferLength = chamfer && gsk && options_.control.chamferSize == ChamferSize::Length;
  return std::optional(CornerRequest{!chamfer, length(*word), chamferLength, word->text(), word->column});
}

std::optional<Word> Executor::takeAngleWord() {
  switch (options_.control.drawingAngleWord) {
    case DrawingAngleWord::Q: return block_.take('Q');
    case DrawingAngleWord::A: return block_.take('A');
    case DrawingAngleWord::CommaA: return block_.take('a');
  }
  return std::nullopt;
}

// An angle in degrees: GSK's Q counts 0.001° without a point (an [LII] word, No.182#7), Fanuc's
// A follows the decimal point input like a length.
double Executor::angleDegrees(const Word& angle) const {
  const bool incrementWord = options_.control.drawingAngleWord == DrawingAngleWord::Q;
  const NumberReading r = reading();
  const bool counted = !hasDecimalPoint(angle) &&
                       (incrementWord ? r.incrementWordInput == IncrementWordInput::LeastIncrements
                                      : r.decimalPointInput == DecimalPointInput::LeastIncrements);
  return counted ? angle.value * r.leastIncrementMm : angle.value;  // 0.001° at IS-B
}

RZ Executor::endPoint(const AxisWords& a) {
  RZ to = state_.position;
  if (a.x) to.x() = length(*a.x) / 2.0;
  if (a.u) to.x() += length(*a.u) / 2.0;
  if (a.z) to.y() = length(*a.z);
  if (a.w) to.y() += length(*a.w);
  return to;
}

std::optional<ArcWord> Executor::arcWord(char letter) {
  const auto word = block_.take(letter);
  if (!word) return std::nullopt;
  return ArcWord{word->text(), word->column, length(*word)};  // I: a radius
}

// G02/G03 (interp/motion/arc_move.hpp): one arc move to the end point; nothing without axis or
// centre words.
Status Executor::applyArc(const std::optional<Code>& code) {
  const bool clockwise = state_.motion == MotionMode::ArcCW;
  const std::string_view name = clockwise ? "G02" : "G03";
  const int anchor = code ? code->column : block_.column;
  auto axes = takeAxisWords();
  if (!axes.ok()) return axes.error();
  ArcRequest arc{name, clockwise, state_.position, endPoint(axes.value()),
                 arcWord('R'), arcWord('I'), arcWord('K'), block_.line, anchor};
  if (!axes.value().any() && !arc.r && !arc.i && !arc.k) return success();
  auto corner = takeCornerWord();
  if (!corner.ok()) return corner.error();
  if (corner.value()) {
    return errorAt(corner.value()->column, fmt::format("{} after an arc: chamfers and corners next to arcs are not "
                                                       "simulated yet; give the corner as its own G01 or G02/G03",
                                                       corner.value()->word));
  }
  if (state_.plane != Plane::ZX) {
    return errorAt(anchor, fmt::format("{} under {}: this machine has no Y axis, so an arc "
                                       "needs the ZX plane; select it with G18",
                                       name, state_.plane == Plane::XY ? "G17" : "G19"));
  }
  if (!state_.feed) {
    return errorAt(anchor, fmt::format("feed rate F is not set: give F (e.g. F0.2 mm/rev) "
                                       "before the first {} move",
                                       name));
  }
  if (auto problem = zeroFeedProblem(state_.feed, name)) return errorAt(anchor, *problem);
  arc.radiusToleranceMm = options_.control.arcRadiusToleranceMm;
  arc.endOffCircle = options_.control.arcEndOffCircle;
  const auto centre = arcCentre(arc);
  if (!centre.ok()) return centre.error();
  warnings_.insert(warnings_.end(), centre.value().warnings.begin(), centre.value().warnings.end());
  if (!centre.value().centre) return success();  // R to the start point: no move
  emit(clockwise ? MoveKind::ArcCW : MoveKind::ArcCCW, arc.start, arc.end, 0, *centre.value().centre);
  state_.position = arc.end;
  return success();
}

Status Executor::applySingleCycle(const SingleCycle& cycle, const std::optional<Code>& code) {
  const char taperLetter = cycleTaperLetter(cycle.code, options_.dialect);
  // A block runs the cycle when it gives any of X U Z W R; the code alone (a G90 on a safety
  // line) makes it the modal motion and moves nothing.
  if (!block_.has('X') && !block_.has('U') && !block_.has('Z') && !block_.has('W') && !block_.has(taperLetter)) {
    return success();
  }
  const int anchor = code ? code->column : block_.column;
  const std::string name = writtenGCode(cycle.code, GGroup::Motion, options_.dialect);
  warnIfCycleRepeatsAfterG80(code, name);
  if (state_.plane != Plane::ZX) {
    return errorAt(anchor, fmt::format("{} under {}: this machine has no Y axis, so a cycle "
                                       "needs the ZX plane; select it with G18",
                                       name, state_.plane == Plane::XY ? "G17" : "G19"));
  }
  auto axes = takeAxisWords();
  if (!axes.ok()) return axes.error();
  const AxisWords& a = axes.value();
  const auto r = block_.take(taperLetter);
  const RZ start = state_.position;  // A
  CycleRetained& kept = state_.cycle;

  std::optional<double> xDiameterMm = kept.xDiameterMm;
  if (a.x) xDiameterMm = length(*a.x);
  if (a.u) xDiameterMm = diameterOf(start) + length(*a.u);
  std::optional<double> zMm = kept.zMm;
  if (a.z) zMm = length(*a.z);
  if (a.w) zMm = start.y() + length(*a.w);
  if (!xDiameterMm || !zMm) {
    return errorAt(anchor, fmt::format("{0} needs X(U) and Z(W): the end point's {1} is neither "
                                       "in this block nor kept from an earlier {0} block",
                                       name, !xDiameterMm ? "X(U)" : "Z(W)"));
  }
  const double rMm = r ? length(*r) : kept.rMm.value_or(0.0);
  if (!state_.feed) {
    return errorAt(anchor, fmt::format("feed rate F is not set: {} cuts at feed; give F (e.g. "
                                       "F0.2 mm/rev) in this block or before it",
                                       name));
  }
  if (auto problem = zeroFeedProblem(state_.feed, name)) return errorAt(anchor, *problem);
  // The alarm compares R with the travel U (G90, a diameter) or W (G94); without R in this
  // block it points at that travel's word.
  const double travelMm = cycle.taperAgainstX ? *xDiameterMm - diameterOf(start) : *zMm - start.y();
  if (auto problem = cycle.taperProblem(travelMm, rMm)) {
    const std::optional<Word>& absolute = cycle.taperAgainstX ? a.x : a.z;
    const std::optional<Word>& incremental = cycle.taperAgainstX ? a.u : a.w;
    const int column = r             ? r->column
                       : absolute    ? absolute->column
                       : incremental ? incremental->column
                                     : anchor;
    return errorAt(column, *problem);
  }
  kept = CycleRetained{xDiameterMm, zMm, rMm};
  cycleStarts_.push_back({ordinal_, block_.line, block_.column, start + state_.frame.shift(), name});
  const RZ end(*xDiameterMm / 2.0, *zMm);  // C
  const NoseComp comp = noseCompWith(state_.noseSide, state_.offset);
  emitLegs(noseCompensatedCycle(cycle.legs(start, end, rMm), start, cycle.taperAgainstX, comp));
  return success();  // the cycle ends at A: the position is unchanged
}

// G32 (lathe-cycles.md §2, interp/cycles/thread_cut.hpp): a cut synchronised with the
// spindle, from here to the end point. The first G32 of a chain waits for the spindle to
// reach Q; a G32 block right after another starts where that one's cut ended, its Q
// ignored. No move without axis words.
Status Executor::applyThreadCut(const std::optional<Code>& code) {
  const ThreadingWords words = threadingWords(options_.dialect);
  const std::string name = writtenGCode(32, GGroup::Motion, options_.dialect);
  const int anchor = code ? code->column : block_.column;
  auto axes = takeAxisWords();
  if (!axes.ok()) return axes.error();
  if (state_.plane != Plane::ZX) {
    return errorAt(anchor, fmt::format("{} under {}: this machine has no Y axis, so a thread needs the ZX "
                                       "plane; select it with G18",
                                       name, state_.plane == Plane::XY ? "G17" : "G19"));
  }
  auto lead = takeLeadMm(block_, state_, words, options_.control, name, anchor, feedGivenHere_);
  if (!lead.ok()) return lead.error();
  auto angle = takeStartAngleDeg(block_, name, warnings_);
  if (!angle.ok()) return angle.error();
  auto runoutWords = takeRunoutWords(block_, reading(), words, state_.threadChainRunout, true, name);
  if (!runoutWords.ok()) return runoutWords.error();
  if (!axes.value().any()) return success();  // a block that cuts nothing ends the chain
  state_.threadChainRunout = runoutWords.value();
  chainedThread_ = true;

  threadStateWarnings(state_, block_.line, anchor, name, warnings_);
  const RZ from = state_.position;
  const RZ to = endPoint(axes.value());
  ThreadMotion motion;
  motion.leadMm = lead.value();
  motion.startAngleDeg = state_.threadChainAngleDeg.value_or(angle.value());
  const std::vector<CycleLeg> legs = threadCutLegs(from, to, chainRunout(state_.threadChainRunout), motion, 0);
  warnIfThreadTooFast(legs, anchor);
  emitLegs(legs);
  const CycleLeg& last = legs.back();
  state_.threadChainAngleDeg = angleAfter(last.thread.startAngleDeg, last.thread.revolutions(last.from, last.to));
  state_.position = last.to;
  return success();
}

// G92 (lathe-cycles.md §1, interp/cycles/g92_cycle.hpp): G90's words and modal repetition,
// the cut a thread with a run-out, and the starts of a multi-start thread.
Status Executor::applyThreadCycle(const std::optional<Code>& code) {
  const ThreadingWords words = threadingWords(options_.dialect);
  const char taperLetter = cycleTaperLetter(92, options_.dialect);
  // As G90: the code alone makes it the modal motion and moves nothing.
  if (!block_.has('X') && !block_.has('U') && !block_.has('Z') && !block_.has('W') && !block_.has(taperLetter)) {
    return success();
  }
  const int anchor = code ? code->column : block_.column;
  const std::string name = writtenGCode(92, GGroup::Motion, options_.dialect);
  warnIfCycleRepeatsAfterG80(code, name);
  if (state_.plane != Plane::ZX) {
    return errorAt(anchor, fmt::format("{} under {}: this machine has no Y axis, so a cycle "
                                       "needs the ZX plane; select it with G18",
                                       name, state_.plane == Plane::XY ? "G17" : "G19"));
  }
  auto axes = takeAxisWords();
  if (!axes.ok()) return axes.error();
  const AxisWords& a = axes.value();
  const auto r = block_.take(taperLetter);
  auto lead = takeLeadMm(block_, state_, words, options_.control, name, anchor, feedGivenHere_);
  if (!lead.ok()) return lead.error();
  ThreadCycleRetained& threadKept = state_.threadCycle;
  auto runoutWords = takeRunoutWords(block_, reading(), words, threadKept.runout, words.hncRunoutRE, name);
  if (!runoutWords.ok()) return runoutWords.error();
  int starts = threadKept.starts;
  double firstStartDeg = threadKept.firstStartDeg;
  const auto startsWord = words.startsL ? block_.take('L') : words.hncStartsCP ? block_.take('C') : std::nullopt;
  if (startsWord) {
    if (startsWord->value < 0 || startsWord->value > 99 || std::floor(startsWord->value) != startsWord->value) {
      return errorAt(startsWord->column, fmt::format("{} {} is not a number of starts: expected a whole number 1 "
                                                     "to 99",
                                                     name, startsWord->text()));
    }
    starts = std::max(1, static_cast<int>(startsWord->value));  // HNC: C0 is one start
  }
  if (words.hncStartsCP) {
    if (const auto p = block_.take('P')) firstStartDeg = std::fmod(std::abs(p->value), 360.0);
  } else {
    // Fanuc's G92 Q: the start angle in 0.001°, not modal (B-63944EN §4.1.2; as G32's Q).
    auto angle = takeStartAngleDeg(block_, name, warnings_);
    if (!angle.ok()) return angle.error();
    firstStartDeg = angle.value();
  }

  const RZ start = state_.position;  // A
  CycleRetained& kept = state_.cycle;
  std::optional<double> xDiameterMm = kept.xDiameterMm;
  if (a.x) xDiameterMm = length(*a.x);
  if (a.u) xDiameterMm = diameterOf(start) + length(*a.u);
  std::optional<double> zMm = kept.zMm;
  if (a.z) zMm = length(*a.z);
  if (a.w) zMm = start.y() + length(*a.w);
  if (!xDiameterMm || !zMm) {
    return errorAt(anchor, fmt::format("{0} needs X(U) and Z(W): the end point's {1} is neither "
                                       "in this block nor kept from an earlier {0} block",
                                       name, !xDiameterMm ? "X(U)" : "Z(W)"));
  }
  if (*zMm == start.y()) {
    return errorAt(a.z ? a.z->column : a.w ? a.w->column : anchor,
                   fmt::format("{} cannot cut a face thread: its end Z must differ from the start point's Z{:g} "
                               "(use G32 for a face thread)",
                               name, start.y()));
  }
  const double rMm = r ? length(*r) : kept.rMm.value_or(0.0);
  if (auto problem = axialCycleTaperProblem(*xDiameterMm - diameterOf(start), rMm, name)) {
    return errorAt(r ? r->column : a.x ? a.x->column : a.u ? a.u->column : anchor,
                   *problem);
  }
  kept = CycleRetained{xDiameterMm, zMm, rMm};
  threadKept = {runoutWords.value(), starts, firstStartDeg};

  threadStateWarnings(state_, block_.line, anchor, name, warnings_);
  cycleStarts_.push_back({ordinal_, block_.line, block_.column, start + state_.frame.shift(), name});
  ThreadCycleParams params;
  params.leadMm = lead.value();
  // Without run-out words the control's parameter decides (GSK No.19, Fanuc No.5130).
  const ThreadRunout runout =
      words.hncRunoutRE ? ThreadRunout{runoutWords.value().alongMm.value_or(0.0), std::abs(runoutWords.value().acrossMm.value_or(0.0))}
                        : cycleRunout(runoutWords.value(), options_.control.threadRunoutLeads * params.leadMm,
                                      options_.control.threadRunoutAngleDeg);
  params.runoutAlongMm = runout.alongMm;
  params.runoutAcrossMm = std::abs(runout.acrossMm);
  params.starts = starts;
  params.firstStartDeg = firstStartDeg;
  const std::vector<CycleLeg> legs = threadCycleLegs(start, RZ(*xDiameterMm / 2.0, *zMm), rMm, params);
  warnIfThreadTooFast(legs, anchor);
  emitLegs(legs);
  return success();  // the cycle ends at A
}

// The control cannot keep the lead when lead × rpm exceeds the lead axis's fastest motion
// (the setup's rapid rate for that axis): one warning per block.
void Executor::warnIfThreadTooFast(const std::vector<CycleLeg>& legs, int column) {
  for (const CycleLeg& leg : legs) {
    if (leg.kind != MoveKind::Thread || !state_.spindleOn) continue;
    const double nearAxis = std::min(std::abs(leg.from.x()), std::abs(leg.to.x()));
    const double rpm = state_.spindleMode == SpindleMode::Rpm
                           ? constantRpm(state_.spindleSpeed, options_.machine)
                           : surfaceSpeedRpm(state_.surfaceSpeedMPerMin, nearAxis, state_.spindleLimitRpm,
                                             options_.machine);
    const double axisMmPerMin = leg.thread.leadAlongZ ? options_.machine.rapidZMmPerMin : options_.machine.rapidXMmPerMin;
    const double needed = leg.thread.leadMm * rpm;
    if (needed <= axisMmPerMin) continue;
    warnings_.push_back({block_.line, column,
                         fmt::format("a lead of {:g} mm at {:g} rpm needs {:g} mm/min along {}, more than that axis's "
                                     "fastest motion ({:g} mm/min, the setup's rapid rate): the control cannot keep "
                                     "the lead; lower the spindle speed",
                                     leg.thread.leadMm, rpm, needed, leg.thread.leadAlongZ ? "Z" : "X",
                                     axisMmPerMin)});
    return;
  }
}

// G70–G75 (interp/cycles/compound_cycle.hpp) in place of the block's motion.
Status Executor::applyCompoundCycle(const Code& code) {
  state_.cycle = {};  // a one-shot code ends G90/G94's retained values
  const RZ start = state_.position;  // A
  auto outcome = runCompoundCycle(code, block_, state_, options_, place_, feedGivenHere_);
  if (!outcome.ok()) return outcome.error();
  const CompoundOutcome& done = outcome.value();
  // The parameter block of a two-block cycle (G71 U R; …) moves nothing and starts nothing.
  if (!done.legs.empty() || !done.contourMoves.empty())
    cycleStarts_.push_back({ordinal_, block_.line, block_.column, start + state_.frame.shift(), code.text});
  moves_.insert(moves_.end(), done.contourMoves.begin(), done.contourMoves.end());
  warnings_.insert(warnings_.end(), done.warnings.begin(), done.warnings.end());
  if (code.number == 76) warnIfThreadTooFast(done.legs, code.column);
  emitLegs(done.legs);
  flow_.continueAfter = done.continueAfter;
  return success();
}

// A word no code took that names machinery this two-axis, one-spindle lathe does not have.
std::optional<std::string> Executor::missingMachineryOf(const Word& word) const {
  if ((word.letter == 'c' || word.letter == 'r') && options_.control.cornerWords == CornerWords::LD) {
    return fmt::format("{} is Fanuc's corner word (,C a chamfer, ,R a corner radius at the end of the move), which "
                       "this control does not read (its corner words are L and D): run with --control fanuc-0i-t, "
                       "or write {} for it",
                       word.text(), word.letter == 'c' ? 'L' : 'D');
  }
  // A line's angle in the word another control reads it in (drawing_angle_word).
  const bool angleA = word.letter == 'A' && options_.control.drawingAngleWord != DrawingAngleWord::A;
  const bool angleCommaA = word.letter == 'a' && options_.control.drawingAngleWord != DrawingAngleWord::CommaA;
  if (angleA || angleCommaA) {
    const std::string_view own = options_.control.drawingAngleWord == DrawingAngleWord::Q ? "Q" :
                                 options_.control.drawingAngleWord == DrawingAngleWord::A ? "A" : ",A";
    return fmt::format("{} is a line's angle where the control reads its angle in {} (drawing_angle_word), which "
                       "this control does not (its angle word is {}): {}",
                       word.text(), angleA ? "A" : ",A", own,
                       angleA ? "run with --control fanuc-0i-t" : "set drawing_angle_word = \",A\" in the setup's [control]");
  }
  if (word.letter == 'C') {
    return fmt::format("{}: this lathe has no C axis (the spindle cannot be positioned or "
                       "milled around); live tooling and C-axis work cannot be simulated",
                       word.text());
  }
  if (word.letter == 'B') {
    return fmt::format("{}: this lathe has no B axis (a sub-spindle's or a tilting tool "
                       "spindle's travel)",
                       word.text());
  }
  // Fanuc's multi-spindle control selects the spindle with P11, P12, P21, P22 beside S or M03.
  const bool spindleBlock = block_.mCode(MGroup::Spindle) || block_.has('S');
  const bool spindleSelect = word.number == "11" || word.number == "12" || word.number == "21" || word.number == "22";
  if (word.letter == 'P' && spindleSelect && spindleBlock) {
    return fmt::format("{} selects a spindle (multi-spindle control: P11 the main, P12 or P2x a "
                       "sub-spindle); this lathe has one spindle",
                       word.text());
  }
  return std::nullopt;
}

Status Executor::checkAllWordsUsed() const {
  if (block_.words.empty()) return success();
  // Report the leftover word that comes first in the block.
  const Word* first = nullptr;
  for (const auto& [letter, word] : block_.words) {
    if (first == nullptr || word.column < first->column) first = &word;
  }
  if (const auto lacking = missingMachineryOf(*first)) return errorAt(first->column, *lacking);
  return errorAt(first->column, fmt::format("{} is not used by any code in this block; remove "
                                            "it or add the code that takes {}",
                                            first->text(), first->letter));
}

void Executor::emit(MoveKind kind, const RZ& from, const RZ& to, int cycleStep, const RZ& center,
                    const ThreadMotion& thread) {
  // An arc back to its start is a full circle, a dwell stands still: both are kept.
  if (from == to && !isArc(kind) && kind != MoveKind::Dwell) return;
  warnIfSurfaceSpeedUnclamped();
  if (isCutting(kind) && kind != MoveKind::Thread) warnIfFeedImplausible();  // a thread's F is its lead
  Move move;
  move.kind = kind;
  move.from = from;
  move.to = to;
  move.center = center;
  move.feed = isCutting(kind) ? *state_.feed : 0.0;
  move.feedMode = state_.feedMode;
  if (kind == MoveKind::Thread) {  // the lead, per revolution whatever G98/G99 says
    move.feed = thread.leadMm;
    move.feedMode = FeedMode::PerRevolution;
    move.thread = thread;
  }
  move.tool = state_.tool;
  move.toolOffset = state_.toolOffset;
  move.offsetShift = offsetShift(state_.offset);
  move.workShift = state_.frame.shift();
  move.noseComp = noseCompWith(state_.noseSide, state_.offset);
  move.spindleOn = state_.spindleOn;
  move.spindleDirection = state_.spindleDirection;
  move.spindleMode = state_.spindleMode;
  const bool surfaceSpeed = state_.spindleMode == SpindleMode::SurfaceSpeed;
  move.spindleS = surfaceSpeed ? state_.surfaceSpeedMPerMin : state_.spindleSpeed;
  if (surfaceSpeed) move.spindleLimitRpm = state_.spindleLimitRpm;
  move.block = ordinal_;
  move.line = block_.line;
  move.column = block_.column;
  move.cycleStep = cycleStep;
  moves_.push_back(move);
}

// Where a cut first runs at a feed (or feed mode) other than the cut before it's.
void Executor::warnIfFeedImplausible() {
  const std::pair current{*state_.feed, state_.feedMode};
  if (state_.checkedFeed == current) return;
  state_.checkedFeed = current;
  if (auto problem = implausibleFeed(state_.feedWord, current.first, current.second, state_.inch))
    warnings_.push_back({block_.line, block_.column, *problem});
}

// The first move after G96 tells whether G50 S was given in time to limit it.
void Executor::warnIfSurfaceSpeedUnclamped() {
  const auto g96 = state_.surfaceSpeedAwaitingMove;
  if (!g96) return;
  state_.surfaceSpeedAwaitingMove.reset();
  if (state_.spindleLimitRpm) return;
  warnings_.push_back({g96->first, g96->second,
                       fmt::format("G96 with no G50 S before its first move: the spindle speed is "
                                   "limited only by the machine's max_rpm ({:g} rpm); give G50 S "
                                   "(the rpm limit) before G96",
                                   options_.machine.maxRpm)});
}

// G81 Z(W) R F, G82 … P (dwell at the bottom), G83 … Q (peck) [P]: drilling on the axis from
// the tool's position (drilling_cycle.hpp). R is the R point's Z on a Haas (⚠) and its distance
// from the start's Z on Fanuc T (⚠); without it the feed starts where the tool stands. Q is a
// length (Haas) or least increments without a point (Fanuc's [LII]); P counts as G04's P. X may
// only be X0 (U0): with no live tool a drill cuts on the axis alone. G84 Z R F [P] taps: F is
// the lead under G99 (the tap follows the spindle), the spindle must turn, and it reverses for
// the feed back out to R (those moves carry the reversed direction).
Status Executor::applyDrillingCycle(const std::optional<Code>& code) {
  const bool haas = options_.dialect == Dialect::Haas;
  const int cycle = code ? code->number : state_.drillingCycle;
  const std::string name = fmt::format("G{}", cycle);
  const int anchor = code ? code->column : block_.column;
  auto axes = takeAxisWords();
  if (!axes.ok()) return axes.error();
  const AxisWords& a = axes.value();
  RZ start = state_.position;
  if (a.x) start.x() = length(*a.x) / 2.0;
  if (a.u) start.x() += length(*a.u) / 2.0;
  if (std::abs(start.x()) > 1e-9) {
    return errorAt(a.x ? a.x->column : a.u ? a.u->column : anchor,
                   fmt::format("{} drills on the spindle's axis, but the tool would stand at X{:g}: a hole off the axis "
                               "needs live tooling, which this lathe does not have (give X0)",
                               name, 2.0 * start.x()));
  }
  if (code && !a.z && !a.w) return errorAt(anchor, fmt::format("{} needs Z(W): the hole's bottom", name));
  if (a.z) state_.drillingBottomZ = length(*a.z);
  if (a.w) state_.drillingBottomZ = state_.position.y() + length(*a.w);
  const double bottomZ = state_.drillingBottomZ;
  const auto r = block_.take('R');
  const auto q = block_.take('Q');
  const auto p = block_.take('P');
  if (code) {  // a new cycle: its R point, peck and dwell are kept for the blocks that repeat it
    state_.drillingCycle = cycle;
    state_.drillingRPlaneZ = !r ? state_.position.y() : haas ? length(*r) : state_.position.y() + length(*r);
    state_.drillingPeckMm = 0;
    state_.drillingDwellS = 0;
  } else if (r) {
    state_.drillingRPlaneZ = haas ? length(*r) : state_.position.y() + length(*r);
  }
  if (q) {
    if (cycle != 83) return errorAt(q->column, fmt::format("{} {}: only G83 pecks", name, q->text()));
    const double peck = haas ? length(*q) : incrementLengthMm(*q, reading());
    if (!(peck > 0)) return errorAt(q->column, fmt::format("G83 {} is not a peck depth: expected a number > 0", q->text()));
    state_.drillingPeckMm = peck;
  }
  if (p) {
    if (cycle == 81) return errorAt(p->column, fmt::format("G81 {}: G81 does not dwell; G82 dwells P at the bottom", p->text()));
    const bool seconds = options_.control.dwellPWord == DwellPWord::SecondsWithPoint &&
                         (p->evaluated || hasDecimalPoint(*p));
    state_.drillingDwellS = std::max(seconds ? p->value : p->value / kMsPerS, 0.0);
  }
  if (!state_.feed) {
    return errorAt(anchor, fmt::format("feed rate F is not set: {} drills at feed; give F in this block or before it",
                                       name));
  }
  if (auto problem = zeroFeedProblem(state_.feed, name)) return errorAt(anchor, *problem);
  const bool tapping = cycle == 84;
  if (tapping && !state_.spindleOn) {
    return errorAt(anchor, "G84 taps with the spindle turning (the tap follows it down, and the spindle reverses to back "
                           "it out): give M03 (or M04) and S before it");
  }
  const RZ from = state_.position;
  DrillingParams params;
  params.rPlaneZ = state_.drillingRPlaneZ;
  params.bottomZ = bottomZ;
  params.peckMm = state_.drillingPeckMm;
  params.clearanceMm = options_.control.peckRetractMm;
  params.tapping = tapping;
  // X0 in the block: the tool goes to the axis first, at rapid.
  if (from.x() != start.x()) emit(MoveKind::Rapid, from, RZ(start.x(), from.y()), 0);
  const auto drilled = drillingLegs(RZ(start.x(), from.y()), params, options_.maxMoves);
  if (!drilled) return *moveLimitError(options_.maxMoves + 1, options_.maxMoves, block_.line, anchor);
  const DrillingLegs& legs = *drilled;
  emitLegs(legs.down);
  if (state_.drillingDwellS > 0) {
    const RZ bottom(start.x(), bottomZ);
    emit(MoveKind::Dwell, bottom, bottom, 0);
    moves_.back().dwellS = state_.drillingDwellS;
  }
  const std::size_t firstUp = moves_.size();
  emitLegs(legs.up);
  for (std::size_t i = firstUp; i < moves_.size(); ++i) {  // a tap backs out with the spindle reversed
    if (moves_[i].kind != MoveKind::Feed) continue;
    moves_[i].spindleDirection = state_.spindleDirection == SpindleDirection::Clockwise
                                     ? SpindleDirection::CounterClockwise
                                     : SpindleDirection::Clockwise;
  }
  state_.position = RZ(start.x(), from.y());
  return success();
}

// A cycle's legs are never part of a G41/G42 chain (lathe-cycles.md §8): G71–G73 rough
// against a contour already offset, G90/G94 are offset by their tip number
// (cycle_nose_compensation.hpp), G74/G75 and the thread codes get none; an open chain ends
// at the first leg.
void Executor::emitLegs(const std::vector<CycleLeg>& legs) {
  const std::size_t first = moves_.size();
  for (const CycleLeg& leg : legs) emit(leg.kind, leg.from, leg.to, leg.step, leg.center, leg.thread);
  for (std::size_t i = first; i < moves_.size(); ++i) moves_[i].noseComp = {};
}

}  // namespace

Result<BlockOutcome> executeBlock(ParsedBlock block, ModalState state,
                                  const InterpreterOptions& options, int ordinal,
                                  const BlockPlace* place) {
  return Executor(std::move(block), std::move(state), options, ordinal, place).run();
}

}  // namespace lathesim::interp
