#pragma once
// Part-off during a simulation: after a cut, the material that no longer hangs together with
// the chuck's end has fallen. It is taken out of the stock. It is the part only when the
// program parted it off on purpose: when it holds most of the material from its own lowest Z
// on (it and what stays there) — a cut through the whole bar (a parting blade to the axis or
// the bore, a face cut past the centre) leaves nothing else there. The stock is then the stub
// left in the chuck; the first such piece is the part. A piece set loose otherwise (a skin
// a finishing arc undercut on a full bar, a ring around a bore, a chip far smaller than what
// stays beside it) is a LoosePiece, warned of at its block: it falls, is in no mesh, and the
// stock stays the part. A later cut into where the part was is warned of: the part is not
// there to cut (it fell, or the parts catcher has it).

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "geometry/revolved_region.hpp"
#include "interp/base/move.hpp"
#include "sim/simulate.hpp"
#include "sim/stock.hpp"

namespace lathesim::sim {

class PartOffWatch {
 public:
  /// After `group`, one written group of moves (the toolpath's from its move `first` on),
  /// removed `removedMm3` from `stock` within `changed`. `revolved` is what they swept when they
  /// turned (empty for a thread or a slot: then the part that fell is not looked for in it);
  /// `catchers`, the parts catcher commands reached so far.
  void afterCut(std::span<const interp::Move> group, std::size_t first,
                const std::vector<interp::PartsCatcherCommand>& catchers, const RevolvedRegion& revolved,
                const std::optional<ChangedArea>& changed, double removedMm3, Stock& stock, SimulationResult& result);

 private:
  int warnedBlock_ = -1;  // one warning per block for cutting where the part was
};

}  // namespace lathesim::sim
