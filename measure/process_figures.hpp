#pragma once
// How the program spends the machine: path lengths, time spent feeding through air, and
// the material each tool removed. Computed from the toolpath and the simulation's
// per-block removal, so they come with every check at no extra simulation cost.
//
// "Cutting air" is counted per block, the unit sim measures removal in: the feed moves
// (straight or arc) of a block that removed less than one voxel's volume of material. A
// cycle block that cuts is not counted, though its retract leg may run through air.
// Times are sums of Move::timeS, so they are as right as the cycle-time model is.

#include <vector>

#include "interp/output/move_spool.hpp"
#include "sim/block_rows.hpp"

namespace lathesim::measure {

struct ToolRemoval {
  int tool = 0;
  double removedMm3 = 0;
};

struct ProcessFigures {
  double rapidPathMm = 0;  // tool-tip path length in the (r, z) plane
  double feedPathMm = 0;   // straight feeds and arcs (arc length)
  double rapidTimeS = 0, feedTimeS = 0;
  int airFeedMoves = 0;
  double airFeedPathMm = 0;
  double airFeedTimeS = 0;
  std::vector<ToolRemoval> removedPerTool;  // by tool number
};

/// The length of a move's path (mm): arcs along the arc, dwells 0.
double pathLengthMm(const interp::Move& move);

/// From the moves and the simulation's rows of the same run, read in step: row k is the k-th
/// run of consecutive moves of one block (sim/simulation.hpp cuts them so). Holds two bits a
/// source block and a total for each block run more than once (a subprogram's, a loop's),
/// not a figure a move. Throws std::logic_error if the rows are not the moves'.
ProcessFigures processFigures(const interp::MoveSpool& moves, const sim::BlockRows& rows, double voxelMm);

}  // namespace lathesim::measure
