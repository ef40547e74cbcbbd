#pragma once
// Inside sim only: u ← min(u, ψ) over one column of eight voxels along Z, the one voxel write
// shared by the level set's writer (region_writer.cpp) and the revolved table
// (revolved_table.cpp), so that both give the same values, masks and volumes.

#include <cstdint>

namespace lathesim::sim {

/// What writing one column needs besides the values and the distances.
struct ColumnWrite {
  double sign;           // u = sign·φ
  double band;           // bg: u ≤ −band is as deep in the region's state as the band allows
  double noChange;       // smaller decreases of u are rounding, not cuts
  double inverseVoxel;
  double voxel;          // a ghost candidate lies within a voxel of the boundary...
  float notMaterial;     // ...and could count as material: notMaterial < φ < ghostCeiling
  float ghostCeiling;

  /// sign +1 adds material (φ ← min(φ, ψ)), −1 removes it (φ ← max(φ, −ψ)).
  static ColumnWrite of(double sign, double voxelMm, float bandMm) {
    // A change smaller than noChange is rounding between the stock's float values and the
    // region's double distance (a tool running along a face it cut before), not a cut.
    return {sign, bandMm, 1e-5 * voxelMm, 1.0 / voxelMm, voxelMm, materialCeiling(voxelMm),
            static_cast<float>(0.5 * voxelMm)};
  }
  /// φ at or below this is material for the ghost test (above: rounding, not material).
  static float materialCeiling(double voxelMm) { return static_cast<float>(-1e-3 * voxelMm); }

  /// Whether some of values[0…7] is open: not yet as deep in the region's state as the band
  /// allows (u = sign·φ > −band, writeColumn's test). Asked of the floats as they are, which
  /// the compiler does as a vector compare: the band is a float (of() takes one), so φ < band
  /// when removing, φ > −band when adding, is the same test.
  bool anyOpen(const float* values) const {
    const float limit = static_cast<float>(band);
    bool open = false;
    if (sign < 0.0)
      for (int k = 0; k < 8; ++k) open |= values[k] < limit;
    else
      for (int k = 0; k < 8; ++k) open |= values[k] > -limit;
    return open;
  }
};

/// u ← min(u, ψ) over values[0…7] with distances psi[0…7]. Returns the material voxels lost;
/// updates the column's bits of the active mask and sets those of the ghost candidates (voxels
/// within a voxel of the boundary that could count as material: see region_writer.cpp).
double writeColumn(const ColumnWrite& w, float* values, const double* psi, std::uint8_t& activeBits,
                   std::uint8_t& ghostBits);

}  // namespace lathesim::sim
