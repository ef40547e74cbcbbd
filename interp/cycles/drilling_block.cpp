#include "interp/cycles/drilling_block.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "interp/cycles/drilling_cycle.hpp"
#include "interp/state/move_limit.hpp"

namespace lathesim::interp {
namespace {

constexpr double kMsPerS = 1000.0;

}  // namespace

// G81 Z(W) R F, G82 … P (dwell at the bottom), G83 … Q (peck) [P]: drilling on the axis from
// the tool's position (drilling_cycle.hpp). R is the R point's Z on a Haas (⚠) and its distance
// from the start's Z on Fanuc T (⚠); without it the feed starts where the tool stands. Q is a
// length (Haas) or least increments without a point (Fanuc's [LII]); P counts as G04's P. X may
// only be X0 (U0): with no live tool a drill cuts on the axis alone. G84 Z R F [P] taps: F is
// the lead under G99 (the tap follows the spindle), the spindle must turn, and it reverses for
// the feed back out to R (those moves carry the reversed direction).
Status runDrillingCycle(BlockWork& work, const std::optional<Code>& code) {
  ParsedBlock& block = work.block;
  ModalState& state = work.state;
  const InterpreterOptions& options = work.options;
  const bool haas = options.dialect == Dialect::Haas;
  const int cycle = code ? code->number : state.drillingCycle;
  const std::string name = fmt::format("G{}", cycle);
  const int anchor = code ? code->column : block.column;
  auto axes = work.takeAxisWords();
  if (!axes.ok()) return axes.error();
  const AxisWords& a = axes.value();
  RZ start = state.position;
  if (a.x) start.x() = work.length(*a.x) / 2.0;
  if (a.u) start.x() += work.length(*a.u) / 2.0;
  if (std::abs(start.x()) > 1e-9) {
    return work.errorAt(
        a.x   ? a.x->column
        : a.u ? a.u->column
              : anchor,
        fmt::format("{} drills on the spindle's axis, but the tool would stand at X{:g}: a hole off the axis "
                    "needs live tooling, which this lathe does not have (give X0)",
                    name, 2.0 * start.x()));
  }
  if (code && !a.z && !a.w) return work.errorAt(anchor, fmt::format("{} needs Z(W): the hole's bottom", name));
  if (a.z) state.drillingBottomZ = work.length(*a.z);
  if (a.w) state.drillingBottomZ = state.position.y() + work.length(*a.w);
  const double bottomZ = state.drillingBottomZ;
  const auto r = block.take('R');
  const auto q = block.take('Q');
  const auto p = block.take('P');
  if (code) {  // a new cycle: its R point, peck and dwell are kept for the blocks that repeat it
    state.drillingCycle = cycle;
    state.drillingRPlaneZ = !r ? state.position.y() : haas ? work.length(*r) : state.position.y() + work.length(*r);
    state.drillingPeckMm = 0;
    state.drillingDwellS = 0;
  } else if (r) {
    state.drillingRPlaneZ = haas ? work.length(*r) : state.position.y() + work.length(*r);
  }
  if (q) {
    if (cycle != 83) return work.errorAt(q->column, fmt::format("{} {}: only G83 pecks", name, q->text()));
    const double peck = haas ? work.length(*q) : incrementLengthMm(*q, work.reading());
    if (!(peck > 0))
      return work.errorAt(q->column, fmt::format("G83 {} is not a peck depth: expected a number > 0", q->text()));
    state.drillingPeckMm = peck;
  }
  if (p) {
    if (cycle == 81)
      return work.errorAt(p->column, fmt::format("G81 {}: G81 does not dwell; G82 dwells P at the bottom", p->text()));
    const bool seconds =
        options.control.dwellPWord == DwellPWord::SecondsWithPoint && (p->evaluated || hasDecimalPoint(*p));
    state.drillingDwellS = std::max(seconds ? p->value : p->value / kMsPerS, 0.0);
  }
  if (!state.feed) {
    return work.errorAt(
        anchor, fmt::format("feed rate F is not set: {} drills at feed; give F in this block or before it", name));
  }
  if (auto problem = zeroFeedProblem(state.feed, name)) return work.errorAt(anchor, *problem);
  const bool tapping = cycle == 84;
  if (tapping && !state.spindleOn) {
    return work.errorAt(anchor,
                        "G84 taps with the spindle turning (the tap follows it down, and the spindle reverses to back "
                        "it out): give M03 (or M04) and S before it");
  }
  const RZ from = state.position;
  DrillingParams params;
  params.rPlaneZ = state.drillingRPlaneZ;
  params.bottomZ = bottomZ;
  params.peckMm = state.drillingPeckMm;
  params.clearanceMm = options.control.peckRetractMm;
  params.tapping = tapping;
  // X0 in the block: the tool goes to the axis first, at rapid.
  if (from.x() != start.x()) work.emit(MoveKind::Rapid, from, RZ(start.x(), from.y()), 0);
  const auto drilled = drillingLegs(RZ(start.x(), from.y()), params, options.maxMoves);
  if (!drilled) return *moveLimitError(options.maxMoves + 1, options.maxMoves, block.line, anchor);
  const DrillingLegs& legs = *drilled;
  work.emitLegs(legs.down);
  if (state.drillingDwellS > 0) {
    const RZ bottom(start.x(), bottomZ);
    work.emit(MoveKind::Dwell, bottom, bottom, 0);
    work.moves.back().dwellS = state.drillingDwellS;
  }
  const std::size_t firstUp = work.moves.size();
  work.emitLegs(legs.up);
  for (std::size_t i = firstUp; i < work.moves.size(); ++i) {  // a tap backs out with the spindle reversed
    if (work.moves[i].kind != MoveKind::Feed) continue;
    work.moves[i].spindleDirection = state.spindleDirection == SpindleDirection::Clockwise
                                         ? SpindleDirection::CounterClockwise
                                         : SpindleDirection::Clockwise;
  }
  state.position = RZ(start.x(), from.y());
  return success();
}

}  // namespace lathesim::interp
