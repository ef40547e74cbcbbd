#pragma once
// Direct drawing dimensions, format 1 (GSK980TDi §3.13; Fanuc's A / ,A): a straight move given
// by one end coordinate and the line's angle, as drawings dimension a chamfer or taper. The
// angle is measured from +Z, counter-clockwise seen from +Y (Z to the right, X up), in degrees;
// only the line's slope matters, so A-45 and A135 are the same line.
//   X(U) given:  Z = Z0 + Δr / tan A     (alarm within 1° of 0° or 180°: the line never gets there)
//   Z(W) given:  X = X0 + 2·ΔZ · tan A   (alarm within 1° of 90° or 270°)
// With both X and Z the end point is given and the angle is not needed (GSK: it is ignored, and
// lathesim warns). A block with the angle alone starts a two-line dimension (formats 2–8), which
// lathesim does not read yet: an error.

#include <optional>

#include "geometry/rz.hpp"
#include "interp/base/result.hpp"
#include "interp/text/lexer.hpp"

namespace lathesim::interp {

/// The end of the line from `start` (radius, Z) at `angleDeg` that ends at `endRadiusMm` or at
/// `endZMm` (exactly one given); an error at `angle` when the line never reaches it.
Result<RZ> lineEndByAngle(const RZ& start, std::optional<double> endRadiusMm, std::optional<double> endZMm,
                          double angleDeg, const Word& angle, int line);

}  // namespace lathesim::interp
