#pragma once
// Part-off during a simulation: after a cut, the material that no longer hangs together with
// the chuck's end has fallen. It is taken out of the stock (which is then the stub left in
// the chuck); the first piece is the part. A later cut into where that part was is warned
// of: the part is not there to cut (it fell, or the parts catcher has it).

#include <cstddef>
#include <optional>

#include "geometry/revolved_region.hpp"
#include "interp/move.hpp"
#include "sim/simulate.hpp"
#include "sim/stock.hpp"

namespace lathesim::sim {

class PartOffWatch {
 public:
  /// After moves[first, end) of `toolpath`, one written group of moves, removed `removedMm3`
  /// from `stock` within `changed`. `revolved` is what they swept when they turned (empty for a
  /// thread or a slot: then the part that fell is not looked for in it).
  void afterCut(const interp::Toolpath& toolpath, std::size_t first, std::size_t end, const RevolvedRegion& revolved,
                const std::optional<ChangedArea>& changed, double removedMm3, Stock& stock, SimulationResult& result);

 private:
  int warnedBlock_ = -1;  // one warning per block for cutting where the part was
};

}  // namespace lathesim::sim
