#pragma once
// What a figure measured at a voxel can tell: a verdict is decided only when the figure lies
// further than the voxel's uncertainty from its limit; closer, it is undecided, and the check
// names the voxel that would decide it.

#include <optional>

namespace lathesim::measure {

/// How far a surface found in a section at voxel h may lie from the true one (mm), and the
/// same on a diameter (twice: a diameter is two radii of the same surface of revolution).
/// (h/16: see verdict.cpp for why.)
double surfaceUncertaintyMm(double voxelMm);

enum class Verdict { Within, Undecided, Out };

const char* verdictName(Verdict verdict);  // "within", "undecided", "out"

/// The verdict on a figure lying `outsideMm` beyond its nearest limit (≤ 0: inside) when it
/// is known to ±`uncertaintyMm`.
Verdict verdictOf(double outsideMm, double uncertaintyMm);

/// A voxel at which a figure known to ±`uncertaintyMm` at voxel `voxelMm` would be known
/// to better than |outsideMm| (uncertainties scale with the voxel), so that it decides;
/// nullopt when the figure sits on its limit within a thousandth of a millimetre.
std::optional<double> decidingVoxelMm(double outsideMm, double voxelMm, double uncertaintyMm);

}  // namespace lathesim::measure
