#pragma once
// G76 in Haas's one-block form (haas dialect): G76 X(U) Z(W) K D F [A I P], mapped onto the
// two-block cycle's passes (g76_cycle.hpp). See haas_g76.cpp for the rules.

#include <functional>
#include <vector>

#include "interp/contour/cycle_leg.hpp"
#include "interp/state/modal_state.hpp"
#include "interp/interpreter.hpp"
#include "interp/base/result.hpp"
#include "interp/text/block_parser.hpp"

namespace lathesim::interp {

/// The passes of Haas G76 `code` in `block` from the tool's position, taking the words it
/// uses. `lengthMm` reads a length word (and notes how it was written); `feedGiven`: the block
/// gave F.
Result<std::vector<CycleLeg>> haasThreadingLegs(const Code& code, ParsedBlock& block, ModalState& state,
                                                const InterpreterOptions& options, bool feedGiven,
                                                const std::function<double(const Word&)>& lengthMm,
                                                std::vector<Error>& warnings);

/// The cumulative depths of Haas G76's passes: P1 (single edge, constant cutting amount)
/// D·√n, a pass adding at least `minimumCutMm` (Setting 99); P3 (single edge, constant depth)
/// n·D; the last at exactly `finalDepthMm`. nullopt past `maxPasses`.
std::optional<std::vector<double>> haasPassDepths(bool constantDepth, double firstDepthMm, double minimumCutMm,
                                                  double finalDepthMm, int maxPasses);

}  // namespace lathesim::interp
