#pragma once
// The G71/G72 stock-removal engine, written once for G71's axes: levels of constant X,
// passes parallel to Z. G72 calls it with the axes exchanged (see g72_cycle.cpp). The moves it
// makes are listed at the top of stock_removal.cpp.

#include <vector>

#include "geometry/rz.hpp"
#include "interp/contour/contour.hpp"
#include "interp/contour/cycle_leg.hpp"
#include "interp/base/result.hpp"
#include "interp/cycles/roughing_cycle.hpp"

namespace lathesim::interp {

/// How the caller names the engine's two axes in its diagnostics.
struct StockRemovalNames {
  const char* cycle;     // "G71" or "G72"
  const char* stepAxis;  // the axis the levels step in: "X" for G71, "Z" for G72
  const char* cutAxis;   // the axis the passes run along: "Z" for G71, "X" for G72
};

/// The legs of a stock-removal cycle in the engine's frame: x() is the step axis, y() the
/// cutting axis; `params.allowanceXMm` is the allowance in the step axis.
Result<std::vector<CycleLeg>> stockRemovalLegs(const RZ& start, const Contour& contour,
                                               const RoughingParams& params,
                                               const StockRemovalNames& names);

}  // namespace lathesim::interp
