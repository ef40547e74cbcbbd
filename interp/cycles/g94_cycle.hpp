#pragma once
// G94, the face (radial) cutting cycle of system A, expanded into primitive moves.

#include <optional>
#include <string>
#include <vector>

#include "geometry/rz.hpp"
#include "interp/contour/cycle_leg.hpp"

namespace lathesim::interp {

/// The legs of one G94 pass, zero-length legs left out.
/// `start` is A and `end` is C, both (radius mm, Z mm); `rMm` is the taper, "Z of the cut's
/// start minus Z of its end" (0 for a straight face).
std::vector<CycleLeg> faceCycleLegs(const RZ& start, const RZ& end, double rMm);

/// Why this taper is not allowed, or nullopt when it is: when R and W (= Z_C − Z_A) have
/// opposite signs, |R| must not exceed |W|.
std::optional<std::string> faceCycleTaperProblem(double wMm, double rMm);

}  // namespace lathesim::interp
