#pragma once
// G90 and G94 read from their block (lathe-cycles.md §1; their legs: g90_cycle.hpp,
// g94_cycle.hpp): the end point given or kept from an earlier block of the cycle, the taper
// R checked against the travel, and the legs emitted, offset by the tip number under G41/G42
// (cycle_nose_compensation.hpp). A block that gives none of X U Z W R only makes the cycle
// the modal motion.

#include <optional>
#include <string_view>

#include "interp/base/result.hpp"
#include "interp/state/block_work.hpp"
#include "interp/text/block_parser.hpp"

namespace lathesim::interp {

/// The end point C of a single cycle (G90, G92, G94) in the work frame.
struct CycleEndPoint {
  double xDiameterMm;
  double zMm;
};

/// C from the block's X(U) and Z(W), a word not given taken from the cycle's earlier block
/// (the cycles are modal: lathe-cycles.md §1), or the error at `anchor` naming the one that
/// neither gives. `name` is the cycle's code as written.
Result<CycleEndPoint> singleCycleEndPoint(BlockWork& work, const AxisWords& axes, std::string_view name,
                                          int anchor);

/// G90 on `work`'s block: `code` as written, or none when the block repeats the modal cycle.
Status runAxialCycle(BlockWork& work, const std::optional<Code>& code);

/// G94 on `work`'s block, as runAxialCycle.
Status runFaceCycle(BlockWork& work, const std::optional<Code>& code);

/// When a block repeats modal cycle `name` (no `code` written) right after a G80 that
/// stood with it, the warning that G80 cancels drilling cycles only.
void warnIfCycleRepeatsAfterG80(BlockWork& work, const std::optional<Code>& code, std::string_view name);

}  // namespace lathesim::interp
