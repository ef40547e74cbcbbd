#pragma once
// Which move made the part's surface at a point: the line to blame when the surface there is
// out of tolerance, whether too much material was left (excess, oversize) or too much was cut
// (gouge, undersize). The surface at a point p was left by the cutting move whose swept
// region's edge passes through p: of the cutting moves whose sweep (as sim sweeps it,
// sim/move_sweep.hpp) comes within `reachMm` of p, the nearest; of moves equally near (within
// a tenth of the reach, as a roughing pass and the finishing pass over the same line), the
// last, whose cut the part kept. A finishing pass's X that is wrong is so found on the block
// that programmed it, a roughing pass that went too deep on its own.
//
// The move's own line may not be the block that gave the value: `G00 X19.5` then `G01 Z-20`
// turns Ø19.5 on the second line with the first's X. So each maker also names the line of
// the last move before it (itself included) that changed X, and the one that changed Z: the
// blocks whose X or Z word put the tool where it made the surface.

#include <optional>
#include <vector>

#include "geometry/rz.hpp"
#include "interp/output/move_spool.hpp"
#include "sim/simulate.hpp"

namespace lathesim::measure {

struct SurfaceMaker {
  int line = 0;   // the move's
  int xLine = 0;  // the move that last changed X (the radius) before or at it
  int zLine = 0;  // and Z
};

/// A point of the part's surface, and the direction the surface runs there when known (a
/// diameter runs along Z, a face along X): of equally near moves, the one moving most along
/// it made the surface (the pass along a diameter, not the step up its shoulder that touches
/// its end), then the last.
struct SurfacePoint {
  RZ at{0, 0};
  std::optional<RZ> along;
};

/// The move that made the surface at each of `points`, or nullopt where no cutting move came
/// within `reachMm` (the bar's own surface). One pass over the moves.
std::vector<std::optional<SurfaceMaker>> surfaceMakers(const std::vector<SurfacePoint>& points,
                                                       const interp::MoveSpool& moves, const sim::ToolOutlines& tools,
                                                       double voxelMm, double reachMm);

}  // namespace lathesim::measure
