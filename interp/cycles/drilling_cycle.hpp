#pragma once
// G81, G82 and G83: drilling on the spindle's axis with the part turning (a drill in the
// turret at X0), from the tool's position; G84 taps there the same way. See
// drilling_cycle.cpp for the moves.

#include <cstddef>
#include <optional>
#include <vector>

#include "geometry/rz.hpp"
#include "interp/contour/cycle_leg.hpp"

namespace lathesim::interp {

struct DrillingParams {
  double rPlaneZ = 0;    // Z of the R point, where the feed starts
  double bottomZ = 0;    // Z of the hole's bottom
  double peckMm = 0;     // G83 Q: the depth of each peck (0: one feed to the bottom)
  double clearanceMm = 0;  // G83: how far short of the last depth the tool comes back down at rapid
  bool tapping = false;    // G84: back out to the R point at feed (the spindle reversed), then rapid
};

/// The legs down to the bottom and, apart, the legs back up to `start`'s Z (the cycle dwells
/// between them when it has a dwell). A tap's `up` begins with its feed back out to the R
/// point, made with the spindle reversed.
struct DrillingLegs {
  std::vector<CycleLeg> down;
  std::vector<CycleLeg> up;
};

/// Nullopt when it would take more than `maxLegs` pecks (the move limit): pecks of microns
/// over metres would fill memory first, and a peck below the precision of a far depth never
/// arrives.
std::optional<DrillingLegs> drillingLegs(const RZ& start, const DrillingParams& params, std::size_t maxLegs);

}  // namespace lathesim::interp
