#pragma once
// The warnings the simulation gives, worded in one place (see SimulationWarning).

#include "interp/base/move.hpp"
#include "sim/simulate.hpp"
#include "sim/stock.hpp"

namespace lathesim::sim {

/// A warning when `start` lies inside `stock` as it is now (deeper than kInsideStockVoxels).
std::optional<SimulationWarning> cycleStartInStock(const interp::CycleStart& start, const Stock& stock);

/// After G50 moved the program's frame (a move's workShift differs from the moves' before it),
/// a warning when `move`, one of the moves up to the first cut, takes the tool into `stock` as
/// it is now: a rapid that ends inside it, or a cut that starts inside it. The position G50
/// declared is not where the setup has the tool.
std::optional<SimulationWarning> shiftedMoveInStock(const interp::Move& move, const Stock& stock);

/// A warning when a cutting move (feed, arc or thread) made with the spindle stopped removed
/// more than kCollisionVoxels voxels' worth of material: it names the cut, a straight slot.
std::optional<SimulationWarning> cutWithSpindleStopped(const interp::Move& head, double removedMm3,
                                                       double voxelMm);

/// A warning when the thread pass that `move` begins (a thread move not continuing `before`,
/// the toolpath's move before it, null for the first) starts inside `stock` (deeper than
/// kInsideStockVoxels): the pass would be synchronised to the spindle with the tool already in
/// the material.
std::optional<SimulationWarning> threadPassStartsInStock(const interp::Move& move, const interp::Move* before,
                                                         const Stock& stock);

}  // namespace lathesim::sim
