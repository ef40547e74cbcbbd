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

#include "interp/output/toolpath_csv.hpp"

namespace lathesim::interp {
namespace {

// Drawing-view coordinates of a point: (Z, radius), Z the horizontal axis.
Eigen::Vector2d drawing(const RZ& p) { return {p.y(), p.x()}; }
RZ fromDrawing(const Eigen::Vector2d& q) { return RZ(q.y(), q.x()); }

// The centre at `radiusMm` from both ends of the chord start → end, on the side of the chord
// nearer to `near` (radius at least half the chord, else the chord's midpoint).
RZ centreOnBisector(const RZ& start, const RZ& end, double radiusMm, const RZ& near) {
  const Eigen::Vector2d s = drawing(start);
  const Eigen::Vector2d e = drawing(end);
  const Eigen::Vector2d middle = 0.5 * (s + e);
  const double half = (e - s).norm() / 2;
  const Eigen::Vector2d along = (e - s).normalized();
  const Eigen::Vector2d normal(-along.y(), along.x());
  const double offset = std::sqrt(std::max(0.0, radiusMm * radiusMm - half * half));
  const Eigen::Vector2d a = middle + offset * normal;
  const Eigen::Vector2d b = middle - offset * normal;
  const Eigen::Vector2d n = drawing(near);
  return fromDrawing((a - n).norm() <= (b - n).norm() ? a : b);
}

Result<ArcCentre> centreFromRadius(const ArcRequest& request, const ArcWord& r) {
  const Eigen::Vector2d s = drawing(request.start);
  const Eigen::Vector2d e = drawing(request.end);
  const double chordMm = (e - s).norm();
  if (chordMm == 0) {
    return ArcCentre{std::nullopt,
                     {Error{request.line, r.column,
                            fmt::format("{} {} ends where it starts: the control makes a 0° arc, no move (a full "
                                        "circle needs I and K, GSK980TDi §3.4 note 4)",
                                        request.code, r.text)}}};
  }
  const double halfChordMm = chordMm / 2;
  if (std::abs(r.mm) < halfChordMm - request.radiusToleranceMm) {
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
  return ArcCentre{fromDrawing(centre), {}};
}

Result<ArcCentre> centreFromOffset(const ArcRequest& request) {
  const RZ offset(request.i ? request.i->mm : 0.0, request.k ? request.k->mm : 0.0);
  const RZ centre = request.start + offset;
  const double startRadiusMm = offset.norm();
  const double endRadiusMm = (request.end - centre).norm();
  const double chordMm = (request.end - request.start).norm();
  if (startRadiusMm == 0) {
    const ArcWord& first = request.i && (!request.k || request.i->column < request.k->column)
                               ? *request.i
                               : *request.k;
    return Error{request.line, first.column,
                 "I and K put the centre on the start point, so the arc has no radius: I (a "
                 "radius) and K go from the start point to the centre"};
  }
  const double offCircleMm = std::abs(endRadiusMm - startRadiusMm);
  const bool alarms = request.endOffCircle == ArcEndOffCircle::Alarm;
  if (offCircleMm > request.radiusToleranceMm && (alarms || chordMm > 2 * startRadiusMm + request.radiusToleranceMm)) {
    return Error{request.line, request.column,
                 fmt::format("the end point X{} Z{} is not on the arc: it is {} mm from the "
                             "centre X{} Z{}, the start point {} mm; {} (check X/Z and I/K; I is a radius)",
                             csvNumber(diameterOf(request.end)), csvNumber(request.end.y()),
                             csvNumber(endRadiusMm), csvNumber(diameterOf(centre)),
                             csvNumber(centre.y()), csvNumber(startRadiusMm),
                             alarms ? fmt::format("they may differ by at most {} mm", request.radiusToleranceMm)
                                    : fmt::format("the end lies {} mm from the start, farther than the arc's "
                                                  "diameter {}",
                                                  csvNumber(chordMm), csvNumber(2 * startRadiusMm)))};
  }
  // A full circle, or both ends on the circle already: the centre as given.
  if (chordMm == 0 || offCircleMm <= 1e-12 * std::max(1.0, startRadiusMm)) return ArcCentre{centre, {}};
  const RZ moved = centreOnBisector(request.start, request.end, startRadiusMm, centre);
  ArcCentre outcome{moved, {}};
  if (offCircleMm > request.radiusToleranceMm) {
    outcome.warnings.push_back(
        {request.line, request.column,
         fmt::format("the end point X{} Z{} is {} mm off the circle I and K give: the control keeps the radius {} "
                     "and moves the centre to X{} Z{} so that the arc ends there (GSK980TDi §3.4 note 6)",
                     csvNumber(diameterOf(request.end)), csvNumber(request.end.y()), csvNumber(offCircleMm),
                     csvNumber(startRadiusMm), csvNumber(diameterOf(moved)), csvNumber(moved.y()))});
  }
  return outcome;
}

}  // namespace

Result<ArcCentre> arcCentre(const ArcRequest& request) {
  const std::optional<ArcWord>& offsetWord = request.i ? request.i : request.k;
  if (request.r && offsetWord) {
    auto outcome = centreFromRadius(request, *request.r);
    if (outcome.ok()) {
      outcome.value().warnings.insert(
          outcome.value().warnings.begin(),
          Error{request.line, offsetWord->column,
                fmt::format("{} is ignored: {} gives the arc's radius (R wins over I and K, GSK980TDi §3.4 note 2)",
                            offsetWord->text, request.r->text)});
    }
    return outcome;
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
