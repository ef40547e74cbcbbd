#pragma once
// Where a thread pass can change the stock, from the thread passes written before it: the
// helical counterpart of cut_history.hpp.
//
// A thread pass's distance ψ at a point of azimuth φ is the meridian distance to its outline
// placed at the programmed point's positions p₀(φ) + k·λ, one per turn (λ the lead vector,
// helical_sweep.hpp), bar the pass's two ends. Two passes of one helix — the same tool, hand
// and lead vector, as a G76's or a G92's successive passes are — place their outlines, at every
// azimuth, one a fixed offset Δ from the other: C_k = D_k + Δ. Every removal writes u ← min(u, ψ)
// (u = −φ clamped to the band [−bg, bg]) and nothing lowers φ again, so after pass P every voxel
// keeps u ≤ max(ψ_P, −bg). In each meridian section the argument of cut_history.hpp then holds
// placement by placement: pass N changes a voxel q only where ψ_N(q) < max(ψ_P(q), −bg), and
// then q lies within the band of some C_k \ D_k — within bg of the sliver O \ (O − Δ) (O the
// outline) carried along N's own helix. Outside N's placements that have no partner in P (where
// P's stretch ends) and near either pass's ends (whose faces are measured in 3D) the argument does
// not hold: there the pass is written whole.
//
// A G76 pass cuts on its leading flank only, its trailing flank sliding along the flank the last
// pass left, and a spring pass (the same depth again) cuts nothing: written this way, a pass
// costs the sliver it removes rather than its whole groove, with the same result voxel for voxel.

#include <deque>
#include <optional>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "geometry/helical_sweep.hpp"
#include "geometry/revolved_region.hpp"

namespace lathesim::sim {

/// One thread move as it is swept: `outline` from `from` to `to` over `revolutions` turns from
/// the spindle angle `startSpindleDeg` in the sense `sense` (the HelicalSweep's arguments).
struct ThreadPass {
  ConvexPolygon outline;
  RZ from, to;
  double revolutions = 0;
  double startSpindleDeg = 0;
  int sense = 1;

  HelicalSweep sweep() const { return HelicalSweep(outline, from, to, revolutions, startSpindleDeg, sense); }
};

/// Where writing a thread pass can change anything: near the slivers its outline adds to an
/// earlier pass's along its helix, and near the zones where it is written whole.
class ThreadChangeBound {
 public:
  ThreadChangeBound(std::vector<HelicalSweep> slivers, std::vector<ConvexPolygon> zones,
                    const std::vector<ConvexPolygon>& extent);

  /// Whether a voxel within `spreadMm` of (x, y, z) (mm, the part's frame) can lie within
  /// `bandMm` of a sliver or a zone: measured at (x, y, z) with each sliver's slope, so that no
  /// such voxel is missed.
  bool mayChange(double x, double y, double z, double spreadMm, double bandMm) const;

  /// Revolved pieces that hold every sliver and zone: what bounds the blocks to look at.
  const RevolvedRegion& extent() const { return extent_; }

 private:
  std::vector<HelicalSweep> slivers_;
  RevolvedRegion zones_;
  RevolvedRegion extent_;
};

class ThreadHistory {
 public:
  /// Where writing `pass` can change the stock beyond what the thread passes remembered
  /// already wrote (see above), or nullopt when no remembered pass shares its helix (write
  /// it whole). Remembers `pass` as written: call it only for passes that are then written.
  std::optional<ThreadChangeBound> changesOf(const ThreadPass& pass);

 private:
  // The last passes written, newest last: a G76 alternates its passes' threads and run-outs.
  static constexpr std::size_t kRemembered = 8;
  std::deque<ThreadPass> written_;
};

}  // namespace lathesim::sim
