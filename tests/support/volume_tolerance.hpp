#pragma once
// How far a simulated volume may stray from the exact one, for tests that check parts.

#include "sim/stock.hpp"

namespace lathesim::test {

/// The level set places the surface to a small fraction of a voxel, so its rounding is a
/// thin skin over the surface; a real error (a cut misplaced by even one voxel, a pass
/// missed) moves whole voxel layers over part of the surface. So the bound scales with
/// voxel × surface area: 5 % of one voxel layer over the bar's whole surface (2πr² + 2πrL;
/// a tube's bore too).
/// The rounding measured on the bundled parts is 1e-5 to 4e-4 relative, at most a fifth of
/// this bound; seed 001's difference is ~7 bounds at 0.5 mm.
inline double volumeToleranceMm3(const sim::StockSpec& stock, double voxelMm) {
  return sim::volumeToleranceMm3(sim::surfaceAreaMm2(stock), voxelMm);
}

}  // namespace lathesim::test
