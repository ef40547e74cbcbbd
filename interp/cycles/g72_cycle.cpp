// G72, stock removal in facing (lathe-cycles.md §4): G71 with the axes exchanged. Levels of
// constant Z, Δd apart; each pass runs parallel to X at F until it meets the rough contour
// (translated by (Δu/2, Δw)); 45° retract by e in both axes, rapid back in X to A′'s X (type
// I), or follow the contour and back off by e in Z (type II: X monotonic, Z may have
// pockets); then the semi-finishing pass B′ → C′ and a rapid back to A.
// Done by mirroring everything about the X = Z diagonal (coordinates exchanged, G02 ↔ G03),
// running the G71 engine (stock_removal.cpp, whose move list and step numbers apply with X and
// Z exchanged), and mirroring the legs back.

#include "interp/contour/contour_geometry.hpp"
#include "interp/cycles/roughing_cycle.hpp"
#include "interp/cycles/stock_removal.hpp"

namespace lathesim::interp {

Result<std::vector<CycleLeg>> facingRoughingLegs(const RZ& start, const Contour& contour,
                                                 const RoughingParams& params) {
  RoughingParams mirroredParams = params;
  mirroredParams.allowanceXMm = params.allowanceZMm;
  mirroredParams.allowanceZMm = params.allowanceXMm;
  mirroredParams.roughAllowanceXMm = params.roughAllowanceZMm;
  mirroredParams.roughAllowanceZMm = params.roughAllowanceXMm;
  auto legs = stockRemovalLegs(swappedAxes(start), swappedAxes(contour), mirroredParams,
                               {"G72", "Z", "X"});
  if (!legs.ok()) return legs;
  return swappedAxes(std::move(legs).value());
}

}  // namespace lathesim::interp
