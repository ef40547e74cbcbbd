#pragma once
// Tolerances a drawing may state without numbers: ISO 286 fits on a diameter (h7, H7, g6 …)
// and the general tolerance classes of ISO 2768-1 (f, m, c, v) for sizes with no tolerance.

#include <optional>
#include <string>

namespace lathesim::measure {

/// A size's permitted deviations from its nominal value, mm (upper ≥ lower; either may be
/// negative), and where they came from, as a report states it ("h7", "±0.1", "ISO 2768-m").
struct Tolerance {
  double upperMm = 0, lowerMm = 0;
  std::string source;
};

/// The limits of an ISO 286 fit such as "h7", "g6", "js6", "H7", "K7" on a nominal size of
/// `nominalMm` (0 < size ≤ 500): shaft letters d e f g h js k m n p, hole letters D E F G H
/// JS K M N P, grades IT5–IT11. nullopt with `problem` set when the fit or size is not covered.
std::optional<Tolerance> isoFit(const std::string& fit, double nominalMm, std::string& problem);

/// True when `fit` names a hole (upper-case letter), false for a shaft.
bool isHoleFit(const std::string& fit);

/// ISO 2768-1's permissible deviation ±t for linear sizes of class 'f', 'm', 'c' or 'v' at
/// nominal size `nominalMm` (sizes under 0.5 mm take the first row; over 4000 mm the last).
/// nullopt for class v under 3 mm, which the standard leaves open.
std::optional<double> generalLinearTolerance(char toleranceClass, double nominalMm);

}  // namespace lathesim::measure
