#pragma once
// G90, the axial (OD/ID turning) cutting cycle of system A, expanded into primitive moves.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/rz.hpp"
#include "interp/contour/cycle_leg.hpp"

namespace lathesim::interp {

/// The legs of one G90 pass, zero-length legs left out.
/// `start` is A and `end` is C, both (radius mm, Z mm); `rMm` is the taper, a RADIUS:
/// "radius at the cut's start minus radius at its end" (0 for a straight cylinder).
std::vector<CycleLeg> axialCycleLegs(const RZ& start, const RZ& end, double rMm);

/// Why this taper is not allowed, or nullopt when it is: when R and U (= X_C − X_A, a
/// diameter) have opposite signs, |R| must not exceed |U/2|. G92 has the same rule;
/// `name` is the code as the program writes it.
std::optional<std::string> axialCycleTaperProblem(double uDiameterMm, double rMm, std::string_view name);
inline std::optional<std::string> axialCycleTaperProblem(double uDiameterMm, double rMm) {
  return axialCycleTaperProblem(uDiameterMm, rMm, "G90");
}

}  // namespace lathesim::interp
