#pragma once
// Inside sim: the rules a simulation judges moves by (what turns, what is a crash, what is
// inside the stock), shared by the simulation, its warnings and its collision checks.

#include <vector>

#include "interp/base/move.hpp"
#include "sim/simulation_result.hpp"

namespace lathesim::sim {

/// Adds a collision, or grows the block's own (same line and column) of the same kind when the
/// block's are the last ones: one collision for the two legs of a dog-leg rapid, or for the
/// moves of one cycle.
void recordCollision(std::vector<Collision>& collisions, const interp::Move& move, const char* kind, double volumeMm3);

/// A rapid that removes more than this many voxels' worth of material is a collision;
/// below it, the removal is rounding at a surface the rapid merely grazes.
inline constexpr double kCollisionVoxels = 10.0;

/// A cycle start point deeper in the material than this many voxels is inside the stock
/// (one voxel: points on the surface, such as a corner just cut, are not).
inline constexpr double kInsideStockVoxels = 1.0;

/// Whether the spindle turns during `move` (M03/M04 in force and S > 0).
bool spindleTurns(const interp::Move& move);

}  // namespace lathesim::sim
