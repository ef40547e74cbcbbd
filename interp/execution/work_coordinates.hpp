#pragma once
// G54–G59 (work coordinate systems) and G53 (a one-shot move in machine coordinates), on the
// frame of interp/state/work_frame.hpp.
//   G54…G59       selects a system; the tool stays where it is, its coordinates change.
//   G53 X_ Z_     rapid to the machine coordinates X (a diameter) and Z: machine zero is where
//                 the setup puts it (InterpreterOptions::machineZero, by default the reference
//                 point). Absolute only: U/W, or G91, are errors. As on the GSK980TDi (3.20),
//                 the move is a G00 and it cancels G41/G42 (the G53 move is the cancel move).

#include "interp/state/modal_state.hpp"
#include "interp/interpreter.hpp"
#include "interp/base/result.hpp"
#include "interp/text/block_parser.hpp"

namespace lathesim::interp {

/// G5x (`code`, 54…59): the system selected, the position expressed in it.
void selectWorkSystem(const Code& code, ModalState& state);

/// Changes the work offsets to `offsets` (G10 L2): the position is re-expressed when the
/// selected system's shift changes, so the tool does not move.
void changeWorkOffsets(const WorkOffsets& offsets, ModalState& state);

/// G53's end point in the selected system's coordinates (radius, Z); takes X and Z from `block`.
Result<RZ> machineCoordinateTarget(ParsedBlock& block, const Code& g53, const ModalState& state,
                                   const InterpreterOptions& options);

}  // namespace lathesim::interp
