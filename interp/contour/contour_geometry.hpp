#pragma once
// Geometry on finishing contours shared by the compound cycles (G71/G72 roughing, G73 pattern
// repeating): translating a contour by the finishing allowance, exchanging its axes, and
// where a segment meets a line of constant X. Positions are (radius mm, Z mm); angles are
// measured in the drawing view (Z to the right, X up), counter-clockwise positive, so an
// ArcCCW sweeps a growing angle.

#include <vector>

#include "geometry/rz.hpp"
#include "interp/contour/contour.hpp"

namespace lathesim::interp {

/// The contour moved rigidly by `offsetMm` (radius, Z): every end point and arc centre is
/// shifted, arcs keep their radius. This is the rough contour of G71–G73: the finishing
/// contour translated by (Δu/2, Δw).
Contour translatedContour(const Contour& contour, const RZ& offsetMm);

/// The point with its two coordinates exchanged: (a, b) → (b, a).
RZ swappedAxes(const RZ& point);

/// ArcCW ↔ ArcCCW; other kinds unchanged.
MoveKind mirroredKind(MoveKind kind);

/// Segments or cycle legs (anything with kind, from, to and center) mirrored about the
/// X = Z diagonal: coordinates exchanged, ArcCW and ArcCCW exchanged (a mirror reverses the
/// sense of rotation). Applying it twice gives the original.
template <class Pieces>
Pieces swappedAxes(Pieces pieces) {
  for (auto& piece : pieces) {
    piece.kind = mirroredKind(piece.kind);
    piece.from = swappedAxes(piece.from);
    piece.to = swappedAxes(piece.to);
    piece.center = swappedAxes(piece.center);
  }
  return pieces;
}

/// Angle (rad) of `point` seen from `center`: atan2(ΔX, ΔZ).
double angleAround(const RZ& center, const RZ& point);

/// How far an arc turns from its start to its end, in (0, 2π] rad; from == to is a full turn.
double arcSweepRad(const ContourSegment& arc);

/// How far the arc turns from its start to `point` (a point on its circle), in [0, 2π) rad.
double arcTravelRad(const ContourSegment& arc, const RZ& point);

/// The point of the arc's circle in direction `angleRad` from its centre.
RZ arcPointAt(const ContourSegment& arc, double angleRad);

/// The segment run backwards: ends exchanged, ArcCW ↔ ArcCCW.
ContourSegment reversed(const ContourSegment& segment);

/// True when the arc passes through the direction `angleRad` strictly between its ends,
/// e.g. π/2 for its highest X: then X reverses inside the arc.
bool arcPassesAngleInside(const ContourSegment& arc, double angleRad);

/// The points where the segment (straight or arc) meets the line X = `xMm`, in order along
/// the segment. A straight segment lying on the line gives its two ends.
std::vector<RZ> levelCrossings(const ContourSegment& segment, double xMm);

}  // namespace lathesim::interp
