// The one voxel write: see column_write.hpp.

#include "sim/column_write.hpp"

#include <immintrin.h>

#include <cstring>

namespace lathesim::sim {
namespace {

// Four lanes at a time in GCC vector types (one AVX2 register in the AVX2 clone, two SSE2 ones
// elsewhere).
using Double4 = double __attribute__((vector_size(32)));
using Float4 = float __attribute__((vector_size(16)));
using Int4 = std::int32_t __attribute__((vector_size(16)));    // float lanes' masks: −1 (true) or 0
using Mask4 = std::int64_t __attribute__((vector_size(32)));  // double lanes' masks

// A mask's lanes as four bits (lane k in bit k): one movmskps, in either clone.
[[gnu::always_inline]] inline int bitsOf(Int4 mask) { return _mm_movemask_ps(reinterpret_cast<__m128>(mask)); }
[[gnu::always_inline]] inline int bitsOf(const Mask4& mask) { return bitsOf(__builtin_convertvector(mask, Int4)); }

}  // namespace

// u ← min(u, ψ) over one column of eight voxels (values[0…7], along Z), four at a time,
// without branches. The band and the ghost bounds are floats, so a stored value is compared
// with them as a float: the same verdict as in double, without widening it first.
__attribute__((target_clones("avx2", "default"))) double writeColumn(const ColumnWrite& w, float* values,
                                                                     const double* psi, std::uint8_t& activeBits,
                                                                     std::uint8_t& ghostBits) {
  const float band = static_cast<float>(w.band);  // exact: of() takes a float
  double lost = 0.0;
  int changedBits = 0, newActive = 0, newGhost = 0;
  for (int half = 0; half < 2; ++half) {
    Float4 old4;
    std::memcpy(&old4, values + 4 * half, sizeof old4);
    Double4 p;
    std::memcpy(&p, psi + 4 * half, sizeof p);
    const Double4 old = __builtin_convertvector(old4, Double4);
    const Double4 uOld = w.sign * old;
    const Mask4 open = uOld > -w.band;
    const Mask4 change = open & (p < uOld - w.noChange);
    const Double4 uNew = p > -w.band ? p : Double4{} - w.band;
    const Float4 stored4 = __builtin_convertvector(w.sign * (change ? uNew : uOld), Float4);  // unchanged: old exactly
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
    const Int4 active = (stored4 < band) & (stored4 > -band);
    const Double4 distance = p < 0.0 ? -p : p;
    const Int4 ghost = __builtin_convertvector(open & (distance < w.voxel), Int4) & (stored4 > w.notMaterial) &
                       (stored4 < w.ghostCeiling);
    changedBits |= bitsOf(change) << (4 * half);
    newActive |= bitsOf(active) << (4 * half);
    newGhost |= bitsOf(ghost) << (4 * half);
  }
  activeBits = static_cast<std::uint8_t>((activeBits & ~changedBits) | (newActive & changedBits));
  ghostBits = static_cast<std::uint8_t>(newGhost);
  return lost;
}

}  // namespace lathesim::sim
