// The one voxel write: see column_write.hpp.

#include "sim/column_write.hpp"

#include <cstring>

namespace lathesim::sim {

// u ← min(u, ψ) over one column of eight voxels (values[0…7], along Z), four at a time in
// GCC vector types (one AVX2 register in the AVX2 clone, two SSE2 ones elsewhere), without
// branches. Returns the material voxels lost; updates the column's bits of the active mask
// and sets those of the ghost candidates (see clearGhostSheets).
using Double4 = double __attribute__((vector_size(32)));
using Float4 = float __attribute__((vector_size(16)));
using Mask4 = std::int64_t __attribute__((vector_size(32)));  // lanes −1 (true) or 0

__attribute__((target_clones("avx2", "default"))) double writeColumn(const ColumnWrite& w, float* values,
                                                                     const double* psi, std::uint8_t& activeBits,
                                                                     std::uint8_t& ghostBits) {
  double lost = 0.0;
  // Per lane k, the masks of voxels k and k + 4 as bits, read out of the vectors once at the
  // end: change, active, ghost of voxel k in bits 0–2, of voxel k + 4 in bits 3–5.
  Mask4 flags{};
  for (int half = 0; half < 2; ++half) {
    Float4 stored4;
    std::memcpy(&stored4, values + 4 * half, sizeof stored4);
    Double4 p;
    std::memcpy(&p, psi + 4 * half, sizeof p);
    const Double4 old = __builtin_convertvector(stored4, Double4);
    const Double4 uOld = w.sign * old;
    const Mask4 open = uOld > -w.band;
    const Mask4 change = open & (p < uOld - w.noChange);
    const Double4 uNew = p > -w.band ? p : Double4{} - w.band;
    stored4 = __builtin_convertvector(w.sign * (change ? uNew : uOld), Float4);  // unchanged: old exactly
    std::memcpy(values + 4 * half, &stored4, sizeof stored4);
    const Double4 value = __builtin_convertvector(stored4, Double4);
    Double4 before = 0.5 - old * w.inverseVoxel, after = 0.5 - value * w.inverseVoxel;
    before = before < 0.0 ? Double4{} : before > 1.0 ? Double4{} + 1.0 : before;
    after = after < 0.0 ? Double4{} : after > 1.0 ? Double4{} + 1.0 : after;
    const Double4 lost4 = before - after;
    lost += (lost4[0] + lost4[1]) + (lost4[2] + lost4[3]);
    // Active: within the band as stored. (A distance just inside the band can round to the
    // band's float; a voxel at the band is as inactive as the tiles it borders, whichever
    // route wrote it: a filled leaf or a pruned one holds it inactive too.)
    const Mask4 active = (value < w.band) & (value > -w.band);
    const Double4 distance = p < 0.0 ? -p : p;
    const Mask4 ghost = open & (distance < w.voxel) & (value > w.notMaterial) & (value < w.ghostCeiling);
    flags |= ((change & 1) | (active & 2) | (ghost & 4)) << (3 * half);
  }
  int changedBits = 0, newActive = 0, newGhost = 0;
  for (int k = 0; k < 4; ++k) {
    const int f = static_cast<int>(flags[k]);
    changedBits |= ((f & 1) << k) | (((f >> 3) & 1) << (k + 4));
    newActive |= (((f >> 1) & 1) << k) | (((f >> 4) & 1) << (k + 4));
    newGhost |= (((f >> 2) & 1) << k) | (((f >> 5) & 1) << (k + 4));
  }
  activeBits = static_cast<std::uint8_t>((activeBits & ~changedBits) | (newActive & changedBits));
  ghostBits = static_cast<std::uint8_t>(newGhost);
  return lost;
}

}  // namespace lathesim::sim
