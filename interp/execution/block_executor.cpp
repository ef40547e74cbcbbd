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

#include "interp/compensation/tool_offset.hpp"
#include "interp/execution/unused_word.hpp"
#include "interp/cycles/compound_block.hpp"
#include "interp/cycles/compound_cycle.hpp"
#include "interp/cycles/drilling_block.hpp"
#include "interp/cycles/single_cycle_block.hpp"
#include "interp/cycles/thread_block.hpp"
#include "interp/execution/data_setting.hpp"
#include "interp/execution/subprogram_call.hpp"
#include "interp/execution/work_coordinates.hpp"
#include "interp/motion/arc_move.hpp"
#include "interp/motion/drawing_angle.hpp"
#include "interp/motion/g28_return.hpp"
#include "interp/motion/spindle_speed.hpp"
#include "interp/state/block_work.hpp"
#include "interp/text/label_number.hpp"
#include "interp/text/tool_word.hpp"
#include "interp/text/word_units.hpp"

namespace lathesim::interp {
namespace {

constexpr double kMetresPerFoot = 0.3048;  // G96 S under G20 is in ft/min
constexpr double kMsPerS = 1000.0;

// The codes of a block other than the canned cycles (cycles/), applied in the controls'
// order; the cycles run on the same BlockWork.
class Executor {
 public:
  Executor(ParsedBlock block, ModalState state, const InterpreterOptions& options, int ordinal, const BlockPlace* place)
      : work_(std::move(block), std::move(state), options, ordinal), place_(place) {}

  Result<BlockOutcome> run();

 private:
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
  const ToolOffsets& offsetTable() const {
    return work_.state.offsetTable ? *work_.state.offsetTable : work_.options.offsets;
  }
  Status applyMotion();
  Status applyStraightMove(const std::optional<Code>& code);
  Status applyArc(const std::optional<Code>& code);
  std::optional<Word> takeAngleWord();
  Result<std::optional<CornerRequest>> takeCornerWord();
  double angleDegrees(const Word& angle) const;
  std::optional<ArcWord> arcWord(char letter);
  Status applyCompoundCycle(const Code& code);
  Status applySubprogramCode();
  Status checkAllWordsUsed() const;
  Status checkToolCalledBeforeCut();

