#pragma once
// The region one thread pass removes: the tool outline carried along a straight line while
// the part turns (../shared/notes/sweep-math.md, "Helical sweeps"). Not a solid of revolution,
// so a point's distance depends on its angle around the axis as well as on (ρ, z).
//
// Frames: the part's frame is the stock's (x, y, z), fixed to the spindle at its zero angle.
// The tool stands in the half-plane y = 0, x ≥ 0 of the machine; when the spindle has turned
// θ about +Z, that half-plane is the part's azimuth φ = −θ. So while the programmed point
// moves P(u) = from + u·(to − from), u ∈ [0, 1], the spindle turns θ(u) = θ₀ + s·360°·n·u
// (n revolutions, s = +1 for M03, −1 for M04), and a point at azimuth φ meets the tool only
// where θ(u) ≡ −φ: at u_k, one per revolution along the pass. Its distance to the swept
// region is taken as the 2D meridian distance from (ρ, z) to the outline placed at the one to
// three P(u_k) near it — exact on the surface, and within the lead angle's cosine elsewhere —
// or to the outline at either end of the pass, where the groove stops (measured in 3D: the
// outline lies in the half-plane of its end's azimuth); inside, no deeper than either end.

#include <utility>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "geometry/revolved_region.hpp"

namespace lathesim {

class HelicalSweep {
 public:
  /// `outline` is the tool's cutter relative to its programmed point (mm, [radial, axial]),
  /// which goes from `from` to `to` while the spindle makes `revolutions` (> 0) turns from
  /// `startSpindleDeg` (about +Z) in the sense `sense` (+1 or −1).
  HelicalSweep(const ConvexPolygon& outline, const RZ& from, const RZ& to, double revolutions,
               double startSpindleDeg, int sense);

  static constexpr int kColumn = RevolvedRegion::kColumn;

  /// Signed distance (mm) at (x, y, z) in the part's frame, negative inside; values beyond
  /// `cap` in size are returned as ±cap or further (as RevolvedRegion::signedDistance).
  double signedDistance(double x, double y, double z, double cap) const;
  /// The same at (x, y, z0 + k·dz), k = 0…kColumn−1.
  void signedDistanceColumn(double x, double y, double z0, double dz, double cap, double (&out)[kColumn]) const;

  /// A bound on how fast signedDistance changes per mm travelled anywhere at distance ≥
  /// `rhoMinMm` from the axis: √(1 + (|dP/dφ| / ρ)²), the in-plane slope 1 and the helix
  /// carrying the outline |dP/dφ| = |to − from|/(2πn) per radian. Infinite near the axis.
  double lipschitzAt(double rhoMinMm) const;

  /// The outline swept straight from `from` to `to` and revolved: it contains the helical
  /// sweep, so its distance is a lower bound of this one's, and its bounds bound it.
  const RevolvedRegion& hull() const { return hull_; }

  /// The helix: the programmed point at u ∈ [0, 1] stands at from() + u·direction(), at the
  /// part's azimuth startAzimuthRad() + u·radiansPerUnit() (see the frames above).
  const RZ& from() const { return from_; }
  const RZ& direction() const { return direction_; }
  double revolutions() const { return revolutions_; }
  double startAzimuthRad() const { return phi0_; }
  double radiansPerUnit() const { return omega_; }

 private:
  double azimuthAt(double u) const { return phi0_ + omega_ * u; }  // radians
  // Lowers out[k] by the outline placed at each P(u_k) for the point's azimuth φ, with u_k in
  // [uLo, uHi]; then by the two ends.
  void candidatesInto(double rho, double phi, double z0, double dz, int count, double cap, double* out) const;
  std::pair<double, double> axialExtentIn(double a, double b) const;

  RevolvedRegion outline_;  // the cutter alone, as one planar piece
  struct Edge {              // an edge of it, from its lower-radius end
    double rLow, rHigh, zAtLow, dzPerDr, zOther;  // zOther: the other end's z (for an edge along Z)
  };
  std::vector<Edge> edges_;
  std::vector<RZ> vertices_;  // its vertices, counter-clockwise
  RZ from_;
  RZ direction_;            // to − from
  double inverseLengthSquared_;
  double revolutions_;
  double phi0_;             // the part's azimuth of the tool at u = 0 (radians)
  double omega_;            // dφ/du (radians)
  double alongReach_;       // the outline's largest extent along the direction of travel (mm)
  double lowestRadius_ = 0; // the least radius the outline reaches along the pass
  double inverseLength_ = 0, inverseOmega_ = 0, inverseDirectionZ_ = 0;
  RevolvedRegion hull_;
};

}  // namespace lathesim
