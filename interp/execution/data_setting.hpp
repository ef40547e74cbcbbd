#pragma once
// G10, programmable data input, in the forms Fanuc lathes use (Fanuc 16i/18i-TB §14.5.2,
// 0i-T):
//   G10 P_ X_ Z_ R_ Q_     tool offset: P1…P99 its wear entry, P10001…P10099 its geometry
//                          entry; X (a diameter), Z and R set the value, U, W and C add to it;
//                          Q sets the imaginary tip number. The changed entry takes effect at
//                          the next T word that selects it (the offset in force keeps the
//                          values its T word found).
//   G10 L2 P_ X_ Z_        work offset: P0 the external offset (added to every system), P1…P6
//                          G54…G59; X (a diameter) and Z set it, U and W add to it. It applies
//                          at once: the tool stays where it is, its coordinates change.
// G10 P0 (the T series' work coordinate system shift) and other L numbers are refused.

#include "interp/state/modal_state.hpp"
#include "interp/interpreter.hpp"
#include "interp/base/result.hpp"
#include "interp/text/block_parser.hpp"

namespace lathesim::interp {

/// Applies the G10 in `block` (`g10`) to `state`, taking the words it uses.
Status applyDataSetting(ParsedBlock& block, const Code& g10, ModalState& state,
                        const InterpreterOptions& options);

}  // namespace lathesim::interp
