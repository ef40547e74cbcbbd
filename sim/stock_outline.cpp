// The stock's section in the meridian half-plane, for comparing the part with a drawing.
//
// A turned part is a solid of revolution (threads aside), so everything a drawing check
// needs lies in one half-plane through the axis. The grid's voxel centres sit at integer
// multiples of the voxel, so the plane y = 0 is a plane of samples: φ is read there as
// stored, no interpolation across y. Near the surface φ is a distance (exact for the bar
// and for each cut), so the zero crossings found by linear interpolation between samples
// lie within a small fraction of a voxel of the true surface; away from it φ is clamped to
// the band and only its sign is used.

#include <cmath>

#include "sim/stock_grid.hpp"

namespace lathesim::sim {

SampledSection Stock::meridianSection() const {
  const StockGrid& s = *impl_;
  const int margin = kHalfBandVoxels + 2;
  const int rLast = s.toIndexCeil(s.spec.diameterMm / 2.0) + margin;
  const int zFirst = s.toIndexFloor(s.spec.faceZMm - s.spec.lengthMm) - margin;
  const int zLast = s.toIndexCeil(s.spec.faceZMm) + margin;

  SampledSection section;
  section.stepMm = s.voxel;
  section.zFirstMm = zFirst * s.voxel;
  section.rCount = rLast + 1;
  section.zCount = zLast - zFirst + 1;
  section.clampMm = s.background;
  section.phi.resize(static_cast<std::size_t>(section.rCount) * section.zCount);
  const auto at = [&](int i, int k) -> float& { return section.phi[static_cast<std::size_t>(k) * section.rCount + i]; };
  if (s.table) {  // revolved: the table holds the plane y = 0 as the level set would
    for (int i = 0; i < section.rCount; ++i) s.table->columnValues(i, 0, zFirst, section.zCount, &at(i, 0), section.rCount);
    return section;
  }
  const auto accessor = s.grid->getConstAccessor();
  for (int k = 0; k < section.zCount; ++k)
    for (int i = 0; i < section.rCount; ++i) at(i, k) = accessor.getValue(Coord(i, 0, zFirst + k));
  return section;
}

}  // namespace lathesim::sim
