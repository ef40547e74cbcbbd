// Measuring material inside a region without removing it (holder collisions).

#include <cmath>
#include <numbers>

#include "sim/stock_grid.hpp"

namespace lathesim::sim {

double Stock::materialInside(const RevolvedRegion& region, double marginMm) const {
  const StockGrid& s = *impl_;
  const double h = s.voxel;
  const auto& bounds = s.materialBounds;
  if (region.empty()) return 0.0;
  const int i0 = std::max(0, s.toIndexFloor(region.lowerBound().x()));
  const int i1 = std::min(bounds.max().x(), s.toIndexCeil(region.maxRadius()));
  const int k0 = std::max(bounds.min().z(), s.toIndexFloor(region.lowerBound().y()));
  const int k1 = std::min(bounds.max().z(), s.toIndexCeil(region.upperBound().y()));
  auto accessor = s.grid->getConstAccessor();
  double sum = 0.0;
  for (int i = i0; i <= i1; ++i) {
    const double rho = i * h;
    // The ring a meridian voxel stands for: 2πρ·h², and the axis voxel's own disc.
    const double ring = i == 0 ? std::numbers::pi * h * h * h / 4.0 : 2.0 * std::numbers::pi * rho * h * h;
    for (int k = k0; k <= k1; ++k) {
      const float phi = s.table ? s.table->value(i, 0, k) : accessor.getValue(Coord(i, 0, k));
      const double material = insideFraction(phi, h);
      if (material == 0.0) continue;
      // Only values within a voxel of -marginMm matter, so the distance may stop there.
      const double psi = region.signedDistance(rho, k * h, marginMm + h) + marginMm;
      sum += material * std::clamp(0.5 - psi / h, 0.0, 1.0) * ring;
    }
  }
  return sum;
}

}  // namespace lathesim::sim
