#pragma once
// G73, pattern repeating: the finishing contour cut d times, shifted less each pass.

#include <cstddef>
#include <optional>
#include <vector>

#include "geometry/rz.hpp"
#include "interp/contour/contour.hpp"
#include "interp/contour/cycle_leg.hpp"

namespace lathesim::interp {

struct PatternRepeatParams {
  double reliefXMm = 0;     // Δi: total X relief, a RADIUS, signed
  double reliefZMm = 0;     // Δk: total Z relief, signed
  int passes = 2;           // d ≥ 1
  bool singlePassRunsTwice = true;  // d = 1 runs as 2 (GSK), or once at the allowance alone
  double allowanceXMm = 0;  // Δu/2: finishing allowance in X as a RADIUS, signed
  double allowanceZMm = 0;  // Δw, signed
};

/// The legs of G73 from the cycle start `start` (A) along `contour` (which starts at A), whose
/// first `firstBlockSegments` segments the ns block made, rapid or at feed as `firstBlockRapid`.
/// Nullopt when there would be more than `maxLegs` (the move limit), found before they are made.
std::optional<std::vector<CycleLeg>> patternRepeatLegs(const RZ& start, const Contour& contour,
                                                       std::size_t firstBlockSegments, bool firstBlockRapid,
                                                       const PatternRepeatParams& params, std::size_t maxLegs);

}  // namespace lathesim::interp
