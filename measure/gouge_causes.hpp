#pragma once
// Which moves cut a gouge. Cutting only ever removes, so a point that was material in the
// bar and is air at the end was removed by the FIRST move, in program order, whose swept
// region (the tool outline swept along the move, as sim sweeps it) covers it. A gouge
// region's points are probed at the midpoints between its samples and their nearest points
// on the other surface — inside the drawing and in the air, where the cut went too deep —
// and the lines of the moves that first covered them are the region's causes. A point the
// bar never held (the drawing asks for more than the stock has) has no cause.

#include "measure/deviation.hpp"
#include "interp/output/move_spool.hpp"
#include "sim/simulate.hpp"
#include "sim/stock_spec.hpp"

namespace lathesim::measure {

/// Fills `lines` of every gouge region of `report` (sorted, each line once). Moves sweep as
/// in the simulation at `voxelMm` (sim/move_sweep.hpp); one pass over them, each swept and
/// let go in turn.
void attributeGouges(DeviationReport& report, const interp::MoveSpool& moves, const sim::ToolOutlines& tools,
                     const sim::StockSpec& stock, double voxelMm);

}  // namespace lathesim::measure
