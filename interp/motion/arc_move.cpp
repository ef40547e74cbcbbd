// G02/G03 centre from R or I/K (see arc_move.hpp).
//
// R form: with d the chord from start S to end E and M its midpoint, the centre lies on the
// chord's perpendicular bisector at h = √(R² − (d/2)²) from M. Looking along S → E in the
// drawing view (Z right, X up), a clockwise arc of at most 180° has its centre on the right,
// a counter-clockwise one on the left; R < 0 asks for the other centre (the major arc).

#include "interp/motion/arc_move.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "interp/toolpath_csv.hpp"

namespace lathesim::interp {
namespace {

// Drawing-view coordinates of a point: (Z, radius), Z the horizontal axis.
Eigen::Vector2d drawing(const RZ& p) { return {p.y(), p.x()}; }
RZ fromDrawing(const Eigen::Vector2d& q) { return RZ(q.y(), q.x()); }

Result<RZ> centreFromRadius(const ArcRequest& request, const ArcWord& r) {
  const Eigen::Vector2d s = drawing(request.start);
  const Eigen::Vector2d e = drawing(request.end);
  const double chordMm = (e - s).norm();
  if (chordMm == 0) {
    return Error{request.line, r.column,
                 fmt::format("{} with {} cannot cut a full circle (the end point is the start "
                             "point): give the centre with I and K instead",
                             request.code, r.text)};
  }
  const double halfChordMm = chordMm / 2;
  if (std::abs(r.mm) < halfChordMm - kArcRadiusToleranceMm) {
    return Error{request.line, r.column,
                 fmt::format("{} is too small: the end point is {} mm from the start, so no arc "
                             "of radius {} mm joins them; |R| must be at least {} mm (half that "
                             "distance)",
                             r.text, csvNumber(chordMm), csvNumber(std::abs(r.mm)),
                             csvNumber(halfChordMm))};
  }
  const double offsetMm = std::sqrt(std::max(0.0, r.mm * r.mm - halfChordMm * halfChordMm));
  const Eigen::Vector2d along = (e - s) / chordMm;
  const Eigen::Vector2d right(along.y(), -along.x());
  const bool centreOnRight = request.clockwise == (r.mm > 0);
  const Eigen::Vector2d centre = 0.5 * (s + e) + (centreOnRight ? offsetMm : -offsetMm) * right;
  return fromDrawing(centre);
}

Result<RZ> centreFromOffset(const ArcRequest& request) {
  const RZ offset(request.i ? request.i->mm : 0.0, request.k ? request.k->mm : 0.0);
  const RZ centre = request.start + offset;
  const double startRadiusMm = offset.norm();
  const double endRadiusMm = (request.end - centre).norm();
  if (startRadiusMm == 0) {
    const ArcWord& first = request.i && (!request.k || request.i->column < request.k->column)
                               ? *request.i
                               : *request.k;
    return Error{request.line, first.column,
                 "I and K put the centre on the start point, so the arc has no radius: I (a "
                 "radius) and K go from the start point to the centre"};
  }
  if (std::abs(endRadiusMm - startRadiusMm) > kArcRadiusToleranceMm) {
    return Error{request.line, request.column,
                 fmt::format("the end point X{} Z{} is not on the arc: it is {} mm from the "
                             "centre X{} Z{}, the start point {} mm; they may differ by at most "
                             "{} mm (check X/Z and I/K; I is a radius)",
                             csvNumber(diameterOf(request.end)), csvNumber(request.end.y()),
                             csvNumber(endRadiusMm), csvNumber(diameterOf(centre)),
                             csvNumber(centre.y()), csvNumber(startRadiusMm),
                             kArcRadiusToleranceMm)};
  }
  return centre;
}

}  // namespace

Result<RZ> arcCentre(const ArcRequest& request) {
  const std::optional<ArcWord>& offsetWord = request.i ? request.i : request.k;
  if (request.r && offsetWord) {
    return Error{request.line, std::max(request.r->column, offsetWord->column),
                 fmt::format("{} takes the centre as R or as I/K, not both: {} and {} are both "
                             "given",
                             request.code, request.r->text, offsetWord->text)};
  }
  if (request.r) return centreFromRadius(request, *request.r);
  if (offsetWord) return centreFromOffset(request);
  return Error{request.line, request.column,
               fmt::format("{} needs the arc's centre: give R (the radius, negative for more "
                           "than 180°) or I and K (from the start point to the centre, I a "
                           "radius)",
                           request.code)};
}

}  // namespace lathesim::interp
