#pragma once

#include <numbers>

namespace lathesim::sim {

/// A round bar on the spindle axis spanning Z = faceZMm − lengthMm … faceZMm; with a bore, a
/// tube (boreMm < diameterMm).
struct StockSpec {
  double diameterMm = 125.0;
  double lengthMm = 112.0;
  double faceZMm = 2.0;  // Z of the right-hand end face
  double boreMm = 0.0;   // the bore's diameter; 0 for a solid bar
};

/// The bar's exact volume, π(R² − r²)L.
inline double exactVolumeMm3(const StockSpec& bar) {
  const double outer = bar.diameterMm / 2.0, inner = bar.boreMm / 2.0;
  return std::numbers::pi * (outer * outer - inner * inner) * bar.lengthMm;
}

/// The bar's whole surface: its outside and bore, 2π(R + r)L, and two end faces, 2π(R² − r²).
inline double surfaceAreaMm2(const StockSpec& bar) {
  const double outer = bar.diameterMm / 2.0, inner = bar.boreMm / 2.0;
  return 2.0 * std::numbers::pi * (outer + inner) * (bar.lengthMm + outer - inner);
}

}  // namespace lathesim::sim
