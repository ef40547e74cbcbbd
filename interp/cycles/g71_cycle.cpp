// G71, stock removal in turning (lathe-cycles.md §3): levels of constant X, Δd apart (a
// radius), each cut parallel to Z at F until it meets the rough contour (the finishing contour
// translated by (Δu/2, Δw)); 45° retract by e, rapid back in Z (type I) or follow the contour
// and back off by e (type II, pockets); then a semi-finishing pass along the rough contour
// B′ → C′ and a rapid back to A. The engine and its full move list, with the step numbers the
// legs carry, are in stock_removal.cpp, which is written in G71's axes.

#include "interp/cycles/roughing_cycle.hpp"
#include "interp/cycles/stock_removal.hpp"

namespace lathesim::interp {

Result<std::vector<CycleLeg>> turningRoughingLegs(const RZ& start, const Contour& contour,
                                                  const RoughingParams& params) {
  return stockRemovalLegs(start, contour, params, {"G71", "X", "Z"});
}

}  // namespace lathesim::interp
