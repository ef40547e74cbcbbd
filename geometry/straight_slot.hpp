#pragma once
// The region a cut made with the spindle stopped removes: the tool outline, as thick as the
// insert, swept straight through the part in the plane of the tool — a slot, not a ring.
// Frames as in helical_sweep.hpp: with the spindle at θ (about +Z) the tool's plane is the
// part's half-plane at azimuth −θ; its outline extends ±thickness/2 across that plane.
// The slot is the convex prism H × [−t/2, t/2], H the outline swept in its plane from `from`
// to `to` (conv of the outline at both ends), so its signed distance is exact: with d the 2D
// distance to H in the tool's plane and e = |across| − t/2, √(d² + e²) outside both, max(d, e)
// otherwise.

#include "geometry/convex_polygon.hpp"
#include "geometry/revolved_region.hpp"

namespace lathesim {

class StraightSlot {
 public:
  /// `outline` relative to the programmed point (mm, [radial, axial]), which moves from `from`
  /// to `to` with the spindle standing at `spindleDeg` (about +Z); `thicknessMm` > 0.
  StraightSlot(const ConvexPolygon& outline, const RZ& from, const RZ& to, double thicknessMm, double spindleDeg);

  static constexpr int kColumn = RevolvedRegion::kColumn;

  /// Signed distance (mm) at (x, y, z) in the part's frame; beyond `cap` as ±cap or further.
  double signedDistance(double x, double y, double z, double cap) const;
  void signedDistanceColumn(double x, double y, double z0, double dz, double cap, double (&out)[kColumn]) const;

  /// The section widened by ±t/2 along r and revolved: it contains the slot (a point across
  /// the plane lies no farther from the axis than |in-plane r| + t/2).
  const RevolvedRegion& hull() const { return hull_; }

 private:
  RevolvedRegion section_;  // H, as one planar piece
  double halfThickness_;
  double cosine_, sine_;    // of the tool plane's azimuth
  RevolvedRegion hull_;
};

}  // namespace lathesim
