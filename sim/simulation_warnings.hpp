#pragma once
// The warnings the simulation gives, worded in one place (see SimulationWarning).

#include "interp/move.hpp"
#include "sim/simulate.hpp"
#include "sim/stock.hpp"

namespace lathesim::sim {

/// A warning when `start` lies inside `stock` as it is now (deeper than kInsideStockVoxels).
std::optional<SimulationWarning> cycleStartInStock(const interp::CycleStart& start, const Stock& stock);

/// A warning when a cutting move (feed or arc) group with the spindle stopped removed more
/// than kCollisionVoxels voxels' worth of material.
std::optional<SimulationWarning> cutWithSpindleStopped(const interp::Move& head, double removedMm3,
                                                       double voxelMm);

}  // namespace lathesim::sim
