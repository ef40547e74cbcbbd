#include "interp/cycles/compound_block.hpp"

#include "interp/cycles/compound_cycle.hpp"
#include "interp/cycles/thread_block.hpp"

namespace lathesim::interp {

Result<std::optional<std::size_t>> runCompoundCycleBlock(BlockWork& work, const Code& code, const BlockPlace* place) {
  ParsedBlock& block = work.block;
  ModalState& state = work.state;
  const InterpreterOptions& options = work.options;
  state.cycle = {};                 // a one-shot code ends G90/G94's retained values
  const RZ start = state.position;  // A
  auto outcome = runCompoundCycle(code, block, state, options, place, work.feedGiven);
  if (!outcome.ok()) return outcome.error();
  const CompoundOutcome& done = outcome.value();
  // The parameter block of a two-block cycle (G71 U R; …) moves nothing and starts nothing.
  if (!done.legs.empty() || !done.contourMoves.empty()) work.noteCycleStart(start, code.text);
  work.moves.insert(work.moves.end(), done.contourMoves.begin(), done.contourMoves.end());
  work.warnings.insert(work.warnings.end(), done.warnings.begin(), done.warnings.end());
  if (code.number == 76) warnIfThreadTooFast(work, done.legs, code.column);
  const std::size_t firstLeg = work.moves.size();
  work.emitLegs(done.legs);
  if (done.contour) {
    work.contourPass = ContourPass{done.contour->first, done.contour->last, code.number == 70, done.contourCompensated};
    // G71–G73 rough under G40 (GSK suspends a G41/G42 for them): the legs along a contour its
    // blocks do not compensate keep the offset's R and tip, which the nose check weighs
    // (compensation/uncompensated_nose.hpp).
    if (!work.contourPass->finishes && !done.contourCompensated && state.noseSide == NoseSide::None)
      for (std::size_t i = firstLeg; i < work.moves.size(); ++i)
        work.moves[i].noseComp = noseCompWith(NoseSide::None, state.offset);
  }
  return done.continueAfter;
}

}  // namespace lathesim::interp
