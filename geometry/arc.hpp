#pragma once
// Circular arcs of the (r, z) half-plane: what G02/G03 cut, and how to follow one with
// straight chords to a stated accuracy.

#include <vector>

#include "geometry/rz.hpp"

namespace lathesim {

/// An arc from `start` to `end` about `center`, turning clockwise or counter-clockwise as
/// seen in the drawing view: Z to the right, radius up (so "clockwise" is G02 whichever
/// side of the spindle the turret is on). start == end is a full circle.
///
/// The end may lie slightly off the start's circle (a control accepts a small mismatch):
/// the radius then changes linearly with the swept angle, so the curve still runs exactly
/// from start to end.
class Arc {
 public:
  Arc(const RZ& start, const RZ& end, const RZ& center, bool clockwise);

  const RZ& start() const { return start_; }
  const RZ& end() const { return end_; }
  const RZ& center() const { return center_; }
  bool clockwise() const { return clockwise_; }

  double startRadiusMm() const { return (start_ - center_).norm(); }
  double endRadiusMm() const { return (end_ - center_).norm(); }

  /// The angle swept, radians, in (0, 2π]: 2π when start == end.
  double sweepRad() const;

  /// The length of the path, mm (for a true circle, radius × sweep).
  double lengthMm() const;

  /// The point a fraction t ∈ [0, 1] of the sweep along: start at 0, end at 1.
  RZ pointAt(double t) const;

  /// The sagitta: the largest distance of the arc from its chord's line, mm,
  /// R·(1 − cos(sweep/2)) with R the larger of the start and end radii.
  double sagittaMm() const;

  /// The arc cut into equal sub-arcs, in order, each sweeping at most 180° and deviating
  /// from its chord by at most `maxSagittaMm` (> 0). Their chords form a polyline from
  /// start to end that lies within maxSagittaMm of the arc.
  std::vector<Arc> split(double maxSagittaMm) const;

 private:
  double angleOf(const RZ& p) const;  // drawing-view angle of p about the centre, radians

  RZ start_;
  RZ end_;
  RZ center_;
  bool clockwise_;
};

}  // namespace lathesim