  BlockWork work_;
  const BlockPlace* place_;  // null for a block run on its own
  ProgramFlow flow_;
};

Result<BlockOutcome> Executor::run() {
  work_.warnings = work_.block.warnings;
  work_.block.take('N');  // sequence number: a label only
  work_.block.take('O');  // program number
  if (auto status = applySubprogramCode(); !status.ok()) return status.error();
  if (auto code = work_.block.gCode(GGroup::Units)) work_.state.inch = code->number == 20;
  if (auto code = work_.block.gCode(GGroup::FeedMode)) {
    work_.state.feedMode = code->number == 98 ? FeedMode::PerMinute : FeedMode::PerRevolution;
  }
  if (auto code = work_.block.gCode(GGroup::Distance)) work_.state.incremental = code->number == kIncrementalDistance;
  if (auto code = work_.block.gCode(GGroup::Plane)) {
    work_.state.plane = code->number == 17 ? Plane::XY : code->number == 19 ? Plane::YZ : Plane::ZX;
  }
  applySpindleMode();
  if (auto code = work_.block.gCode(GGroup::NoseRadius)) {
    work_.state.noseSide = code->number == 41 ? NoseSide::Left : code->number == 42 ? NoseSide::Right : NoseSide::None;
  }

  // A one-shot code takes the block's axis words; a motion code beside it (G28 G00 U0 W0) only
  // becomes the modal motion, as on the controls.
  const auto oneShot = work_.block.gCode(GGroup::NonModal);
  applyWorkSystem(oneShot);
  noteDrillingCycleCancel();
  if (const auto motion = work_.block.gCode(GGroup::Motion); oneShot && motion) selectMotion(*motion);
  // G81–G84 stay in force until G80 or a motion code; a block that gives an axis word drills again
  // (at X0 only: a hole elsewhere needs live tooling, and is refused rather than moved to).
  const auto drillCode = work_.block.gCode(GGroup::DrillingCycle);
  if ((drillCode && drillCode->number == 80) || work_.block.gCode(GGroup::Motion)) work_.state.drillingCycle = 0;
  const bool drills =
      !oneShot && ((drillCode && drillCode->number != 80) ||
                   (!drillCode && work_.state.drillingCycle != 0 &&
                    (work_.block.has('X') || work_.block.has('U') || work_.block.has('Z') || work_.block.has('W'))));
  const bool compound = oneShot && isCompoundCycle(*oneShot);  // G70–G75: after F, S, T
  if (oneShot && !compound) {
    if (auto status = applyOneShot(*oneShot); !status.ok()) return status.error();
  }
  if (auto status = applyFeed(); !status.ok()) return status.error();
  if (auto status = applySpindleSpeed(); !status.ok()) return status.error();
  if (auto status = applyTool(); !status.ok()) return status.error();

  // M03/M04/M08 act before the block's motion, M05/M09 after it (as on the controls).
  const auto spindle = work_.block.mCode(MGroup::Spindle);
  const auto coolant = work_.block.mCode(MGroup::Coolant);
  if (spindle && spindle->number != 5) {
    work_.state.spindleOn = true;
    work_.state.spindleDirection =
        spindle->number == 3 ? SpindleDirection::Clockwise : SpindleDirection::CounterClockwise;
  }
  if (coolant && coolant->number == 8) work_.state.coolantOn = true;

  const Status moved = compound  ? applyCompoundCycle(*oneShot)
                       : oneShot ? success()
                       : drills  ? runDrillingCycle(work_, drillCode)
                                 : applyMotion();
  if (!moved.ok()) return moved.error();
  if (auto status = checkAllWordsUsed(); !status.ok()) return status.error();
  if (auto status = checkToolCalledBeforeCut(); !status.ok()) return status.error();
  if (!work_.chainedThread) {  // any other block ends a chain of G32 cuts
    work_.state.threadChainAngleDeg.reset();
    work_.state.threadChainRunout = {};
  }

  if (spindle && spindle->number == 5) work_.state.spindleOn = false;
  if (coolant && coolant->number == 9) work_.state.coolantOn = false;
  if (work_.block.mCode(MGroup::ProgramEnd)) work_.state.ended = true;
  return BlockOutcome{std::move(work_.state), std::move(work_.moves), std::move(work_.warnings),
                      std::move(work_.cycleStarts), flow_, work_.contourPass, work_.legsCompensated};
}

Status Executor::applySubprogramCode() {
  const auto code = work_.block.mCode(MGroup::Subprogram);
  if (!code) return success();
  if (code->number == 99) {
    SubprogramReturn giveBack{code->column, std::nullopt, 0};
    if (const auto p = work_.block.take('P')) {
      auto sequence = labelNumberOf(*p, work_.block.line, kMaxSequenceDigits, "a sequence number to return to");
      if (!sequence.ok()) return sequence.error();
      giveBack.sequence = sequence.value();
      giveBack.sequenceColumn = p->column;
    }
    flow_.giveBack = giveBack;
    return success();
  }
  if (code->number == 97 && work_.options.dialect != Dialect::Haas) {
    return work_.errorAt(code->column,
                         fmt::format("M97 is Haas's local subprogram call, not a code of dialect {}: choose "
                                     "--dialect haas, or call an O program with M98",
                                     dialectName(work_.options.dialect)));
  }
  auto call = code->number == 97 ? takeLocalSubprogramCall(work_.block, *code) : takeSubprogramCall(work_.block, *code);
  if (!call.ok()) return call.error();
  flow_.call = call.value();
  return success();
}

Status Executor::applyFeed() {
  const auto f = work_.block.take('F');
  if (!f) return success();
  if (f->value < 0) {
    return work_.errorAt(f->column, fmt::format("{} is not a feed rate: expected a number ≥ 0 "
                                                "(mm/rev under G99, mm/min under G98)",
                                                f->text()));
  }
  work_.state.feed = work_.reading().mm(f->value);  // mm (inch) per minute or revolution
  work_.state.feedWord = f->text();
  work_.feedGiven = true;
  return success();
}

// G96 / G97 (lathe-cycles.md §7). G97 with no S after G96 keeps the rpm the spindle turns
// at here, where G96 leaves it; the G96 surface speed is remembered for the next G96.
void Executor::applySpindleMode() {
  const auto code = work_.block.gCode(GGroup::SpindleMode);
  if (!code) return;
  const SpindleMode mode = code->number == 96 ? SpindleMode::SurfaceSpeed : SpindleMode::Rpm;
  if (mode == SpindleMode::Rpm && work_.state.spindleMode == SpindleMode::SurfaceSpeed) {
    work_.state.spindleSpeed = surfaceSpeedRpm(work_.state.surfaceSpeedMPerMin, work_.state.position.x(),
                                               work_.state.spindleLimitRpm, work_.options.machine);
  }
  if (mode == SpindleMode::SurfaceSpeed && work_.state.spindleMode == SpindleMode::Rpm)
    work_.state.surfaceSpeedAwaitingMove = std::pair{work_.block.line, code->column};
  if (mode == SpindleMode::Rpm) work_.state.surfaceSpeedAwaitingMove.reset();
  work_.state.spindleMode = mode;
}

Status Executor::applySpindleSpeed() {
  const auto s = work_.block.take('S');
  if (!s) return success();
  if (s->value < 0) {
    return work_.errorAt(s->column, fmt::format("{} is not a spindle speed: expected a number ≥ 0", s->text()));
  }
  // Under G96, S is a surface speed: m/min, or ft/min under G20.
  if (work_.state.spindleMode == SpindleMode::SurfaceSpeed)
    work_.state.surfaceSpeedMPerMin = work_.state.inch ? s->value * kMetresPerFoot : s->value;
  else
    work_.state.spindleSpeed = s->value;
  return success();
}

Status Executor::applyTool() {
  const auto t = work_.block.take('T');
  const auto toolChange = work_.block.mCode(MGroup::ToolChange);
  if (toolChange && !t) {
    work_.warnings.push_back({work_.block.line, toolChange->column,
                              fmt::format("{} changes to the tool a T word in its block names, and this block has "
                                          "none: the tool in place stays (write {} T0101)",
                                          toolChange->text, toolChange->text)});
  }
  if (!t) return success();
  auto read = readToolWord(*t, work_.options.control.toolWordForms, work_.block.line, toolChange.has_value());
  if (!read.ok()) return read.error();
  const auto [tool, offset, note] = read.value();
  if (note) work_.warnings.push_back({work_.block.line, t->column, *note});
  work_.state.toolOffset = offset;
  work_.state.offset = offsetNumbered(offsetTable(), offset);
  if (tool == 0 && offset == 0) work_.state.toolCalled = false;  // T0, T00: no tool selected
  if (tool == 0) return success();  // no tool change
  const auto& tools = work_.options.toolNumbers;
  if (std::find(tools.begin(), tools.end(), tool) == tools.end() && work_.options.toolDefinitionHint && place_) {
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
    return work_.errorAt(t->column, fmt::format("tool {} ({}) is defined neither in the setup nor by a comment on its "
                                                "block naming an insert (CNMG 120408) or a kind (GROOVE 3MM, DRILL 12, "
                                                "THREAD 60 DEG); the program's tools: {}; add it to the setup:\n{}",
                                                tool, t->text(), used, work_.options.toolDefinitionHint(tool)));
  }
  if (std::find(tools.begin(), tools.end(), tool) == tools.end()) {
    std::string defined;
    for (int number : tools) defined += (defined.empty() ? "" : ", ") + std::to_string(number);
    return work_.errorAt(t->column, fmt::format("tool {} ({}) is not defined in the setup; defined tools: {} "
                                                "(T is written tool number then offset number, e.g. T0101)",
                                                tool, t->text(), defined.empty() ? "none" : defined));
  }
  work_.state.tool = tool;
  work_.state.toolCalled = true;
  return success();
}

// A block that cuts (a feed move, an arc, a thread, a cycle's legs) with no tool selected: no
// T word has named one (and the setup names none mounted), or T0/T00 deselected it. The
// program relies on the tool the turret was left at, without its offset. Refused or warned of
// once, as the control's cut_without_tool says.
Status Executor::checkToolCalledBeforeCut() {
  if (work_.state.toolCalled || work_.state.cutWithoutToolSaid) return success();
  const auto cuts = std::find_if(work_.moves.begin(), work_.moves.end(),
                                 [](const Move& m) { return m.kind != MoveKind::Rapid && m.kind != MoveKind::Dwell; });
  if (cuts == work_.moves.end()) return success();
  const bool refused = work_.options.control.cutWithoutTool == CutWithoutTool::Error;
  const std::string message = fmt::format(
      "this block cuts with no tool selected (no T word has named one, or T0/T00 deselected it): {}; "
      "call the tool first (T0101, or M06 T0101 on a trainer)",
      refused
          ? "this control does not cut with no tool selected (cut_without_tool = error)"
          : fmt::format("the machine cuts with the tool its turret was left at, tool {} assumed", work_.state.tool));
  if (refused) return Error{work_.block.line, work_.block.column, message};
  work_.warnings.push_back({work_.block.line, work_.block.column, message});
  work_.state.cutWithoutToolSaid = true;
  return success();
}

Status Executor::applyOneShot(const Code& code) {
  if (code.number == 4) return applyDwell(code);
  // Every other one-shot code ends a G90/G94 cycle's retained values (GSK 3.21.2 note 2).
  work_.state.cycle = {};
  work_.state.threadCycle = {};
  if (code.number == 50) return applyCoordinateSetting(code);
  if (code.number == 28 || code.number == 30) return applyReferenceReturn(code);
  if (code.number == 53) return applyMachineCoordinateMove(code);
  if (code.number == 10) return applyDataSetting(work_.block, code, work_.state, work_.options);
  return work_.errorAt(code.column, fmt::format("{} is not supported by lathesim yet", code.text));
}

// G04 (GSK980TDi §3.14): X or U in seconds, P in milliseconds; with several, P wins over X and
// X over U (the others are warned as ignored); none is an exact stop between blocks (no time);
// a negative time dwells 0 s. A Haas control (g04_p = "seconds_with_point") reads a P written
// with a decimal point (or from a macro value) in seconds: G04 P1.5 is 1.5 s, G04 P1500 1.5 s.
Status Executor::applyDwell(const Code&) {
  std::optional<Word> time;
  for (char letter : {'P', 'X', 'U'}) {
    auto word = work_.block.take(letter);
    if (!word) continue;
    if (time) {
      work_.warnings.push_back({work_.block.line, word->column,
                                fmt::format("{} is ignored: {} gives G04's time (P before X before U, GSK980TDi §3.14)",
                                            word->text(), time->text())});
      continue;
    }
    time = word;
  }
  if (!time) return success();
  const bool pInSeconds =
      work_.options.control.dwellPWord == DwellPWord::SecondsWithPoint && (time->evaluated || hasDecimalPoint(*time));
  const double seconds = time->letter != 'P' ? dwellSeconds(*time, work_.reading())
                         : pInSeconds        ? time->value
                                             : time->value / kMsPerS;
  work_.emit(MoveKind::Dwell, work_.state.position, work_.state.position, 0);
  work_.moves.back().dwellS = std::max(seconds, 0.0);
  return success();
}

Status Executor::applyCoordinateSetting(const Code&) {
  // G50 X(U) Z(W) (GSK980TDi §3.18): the tool is declared to stand at these coordinates; it
  // does not move, the program's frame does. An axis not given keeps its coordinate, so a
  // bare G50 changes nothing.
  auto axes = work_.takeAxisWords(Coordinates::Declared);
  if (!axes.ok()) return axes.error();
  const AxisWords& a = axes.value();
  const auto s = work_.block.take('S');
  RZ declared = work_.state.position;
  if (a.x) declared.x() = work_.length(*a.x) / 2.0;
  if (a.u) declared.x() += work_.length(*a.u) / 2.0;
  if (a.z) declared.y() = work_.length(*a.z);
  if (a.w) declared.y() += work_.length(*a.w);
  work_.state.frame.coordinateSetting += work_.state.position - declared;
  work_.state.position = declared;
  if (s) work_.state.spindleLimitRpm = s->value;
  return success();
}

Status Executor::applyReferenceReturn(const Code& code) {
  auto axes = work_.takeAxisWords();
  if (!axes.ok()) return axes.error();
  const AxisWords& a = axes.value();
  // G30 goes to the second reference point (P2, the default; the setup's second_reference).
  const bool second = code.number == 30;
  if (second) {
    if (const auto p = work_.block.take('P'); p && p->value != 2) {
      return work_.errorAt(p->column, fmt::format("G30 {}: only the second reference point (P2) is known; a third or "
                                                  "fourth is not in the setup",
                                                  p->text()));
    }
    if (!work_.options.secondReferencePosition) {
      return work_.errorAt(code.column,
                           "G30 returns to the second reference point, which the setup does not give: add "
                           "[machine] second_reference = [X, Z]");
    }
  }
  // Haas: G28 with no axis word sends every axis home, straight from where it stands.
  const bool everyAxis = !a.any() && work_.options.dialect == Dialect::Haas;
  if (!a.any() && !everyAxis) {
    return work_.errorAt(code.column, fmt::format("{} needs X(U) and/or Z(W): the intermediate point of the axes "
                                                  "to return ({} U0 W0 returns both straight from here)",
                                                  code.text, code.text));
  }
  const RZ& p = work_.state.position;
  std::optional<double> radiusMm, zMm;
  if (everyAxis) {
    radiusMm = p.x();
    zMm = p.y();
  }
  if (a.x) radiusMm = work_.length(*a.x) / 2.0;
  if (a.u) radiusMm = p.x() + work_.length(*a.u) / 2.0;
  if (a.z) zMm = work_.length(*a.z);
  if (a.w) zMm = p.y() + work_.length(*a.w);
  // The reference point is the machine's: in the program's frame it moves with G54–G59 and G50.
  const RZ machinePoint = second ? *work_.options.secondReferencePosition
                                 : work_.options.referencePosition.value_or(work_.options.startPosition);
  const RZ reference = machinePoint - work_.state.frame.shift();
  const std::vector<CycleLeg> legs = referenceReturnLegs(p, radiusMm, zMm, reference);
  // Under G41/G42 the compensation is suspended at the intermediate point (lathe-cycles.md §10):
  // the legs are no part of the chain, which ends with the move before them and resumes with a
  // start-up after them.
  const std::size_t first = work_.moves.size();
  work_.emitLegs(legs);
  // The reference point is a position of the machine: the axes that return reach it without the
  // tool offset (GSK980TDi §3.15 note 4; Fanuc 0i-TC B-64114EN §14.1.6, the vector is not
  // reflected in the G28 block), while the intermediate point is a programmed one and keeps it.
  for (std::size_t i = first; i < work_.moves.size(); ++i) {
    if (work_.moves[i].cycleStep != 2) continue;
    if (radiusMm) work_.moves[i].offsetShift.x() = 0;
    if (zMm) work_.moves[i].offsetShift.y() = 0;
  }
  if (!legs.empty()) work_.state.position = legs.back().to;
  // GSK No.182#2: arrived at the reference, the control forgets the tool offset until a T word.
  if (work_.options.control.offsetAfterReturn == OffsetAfterReturn::Cancelled) {
    work_.state.toolOffset = 0;
    work_.state.offset = offsetNumbered(offsetTable(), 0);
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
  if (mode != work_.state.motion) {
    work_.state.cycle = {};
    work_.state.threadCycle = {};
    work_.state.drillCancelWithCycle.reset();
  }
  work_.state.motion = mode;
}

Status Executor::applyMachineCoordinateMove(const Code& code) {
  auto target = machineCoordinateTarget(work_.block, code, work_.state, work_.options);
  if (!target.ok()) return target.error();
  work_.state.noseSide = NoseSide::None;  // G53 cancels G41/G42 (GSK980TDi 3.20): its move is the cancel
  work_.emit(MoveKind::Rapid, work_.state.position, target.value(), 0);
  work_.state.position = target.value();
  return success();
}

// G54–G59 before the block's motion, so the block's own move is in the new system. In a G50
// block the selection is ignored and G50 acts (GSK980TDi 3.21 note 6).
void Executor::applyWorkSystem(const std::optional<Code>& oneShot) {
  const auto code = work_.block.gCode(GGroup::WorkCoordinates);
  if (!code) return;
  if (oneShot && oneShot->number == 50) {
    work_.warnings.push_back({work_.block.line, code->column,
                              fmt::format("{} in a G50 block is ignored: G50 sets the coordinates "
                                          "(GSK980TDi 3.21); select the work system in a block of its own",
                                          code->text)});
    return;
  }
  selectWorkSystem(*code, work_.state);
}

// G80 cancels the drilling cycles (group 10 on Fanuc T and GSK: G83–G89); it does not end
// G90/G92/G94, which only another group-01 code ends. Remember it, so that a block that then
// repeats such a cycle says so.
void Executor::noteDrillingCycleCancel() {
  const auto code = work_.block.gCode(GGroup::DrillingCycle);
  if (!code) return;
  if (work_.state.motion == MotionMode::AxialCycle || work_.state.motion == MotionMode::FaceCycle ||
      work_.state.motion == MotionMode::ThreadCycle)
    work_.state.drillCancelWithCycle = std::pair{work_.block.line, code->column};
}

Status Executor::applyMotion() {
  const auto code = work_.block.gCode(GGroup::Motion);
  if (code) selectMotion(*code);
  switch (work_.state.motion) {
    case MotionMode::AxialCycle:
      return runAxialCycle(work_, code);
    case MotionMode::FaceCycle:
      return runFaceCycle(work_, code);
    case MotionMode::Thread:
      return runThreadCut(work_, code);
    case MotionMode::ThreadCycle:
      return runThreadCycle(work_, code);
    case MotionMode::ArcCW:
    case MotionMode::ArcCCW: return applyArc(code);
    case MotionMode::Rapid:
    case MotionMode::Linear: break;
  }
  return applyStraightMove(code);
}

Status Executor::applyStraightMove(const std::optional<Code>& code) {
  auto axes = work_.takeAxisWords();
  if (!axes.ok()) return axes.error();
  const AxisWords& a = axes.value();
  const std::optional<Word> angle = takeAngleWord();
  if (angle && !a.any()) {
    return work_.errorAt(angle->column, fmt::format("{} alone starts a drawing dimension of two lines (their "
                                                    "intersection found by the control), which lathesim does not read "
                                                    "yet; give this line's end X or Z with the angle",
                                                    angle->text()));
  }
  if (!a.any()) return success();
  const RZ from = work_.state.position;
  RZ to = work_.endPoint(a);
  const bool givesX = a.x || a.u;
  const bool givesZ = a.z || a.w;
  if (angle && givesX && givesZ) {
    work_.warnings.push_back(
        {work_.block.line, angle->column,
         fmt::format("{} is ignored: X and Z give the end point (GSK980TDi §3.13)", angle->text())});
  } else if (angle) {
    auto end =
        lineEndByAngle(from, givesX ? std::optional(to.x()) : std::nullopt,
                       givesZ ? std::optional(to.y()) : std::nullopt, angleDegrees(*angle), *angle, work_.block.line);
    if (!end.ok()) return end.error();
    to = end.value();
  }
  const bool feed = work_.state.motion == MotionMode::Linear;
  auto corner = feed ? takeCornerWord() : Result<std::optional<CornerRequest>>(std::nullopt);
  if (!corner.ok()) return corner.error();
  if (feed && !work_.state.feed) {
    return work_.errorAt(code ? code->column : work_.block.column,
                         "feed rate F is not set: give F (e.g. F0.2 mm/rev) before the first G01 move");
  }
  if (auto problem = feed ? zeroFeedProblem(work_.state.feed, "G01") : std::nullopt)
    return work_.errorAt(code ? code->column : work_.block.column, *problem);
  const std::size_t before = work_.moves.size();
  work_.emit(feed ? MoveKind::Feed : MoveKind::Rapid, from, to, 0);
  if (corner.value() && work_.moves.size() > before)
    work_.moves.back().cornerAfter = std::make_shared<const CornerRequest>(std::move(*corner.value()));
  work_.state.position = to;
  return success();
}

// L / D (GSK §3.11) or ,C / ,R (Fanuc): a chamfer or a corner radius after this block's move.
Result<std::optional<CornerRequest>> Executor::takeCornerWord() {
  const bool gsk = work_.options.control.cornerWords == CornerWords::LD;
  const auto chamfer = work_.block.take(gsk ? 'L' : 'c');
  const auto round = work_.block.take(gsk ? 'D' : 'r');
  if (chamfer && round) {
    return work_.errorAt(round->column, fmt::format("{} and {} both ask for a corner; give one of them",
                                                    chamfer->text(), round->text()));
  }
  const std::optional<Word>& word = chamfer ? chamfer : round;
  if (!word) return std::optional<CornerRequest>();
  if (word->value <= 0) {
    return work_.errorAt(word->column, fmt::format("{} is not a {}: expected a size > 0", word->text(),
                                                   chamfer ? "chamfer" : "corner radius"));
  }
  const bool chamferLength = chamfer && gsk && work_.options.control.chamferSize == ChamferSize::Length;
  return std::optional(CornerRequest{!chamfer, work_.length(*word), chamferLength, word->text(), word->column});
}

std::optional<Word> Executor::takeAngleWord() {
  switch (work_.options.control.drawingAngleWord) {
    case DrawingAngleWord::Q:
      return work_.block.take('Q');
    case DrawingAngleWord::A:
      return work_.block.take('A');
    case DrawingAngleWord::CommaA:
      return work_.block.take('a');
  }
  return std::nullopt;
}

// An angle in degrees: GSK's Q counts 0.001° without a point (an [LII] word, No.182#7), Fanuc's
// A follows the decimal point input like a length.
double Executor::angleDegrees(const Word& angle) const {
  const bool incrementWord = work_.options.control.drawingAngleWord == DrawingAngleWord::Q;
  const NumberReading r = work_.reading();
  const bool counted = !hasDecimalPoint(angle) &&
                       (incrementWord ? r.incrementWordInput == IncrementWordInput::LeastIncrements
                                      : r.decimalPointInput == DecimalPointInput::LeastIncrements);
  return counted ? angle.value * r.leastIncrementMm : angle.value;  // 0.001° at IS-B
}

std::optional<ArcWord> Executor::arcWord(char letter) {
  const auto word = work_.block.take(letter);
  if (!word) return std::nullopt;
  return ArcWord{word->text(), word->column, work_.length(*word)};  // I: a radius
}

// G02/G03 (interp/motion/arc_move.hpp): one arc move to the end point; nothing without axis or
// centre words.
Status Executor::applyArc(const std::optional<Code>& code) {
  const bool clockwise = work_.state.motion == MotionMode::ArcCW;
  const std::string_view name = clockwise ? "G02" : "G03";
  const int anchor = code ? code->column : work_.block.column;
  auto axes = work_.takeAxisWords();
  if (!axes.ok()) return axes.error();
  ArcRequest arc{name,         clockwise,    work_.state.position, work_.endPoint(axes.value()),
                 arcWord('R'), arcWord('I'), arcWord('K'),         work_.block.line,
                 anchor};
  if (!axes.value().any() && !arc.r && !arc.i && !arc.k) return success();
  auto corner = takeCornerWord();
  if (!corner.ok()) return corner.error();
  if (corner.value()) {
    return work_.errorAt(corner.value()->column,
                         fmt::format("{} after an arc: chamfers and corners next to arcs are not "
                                     "simulated yet; give the corner as its own G01 or G02/G03",
                                     corner.value()->word));
  }
  if (auto problem = planeProblem(work_.state.plane, name, "an arc")) return work_.errorAt(anchor, *problem);
  if (!work_.state.feed) {
    return work_.errorAt(anchor, fmt::format("feed rate F is not set: give F (e.g. F0.2 mm/rev) "
                                             "before the first {} move",
                                             name));
  }
  if (auto problem = zeroFeedProblem(work_.state.feed, name)) return work_.errorAt(anchor, *problem);
  arc.radiusToleranceMm = work_.options.control.arcRadiusToleranceMm;
  arc.endOffCircle = work_.options.control.arcEndOffCircle;
  const auto centre = arcCentre(arc);
  if (!centre.ok()) return centre.error();
  work_.warnings.insert(work_.warnings.end(), centre.value().warnings.begin(), centre.value().warnings.end());
  if (!centre.value().centre) return success();  // R to the start point: no move
  work_.emit(clockwise ? MoveKind::ArcCW : MoveKind::ArcCCW, arc.start, arc.end, 0, *centre.value().centre);
  work_.state.position = arc.end;
  return success();
}

// A word no code took that names machinery this two-axis, one-spindle lathe does not have.

// G70–G76 in place of the block's motion; G71–G73 may go on after their nf block.
Status Executor::applyCompoundCycle(const Code& code) {
  auto continueAfter = runCompoundCycleBlock(work_, code, place_);
  if (!continueAfter.ok()) return continueAfter.error();
  flow_.continueAfter = continueAfter.value();
  return success();
}

Status Executor::checkAllWordsUsed() const {
  if (work_.block.words.empty()) return success();
  // Report the leftover word that comes first in the block.
  const Word* first = nullptr;
  for (const auto& [letter, word] : work_.block.words) {
    if (first == nullptr || word.column < first->column) first = &word;
  }
  if (const auto lacking = missingMachineryOf(*first, work_.block, work_.options.control))
    return work_.errorAt(first->column, *lacking);
  return work_.errorAt(first->column, fmt::format("{} is not used by any code in this block; remove "
                                                  "it or add the code that takes {}",
                                                  first->text(), first->letter));
}

// G70–G73's contour blocks, each run on its own.
class ContourBlockExecutor final : public BlockRunner {
 public:
  Result<BlockRun> run(ParsedBlock words, ModalState state, const InterpreterOptions& options,
                       int ordinal) const override {
    auto done = Executor(std::move(words), std::move(state), options, ordinal, nullptr).run();
    if (!done.ok()) return done.error();
    return BlockRun{std::move(done.value().state), std::move(done.value().moves), std::move(done.value().warnings)};
  }
};

}  // namespace

const BlockRunner& blockExecutor() {
  static const ContourBlockExecutor executor;
  return executor;
}

Result<BlockOutcome> executeBlock(ParsedBlock block, ModalState state,
                                  const InterpreterOptions& options, int ordinal,
                                  const BlockPlace* place) {
  return Executor(std::move(block), std::move(state), options, ordinal, place).run();
}

}  // namespace lathesim::interp
