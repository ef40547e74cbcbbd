#pragma once
// Where a turning write can change the stock, from what earlier writes already removed.
//
// Every removal writes u ← min(u, ψ) with u = −φ clamped to the band [−bg, bg], and nothing
// ever lowers φ again (later cuts, ghost clearing and part-off only raise it). So after a
// convex piece P has been written, every voxel keeps u ≤ max(ψ_P, −bg) (to the writer's
// no-change slack), whatever is written later. A new piece N then changes a voxel q only
// where ψ_N(q) < max(ψ_P(q), −bg): outside N, the nearest point of N lies outside P; inside
// N, a point of N \ P lies nearer to q than P's boundary does, or q lies deeper in P than the
// band and nothing changes. Either way q lies within the band of N \ P. Within one write, the
// piece that sets q's new value first (in order) is nearer than every earlier piece, so each
// piece may be measured against any piece written before it, in this write or an earlier one.
//
// A CAM finishing contour moves the tool by hundredths of a millimetre a block: each move's
// hull differs from the last one's by a thin sliver at the leading edge, while its whole
// outline (flanks resting on the surface just cut) lies in the band. Writing only near the
// slivers makes a move cost what it changes, with the same result as writing the whole hull.

#include <deque>
#include <optional>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "geometry/revolved_region.hpp"

namespace lathesim::sim {

class CutHistory {
 public:
  /// The convex pieces outside which writing `pieces` (one revolved write, in order) can
  /// change nothing beyond the band (see above); nullopt when that cannot be bounded (a piece
  /// reaching across the axis: its mirror image revolves with it). Remembers `pieces` as
  /// written: call it only for pieces that are then written whole.
  std::optional<RevolvedRegion> changesOf(const std::vector<ConvexPolygon>& pieces);

 private:
  // The last pieces written, newest last: each new piece is measured against the one that
  // leaves the least of it (the previous move's, or the same stretch one pass before).
  static constexpr std::size_t kRemembered = 8;
  std::deque<ConvexPolygon> written_;
};

}  // namespace lathesim::sim
