#include "interp/cycles/single_cycle_block.hpp"

#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "interp/compensation/cycle_nose_compensation.hpp"
#include "interp/compensation/tool_offset.hpp"
#include "interp/control/gcode_table.hpp"
#include "interp/cycles/g90_cycle.hpp"
#include "interp/cycles/g94_cycle.hpp"

namespace lathesim::interp {
namespace {

// What sets G90 and G94 apart; the rest of a single cycle (modal retention, the checks,
// emitting its legs) is one code path for both.
struct SingleCycle {
  int code;            // the system-A code, 90 or 94 (the dialect may write another)
  bool taperAgainstX;  // the R alarm compares R with U (G90) or with W (G94)
  std::vector<CycleLeg> (*legs)(const RZ& start, const RZ& end, double rMm);
  std::optional<std::string> (*taperProblem)(double travelMm, double rMm);
};

constexpr SingleCycle kAxialCycle{90, true, axialCycleLegs, axialCycleTaperProblem};
constexpr SingleCycle kFaceCycle{94, false, faceCycleLegs, faceCycleTaperProblem};

Status runSingleCycle(BlockWork& work, const SingleCycle& cycle, const std::optional<Code>& code) {
  ParsedBlock& block = work.block;
  ModalState& state = work.state;
  const InterpreterOptions& options = work.options;
  const char taperLetter = cycleTaperLetter(cycle.code, options.dialect);
  // A block runs the cycle when it gives any of X U Z W R; the code alone (a G90 on a safety
  // line) makes it the modal motion and moves nothing.
  if (!block.has('X') && !block.has('U') && !block.has('Z') && !block.has('W') && !block.has(taperLetter)) {
    return success();
  }
  const int anchor = code ? code->column : block.column;
  const std::string name = writtenGCode(cycle.code, GGroup::Motion, options.dialect);
  warnIfCycleRepeatsAfterG80(work, code, name);
  if (auto problem = planeProblem(state.plane, name, "a cycle")) return work.errorAt(anchor, *problem);
  auto axes = work.takeAxisWords();
  if (!axes.ok()) return axes.error();
  const AxisWords& a = axes.value();
  const auto r = block.take(taperLetter);
  const RZ start = state.position;  // A
  CycleRetained& kept = state.cycle;
  const auto endWords = singleCycleEndPoint(work, a, name, anchor);
  if (!endWords.ok()) return endWords.error();
  const double xDiameterMm = endWords.value().xDiameterMm;
  const double zMm = endWords.value().zMm;
  const double rMm = r ? work.length(*r) : kept.rMm.value_or(0.0);
  if (!state.feed) {
    return work.errorAt(anchor, fmt::format("feed rate F is not set: {} cuts at feed; give F (e.g. "
                                            "F0.2 mm/rev) in this block or before it",
                                            name));
  }
  if (auto problem = zeroFeedProblem(state.feed, name)) return work.errorAt(anchor, *problem);
  // The alarm compares R with the travel U (G90, a diameter) or W (G94); without R in this
  // block it points at that travel's word.
  const double travelMm = cycle.taperAgainstX ? xDiameterMm - diameterOf(start) : zMm - start.y();
  if (auto problem = cycle.taperProblem(travelMm, rMm)) {
    const std::optional<Word>& absolute = cycle.taperAgainstX ? a.x : a.z;
    const std::optional<Word>& incremental = cycle.taperAgainstX ? a.u : a.w;
    const int column = r ? r->column : absolute ? absolute->column : incremental ? incremental->column : anchor;
    return work.errorAt(column, *problem);
  }
  kept = CycleRetained{xDiameterMm, zMm, rMm};
  work.noteCycleStart(start, name);
  const RZ end(xDiameterMm / 2.0, zMm);  // C
  const NoseComp comp = noseCompWith(state.noseSide, state.offset);
  const std::size_t firstLeg = work.moves.size();
  work.emitLegs(noseCompensatedCycle(cycle.legs(start, end, rMm), start, cycle.taperAgainstX, comp));
  // Under G40 the legs keep the offset's R and tip, which the nose check weighs (a taper leg
  // misses its line by R·(|s·n| − 1); compensation/uncompensated_nose.hpp), as G71–G73's do.
  // Under G41/G42 the cycle offset them (with the offset's R): the check leaves them out.
  if (state.noseSide == NoseSide::None)
    for (std::size_t i = firstLeg; i < work.moves.size(); ++i) work.moves[i].noseComp = noseCompWith(NoseSide::None, state.offset);
  else
    work.legsCompensated = comp.radiusMm > 0;
  return success();  // the cycle ends at A: the position is unchanged
}

}  // namespace

Result<CycleEndPoint> singleCycleEndPoint(BlockWork& work, const AxisWords& axes, std::string_view name,
                                          int anchor) {
  const RZ start = work.state.position;
  const CycleRetained& kept = work.state.cycle;
  std::optional<double> xDiameterMm = kept.xDiameterMm;
  if (axes.x) xDiameterMm = work.length(*axes.x);
  if (axes.u) xDiameterMm = diameterOf(start) + work.length(*axes.u);
  std::optional<double> zMm = kept.zMm;
  if (axes.z) zMm = work.length(*axes.z);
  if (axes.w) zMm = start.y() + work.length(*axes.w);
  if (!xDiameterMm || !zMm) {
    return work.errorAt(anchor, fmt::format("{0} needs X(U) and Z(W): the end point's {1} is neither "
                                            "in this block nor kept from an earlier {0} block",
                                            name, !xDiameterMm ? "X(U)" : "Z(W)"));
  }
  return CycleEndPoint{*xDiameterMm, *zMm};
}

Status runAxialCycle(BlockWork& work, const std::optional<Code>& code) {
  return runSingleCycle(work, kAxialCycle, code);
}

Status runFaceCycle(BlockWork& work, const std::optional<Code>& code) { return runSingleCycle(work, kFaceCycle, code); }

void warnIfCycleRepeatsAfterG80(BlockWork& work, const std::optional<Code>& code, std::string_view name) {
  ParsedBlock& block = work.block;
  ModalState& state = work.state;
  const auto g80 = state.drillCancelWithCycle;
  state.drillCancelWithCycle.reset();
  if (code || !g80) return;
  work.warnings.push_back({block.line, block.column,
                           fmt::format("this block repeats {}: the G80 on line {} cancels drilling "
                                       "cycles only, and {} stays modal until a G00, G01, G02 or G03 "
                                       "(Fanuc and GSK group 01)",
                                       name, g80->first, name)});
}

}  // namespace lathesim::interp
