#pragma once
// A turned part's section in the meridian half-plane (r ≥ 0, z): the region, its surface
// as segments, and the signed distance to that surface. Both sides of a drawing check are
// one of these: the drawing (a polygon closed via the axis) and the simulated part (the
// zero crossings of its level set sampled in the plane y = 0, joined by marching squares).
//
// The axis is not a surface: edges lying on r = 0 close the region but are left out of
// `surface()`, so a point near the axis is measured to the real faces, not to the axis.

#include <optional>
#include <vector>

#include "geometry/rz.hpp"

namespace lathesim {

/// Signed distances φ (mm, negative inside the material) sampled on a square grid of the
/// meridian plane: sample (i, k) sits at r = i·stepMm, z = zFirstMm + k·stepMm. Values far
/// from the surface may be clamped (a narrow band); only their sign is used there.
struct SampledSection {
  double stepMm = 0;
  double zFirstMm = 0;
  int rCount = 0;
  int zCount = 0;
  double clampMm = 0;      // |φ| is clamped at this (the narrow band); nearer values are distances
  std::vector<float> phi;  // rCount·zCount values, i fastest
  float at(int i, int k) const { return phi[static_cast<std::size_t>(k) * rCount + i]; }
};

struct Segment {
  RZ a, b;
};

/// The nearest surface point and the signed distance to it (negative inside the region).
struct SurfaceDistance {
  double signedMm = 0;
  RZ nearest{0, 0};
};

class MeridianProfile {
 public:
  /// A simple polygon (any orientation). If it ends where it starts it is closed as given (a
  /// bored part, whose section does not reach the axis); otherwise, if it starts or ends off
  /// the axis, it is closed via the axis: (0, z of the first point) before it and (0, z of
  /// the last point) after it.
  static MeridianProfile fromPolygon(std::vector<RZ> points);

  /// The region bounded by `surface` (and the axis), e.g. a mesh's meridianSlice: a point
  /// is inside when a ray from it away from the axis crosses the surface an odd number of times.
  static MeridianProfile fromSurface(std::vector<Segment> surface);

  /// The region φ < 0 of a sampled section; inside/outside between samples by bilinear
  /// interpolation, the surface by marching squares over the linear zero crossings.
  static MeridianProfile fromSection(SampledSection section);

  const std::vector<Segment>& surface() const { return surface_; }

  /// True for a section: only the surface's vertices lie on the true surface; the chords
  /// between them cut its corners.
  bool fromSamples() const { return section_.has_value(); }

  bool contains(const RZ& p) const;

  /// Distance to the surface, negative when p is inside the region. With no surface at all
  /// the distance is +∞ (outside) or −∞. For a section, where the four samples around p are
  /// all inside the band, the distance is φ interpolated there: exact on flat faces, and
  /// within about h/4 at a sharp convex corner that the marching-squares polyline would cut
  /// off by up to h/√2. Elsewhere it is the distance to that polyline, whose vertices lie on
  /// the surface.
  SurfaceDistance signedDistance(const RZ& p) const;

  /// Where the surface lies: componentwise bounds of its segments.
  RZ lowerBound() const { return lower_; }
  RZ upperBound() const { return upper_; }

 private:
  MeridianProfile() = default;
  void indexSurface();
  std::optional<double> interpolatedPhi(const RZ& p, bool withinBandOnly) const;

  std::optional<SampledSection> section_;  // fromSection: the samples
  std::vector<Segment> surface_;
  RZ lower_{0, 0}, upper_{0, 0};
  // Uniform bins over the surface's bounds, each listing the segments that cross it.
  double binMm_ = 1.0;
  int binsR_ = 0, binsZ_ = 0;
  std::vector<std::vector<int>> bins_;
};

}  // namespace lathesim
