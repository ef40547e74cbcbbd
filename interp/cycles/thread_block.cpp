#include "interp/cycles/thread_block.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "interp/control/gcode_table.hpp"
#include "interp/control/threading_words.hpp"
#include "interp/cycles/g90_cycle.hpp"
#include "interp/cycles/g92_cycle.hpp"
#include "interp/cycles/single_cycle_block.hpp"
#include "interp/cycles/thread_cut.hpp"
#include "interp/cycles/thread_words.hpp"
#include "interp/motion/spindle_speed.hpp"

namespace lathesim::interp {

// G32 (lathe-cycles.md §2, interp/cycles/thread_cut.hpp): a cut synchronised with the
// spindle, from here to the end point. The first G32 of a chain waits for the spindle to
// reach Q; a G32 block right after another starts where that one's cut ended, its Q
// ignored. No move without axis words.
Status runThreadCut(BlockWork& work, const std::optional<Code>& code) {
  ParsedBlock& block = work.block;
  ModalState& state = work.state;
  const InterpreterOptions& options = work.options;
  const ThreadingWords words = threadingWords(options.dialect);
  const std::string name = writtenGCode(32, GGroup::Motion, options.dialect);
  const int anchor = code ? code->column : block.column;
  auto axes = work.takeAxisWords();
  if (!axes.ok()) return axes.error();
  if (auto problem = planeProblem(state.plane, name, "a thread")) return work.errorAt(anchor, *problem);
  auto lead = takeLeadMm(block, state, words, options.control, name, anchor, work.feedGiven);
  if (!lead.ok()) return lead.error();
  auto angle = takeStartAngleDeg(block, name, work.warnings);
  if (!angle.ok()) return angle.error();
  auto runoutWords = takeRunoutWords(block, work.reading(), words, state.threadChainRunout, true, name);
  if (!runoutWords.ok()) return runoutWords.error();
  if (!axes.value().any()) return success();  // a block that cuts nothing ends the chain
  state.threadChainRunout = runoutWords.value();
  work.chainedThread = true;

  threadStateWarnings(state, block.line, anchor, name, work.warnings);
  const RZ from = state.position;
  const RZ to = work.endPoint(axes.value());
  ThreadMotion motion;
  motion.leadMm = lead.value();
  motion.startAngleDeg = state.threadChainAngleDeg.value_or(angle.value());
  const std::vector<CycleLeg> legs = threadCutLegs(from, to, chainRunout(state.threadChainRunout), motion, 0);
  warnIfThreadTooFast(work, legs, anchor);
  work.emitLegs(legs);
  const CycleLeg& last = legs.back();
  state.threadChainAngleDeg = angleAfter(last.thread.startAngleDeg, last.thread.revolutions(last.from, last.to));
  state.position = last.to;
  return success();
}

// G92 (lathe-cycles.md §1, interp/cycles/g92_cycle.hpp): G90's words and modal repetition,
// the cut a thread with a run-out, and the starts of a multi-start thread.
Status runThreadCycle(BlockWork& work, const std::optional<Code>& code) {
  ParsedBlock& block = work.block;
  ModalState& state = work.state;
  const InterpreterOptions& options = work.options;
  const ThreadingWords words = threadingWords(options.dialect);
  const char taperLetter = cycleTaperLetter(92, options.dialect);
  // As G90: the code alone makes it the modal motion and moves nothing.
  if (!block.has('X') && !block.has('U') && !block.has('Z') && !block.has('W') && !block.has(taperLetter)) {
    return success();
  }
  const int anchor = code ? code->column : block.column;
  const std::string name = writtenGCode(92, GGroup::Motion, options.dialect);
  warnIfCycleRepeatsAfterG80(work, code, name);
  if (auto problem = planeProblem(state.plane, name, "a cycle")) return work.errorAt(anchor, *problem);
  auto axes = work.takeAxisWords();
  if (!axes.ok()) return axes.error();
  const AxisWords& a = axes.value();
  const auto r = block.take(taperLetter);
  auto lead = takeLeadMm(block, state, words, options.control, name, anchor, work.feedGiven);
  if (!lead.ok()) return lead.error();
  ThreadCycleRetained& threadKept = state.threadCycle;
  auto runoutWords = takeRunoutWords(block, work.reading(), words, threadKept.runout, words.hncRunoutRE, name);
  if (!runoutWords.ok()) return runoutWords.error();
  int starts = threadKept.starts;
  double firstStartDeg = threadKept.firstStartDeg;
  const auto startsWord = words.startsL ? block.take('L') : words.hncStartsCP ? block.take('C') : std::nullopt;
  if (startsWord) {
    if (startsWord->value < 0 || startsWord->value > 99 || std::floor(startsWord->value) != startsWord->value) {
      return work.errorAt(startsWord->column, fmt::format("{} {} is not a number of starts: expected a whole number 1 "
                                                          "to 99",
                                                          name, startsWord->text()));
    }
    starts = std::max(1, static_cast<int>(startsWord->value));  // HNC: C0 is one start
  }
  if (words.hncStartsCP) {
    if (const auto p = block.take('P')) firstStartDeg = std::fmod(std::abs(p->value), 360.0);
  } else {
    // Fanuc's G92 Q: the start angle in 0.001°, not modal (B-63944EN §4.1.2; as G32's Q).
    auto angle = takeStartAngleDeg(block, name, work.warnings);
    if (!angle.ok()) return angle.error();
    firstStartDeg = angle.value();
  }

  const RZ start = state.position;  // A
  CycleRetained& kept = state.cycle;
  const auto endWords = singleCycleEndPoint(work, a, name, anchor);
  if (!endWords.ok()) return endWords.error();
  const double xDiameterMm = endWords.value().xDiameterMm;
  const double zMm = endWords.value().zMm;
  if (zMm == start.y()) {
    return work.errorAt(a.z   ? a.z->column
                        : a.w ? a.w->column
                              : anchor,
                        fmt::format("{} cannot cut a face thread: its end Z must differ from the start point's Z{:g} "
                                    "(use G32 for a face thread)",
                                    name, start.y()));
  }
  const double rMm = r ? work.length(*r) : kept.rMm.value_or(0.0);
  if (auto problem = axialCycleTaperProblem(xDiameterMm - diameterOf(start), rMm, name)) {
    return work.errorAt(r ? r->column : a.x ? a.x->column : a.u ? a.u->column : anchor, *problem);
  }
  kept = CycleRetained{xDiameterMm, zMm, rMm};
  threadKept = {runoutWords.value(), starts, firstStartDeg};

  threadStateWarnings(state, block.line, anchor, name, work.warnings);
  work.noteCycleStart(start, name);
  ThreadCycleParams params;
  params.leadMm = lead.value();
  // Without run-out words the control's parameter decides (GSK No.19, Fanuc No.5130).
  const ThreadRunout runout = words.hncRunoutRE
                                  ? ThreadRunout{runoutWords.value().alongMm.value_or(0.0),
                                                 std::abs(runoutWords.value().acrossMm.value_or(0.0))}
                                  : cycleRunout(runoutWords.value(), options.control.threadRunoutLeads * params.leadMm,
                                                options.control.threadRunoutAngleDeg);
  params.runoutAlongMm = runout.alongMm;
  params.runoutAcrossMm = std::abs(runout.acrossMm);
  params.starts = starts;
  params.firstStartDeg = firstStartDeg;
  const std::vector<CycleLeg> legs = threadCycleLegs(start, RZ(xDiameterMm / 2.0, zMm), rMm, params);
  warnIfThreadTooFast(work, legs, anchor);
  work.emitLegs(legs);
  return success();  // the cycle ends at A
}

// The control cannot keep the lead when lead × rpm exceeds the lead axis's fastest motion
// (the setup's rapid rate for that axis): one warning per block.
void warnIfThreadTooFast(BlockWork& work, const std::vector<CycleLeg>& legs, int column) {
  ParsedBlock& block = work.block;
  ModalState& state = work.state;
  const InterpreterOptions& options = work.options;
  for (const CycleLeg& leg : legs) {
    if (leg.kind != MoveKind::Thread || !state.spindleOn) continue;
    const double nearAxis = std::min(std::abs(leg.from.x()), std::abs(leg.to.x()));
    const double rpm = state.spindleMode == SpindleMode::Rpm ? constantRpm(state.spindleSpeed, options.machine)
                                                             : surfaceSpeedRpm(state.surfaceSpeedMPerMin, nearAxis,
                                                                               state.spindleLimitRpm, options.machine);
    const double axisMmPerMin = leg.thread.leadAlongZ ? options.machine.rapidZMmPerMin : options.machine.rapidXMmPerMin;
    const double needed = leg.thread.leadMm * rpm;
    if (needed <= axisMmPerMin) continue;
    work.warnings.push_back(
        {block.line, column,
         fmt::format("a lead of {:g} mm at {:g} rpm needs {:g} mm/min along {}, more than that axis's "
                     "fastest motion ({:g} mm/min, the setup's rapid rate): the control cannot keep "
                     "the lead; lower the spindle speed",
                     leg.thread.leadMm, rpm, needed, leg.thread.leadAlongZ ? "Z" : "X", axisMmPerMin)});
    return;
  }
}

}  // namespace lathesim::interp
