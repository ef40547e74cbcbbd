#pragma once
// G28 X(U) Z(W) — reference point return (lathe-cycles.md §7). Moves it makes:
//   1. rapid from the current position to the intermediate point: each named axis goes to
//      its X(U)/Z(W) value, an axis not named stays where it is;
//   2. rapid from there to the reference point, again on the named axes only.
// Zero-length legs are left out, so `G28 U0 W0` (the usual idiom) makes only leg 2.

#include <optional>
#include <vector>

#include "interp/contour/cycle_leg.hpp"

namespace lathesim::interp {

/// The legs, with step numbers 1 and 2. `intermediateRadiusMm` / `intermediateZMm` are the
/// intermediate point's coordinates on the named axes (absolute, already resolved from U/W),
/// nullopt for an axis the block does not name. `reference` is (radius mm, Z mm).
std::vector<CycleLeg> referenceReturnLegs(const RZ& position, std::optional<double> intermediateRadiusMm,
                                          std::optional<double> intermediateZMm, const RZ& reference);

}  // namespace lathesim::interp
