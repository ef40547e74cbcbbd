// Tool nose radius compensation; the rules and the moves it makes are in
// nose_compensation.hpp. Geometry is in the drawing view: Z to the right, X (radius) up, so
// "turning left" is counter-clockwise. Points are RZ = (radius, Z).

#include "geometry/imaginary_tip.hpp"
#include "interp/compensation/nose_compensation.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "interp/base/tolerance.hpp"
#include "interp/contour/contour_geometry.hpp"
#include "interp/compensation/tool_offset.hpp"

namespace lathesim::interp {
namespace {

constexpr double kTurnTol = 1e-9;  // |sin| of a corner angle below which the path goes straight on

/// A segment of the output path and the input segment it comes from.
struct Piece {
  ContourSegment segment;
  std::size_t source = 0;
};

/// `v` turned 90° counter-clockwise in the drawing view: +Z becomes +X.
RZ turnedLeft(const RZ& v) { return RZ(v.y(), -v.x()); }

/// > 0 when `b` turns counter-clockwise (left) from `a`.
double crossOf(const RZ& a, const RZ& b) { return a.y() * b.x() - a.x() * b.y(); }

/// The unit direction of travel of `segment` at `point` (a point of it).
RZ tangentAt(const ContourSegment& segment, const RZ& point) {
  if (!isArc(segment.kind)) return (segment.to - segment.from).normalized();
  const RZ radial = (point - segment.center).normalized();
  return segment.kind == MoveKind::ArcCCW ? turnedLeft(radial) : RZ(-turnedLeft(radial));
}

double sideSign(NoseSide side) { return side == NoseSide::Left ? 1.0 : -1.0; }

const char* sideCode(NoseSide side) { return side == NoseSide::Left ? "G41" : "G42"; }

const char* kindCode(MoveKind kind) { return kind == MoveKind::ArcCW ? "G02" : "G03"; }

Error errorAt(const ContourSegment& segment, std::string message) {
  return Error{segment.line, segment.column, std::move(message)};
}

/// One compensated segment's nose-centre path: the programmed segment offset by R.
struct Curve {
  ContourSegment offset;     // from/to trimmed or extended at the corners
  RZ untrimmedFrom{0, 0};    // the offset ends before the corners were joined
  RZ untrimmedTo{0, 0};
  double radiusMm = 0;       // arcs: the offset radius
  std::size_t source = 0;
  std::vector<ContourSegment> cornerAfter;  // straight moves joining it to the next curve
};

Result<Curve> offsetCurve(const ContourSegment& segment, std::size_t source, double sign,
                          double radiusMm) {
  Curve curve;
  curve.offset = segment;
  curve.source = source;
  const auto shifted = [&](const RZ& point) {
    return RZ(point + sign * radiusMm * turnedLeft(tangentAt(segment, point)));
  };
  curve.offset.from = shifted(segment.from);
  curve.offset.to = shifted(segment.to);
  if (isArc(segment.kind)) {
    const double programmed = (segment.from - segment.center).norm();
    curve.radiusMm = (curve.offset.from - segment.center).norm();
    // The left normal of a CCW arc points at its centre, of a CW arc away from it.
    const double expected =
        programmed + (segment.kind == MoveKind::ArcCCW ? -sign : sign) * radiusMm;
    if (expected <= kTolMm) {
      return errorAt(segment, fmt::format(
          "interference: this {} arc's radius {:g} is not larger than the nose radius {:g} on "
          "the side the tool is; the nose cannot follow it (Fanuc alarm PS0041)",
          kindCode(segment.kind), programmed, radiusMm));
    }
  }
  curve.untrimmedFrom = curve.offset.from;
  curve.untrimmedTo = curve.offset.to;
  return curve;
}

/// Where the two paths, extended (lines without end, arcs as whole circles), meet.
std::vector<RZ> intersections(const Curve& a, const Curve& b) {
  const bool arcA = isArc(a.offset.kind);
  const bool arcB = isArc(b.offset.kind);
  if (!arcA && !arcB) {
    const RZ da = a.offset.to - a.offset.from;
    const RZ db = b.offset.to - b.offset.from;
    const double denominator = crossOf(da, db);
    if (std::abs(denominator) < kTurnTol * da.norm() * db.norm()) return {};
    const double t = crossOf(b.offset.from - a.offset.from, db) / denominator;
    return {a.offset.from + t * da};
  }
  if (arcA != arcB) {
    const Curve& line = arcA ? b : a;
    const Curve& arc = arcA ? a : b;
    const RZ d = (line.offset.to - line.offset.from).normalized();
    const RZ foot = line.offset.from + d * d.dot(arc.offset.center - line.offset.from);
    const double distance = (foot - arc.offset.center).norm();
    if (distance > arc.radiusMm + kTolMm) return {};
    const double half = std::sqrt(std::max(0.0, arc.radiusMm * arc.radiusMm - distance * distance));
    return {foot - half * d, foot + half * d};
  }
  const RZ c1 = a.offset.center;
  const RZ c2 = b.offset.center;
  const double d = (c2 - c1).norm();
  const double r1 = a.radiusMm;
  const double r2 = b.radiusMm;
  if (d < kTolMm || d > r1 + r2 + kTolMm || d < std::abs(r1 - r2) - kTolMm) return {};
  const double along = (r1 * r1 - r2 * r2 + d * d) / (2 * d);
  const double half = std::sqrt(std::max(0.0, r1 * r1 - along * along));
  const RZ unit = (c2 - c1) / d;
  const RZ base = c1 + along * unit;
  return {base + half * turnedLeft(unit), base - half * turnedLeft(unit)};
}

RZ nearestTo(const std::vector<RZ>& points, const RZ& target) {
  RZ best = points.front();
  for (const RZ& p : points) {
    if ((p - target).norm() < (best - target).norm()) best = p;
  }
  return best;
}

/// Where the lines through `p` along `dp` and through `q` along `dq` meet (not parallel).
RZ lineMeet(const RZ& p, const RZ& dp, const RZ& q, const RZ& dq) {
  return p + crossOf(q - p, dq) / crossOf(dp, dq) * dp;
}

ContourSegment straightPiece(const ContourSegment& like, const RZ& from, const RZ& to) {
  ContourSegment piece = like;
  piece.kind = like.kind == MoveKind::Rapid ? MoveKind::Rapid : MoveKind::Feed;
  piece.from = from;
  piece.to = to;
  piece.center = RZ(0, 0);
  return piece;
}

/// Joins curve `a` to the next curve `b` at the programmed corner `corner` (see the header).
Status joinCorner(Curve& a, Curve& b, const ContourSegment& programmedA,
                  const ContourSegment& programmedB, double sign, double radiusMm) {
  if ((a.offset.to - b.offset.from).norm() < kTolMm) {
    b.offset.from = a.offset.to;
    return success();
  }
  const RZ corner = programmedA.to;
  const RZ t1 = tangentAt(programmedA, programmedA.to);
  const RZ t2 = tangentAt(programmedB, programmedB.from);
  const bool inner = sign * crossOf(t1, t2) > kTurnTol;
  if (inner) {
    const auto meet = intersections(a, b);
    if (meet.empty()) {
      return errorAt(programmedB, fmt::format(
          "nose radius compensation: the nose-centre paths of this block and the one before "
          "it never meet at their inner corner (Fanuc alarm PS0033)"));
    }
    a.offset.to = b.offset.from = nearestTo(meet, corner);
    return success();
  }
  if (t1.dot(t2) >= -kTurnTol) {  // outer, turning by at most 90°
    const auto meet = intersections(a, b);
    if (!meet.empty()) {
      a.offset.to = b.offset.from = nearestTo(meet, corner);
      return success();
    }
    const RZ q = lineMeet(a.offset.to, t1, b.offset.from, t2);
    a.cornerAfter.push_back(straightPiece(programmedA, a.offset.to, q));
    a.cornerAfter.push_back(straightPiece(programmedA, q, b.offset.from));
    return success();
  }
  const RZ q1 = a.offset.to + radiusMm * t1;
  const RZ q2 = b.offset.from - radiusMm * t2;
  a.cornerAfter.push_back(straightPiece(programmedA, a.offset.to, q1));
  a.cornerAfter.push_back(straightPiece(programmedA, q1, q2));
  a.cornerAfter.push_back(straightPiece(programmedA, q2, b.offset.from));
  return success();
}

/// Signed travel (rad) along `arc`'s direction from its start to `point` on its circle,
/// taken in (−π, π] around `reference` (a travel already known to be near).
double travelNear(const ContourSegment& arc, const RZ& point, double reference) {
  double travel = arcTravelRad(arc, point);
  while (travel - reference > std::numbers::pi) travel -= 2 * std::numbers::pi;
  while (travel - reference <= -std::numbers::pi) travel += 2 * std::numbers::pi;
  return travel;
}

/// Interference: the trimmed offset runs against its programmed direction.
Status checkNotReversed(const Curve& curve, const ContourSegment& programmed, double radiusMm) {
  bool reversed = false;
  if (isArc(curve.offset.kind)) {
    ContourSegment untrimmed = curve.offset;
    untrimmed.from = curve.untrimmedFrom;
    untrimmed.to = curve.untrimmedTo;
    const double sweep = arcSweepRad(untrimmed);
    const double start = travelNear(untrimmed, curve.offset.from, 0.0);
    const double end = travelNear(untrimmed, curve.offset.to, sweep);
    reversed = end - start < -kTurnTol;
  } else {
    reversed = (curve.offset.to - curve.offset.from).dot(curve.untrimmedTo - curve.untrimmedFrom) <
               -kTolMm;
  }
  if (!reversed) return success();
  return errorAt(programmed, fmt::format(
      "interference: with the nose radius {:g} the nose-centre path of this block runs "
      "backwards once its corners are joined; the block is too short for the radius "
      "(Fanuc alarm PS0041)",
      radiusMm));
}

bool zeroLengthStraight(const ContourSegment& segment) {
  return !isArc(segment.kind) && (segment.to - segment.from).norm() < kTolMm;
}

/// Walks the path, compensating each chain (see the header).
class PathCompensation {
 public:
  PathCompensation(const std::vector<ContourSegment>& path, const std::vector<NoseComp>& comps)
      : path_(path), comps_(comps) {}

  Result<std::vector<Piece>> run();

 private:
  Status chain(std::size_t first, std::size_t end);
  void push(ContourSegment segment, std::size_t source);
  std::size_t chainEnd(std::size_t first) const;

  const std::vector<ContourSegment>& path_;
  const std::vector<NoseComp>& comps_;  // in force in each segment's block
  std::vector<Piece> out_;
  std::optional<RZ> at_;          // where the tool stands after the last piece
  std::optional<RZ> cancelFrom_;  // the next uncompensated move starts here
};

void PathCompensation::push(ContourSegment segment, std::size_t source) {
  at_ = segment.to;
  out_.push_back({std::move(segment), source});
}

// The index after the chain starting at `first`: of its cancel move, or the path's end.
std::size_t PathCompensation::chainEnd(std::size_t first) const {
  std::size_t end = first + 1;
  while (end < path_.size() &&
         (path_[end].kind == MoveKind::Dwell || comps_[end].side != NoseSide::None)) {
    ++end;
  }
  return end;
}

Result<std::vector<Piece>> PathCompensation::run() {
  std::size_t i = 0;
  while (i < path_.size()) {
    ContourSegment segment = path_[i];
    if (segment.kind == MoveKind::Dwell) {
      if (at_) segment.from = segment.to = *at_;
      push(segment, i++);
      continue;
    }
    if (comps_[i].side == NoseSide::None) {
      if (cancelFrom_) {
        if (isArc(segment.kind)) {
          return errorAt(segment, fmt::format(
              "nose radius compensation cannot be cancelled in an arc block ({}): cancel it "
              "with G40 in a G00 or G01 block (Fanuc alarm PS0034)",
              kindCode(segment.kind)));
        }
        segment.from = *cancelFrom_;
        cancelFrom_.reset();
      }
      push(segment, i++);
      continue;
    }
    const std::size_t end = chainEnd(i);
    if (auto status = chain(i, end); !status.ok()) return status.error();
    i = end;
  }
  return std::move(out_);
}

Status PathCompensation::chain(std::size_t first, std::size_t end) {
  const ContourSegment& startUp = path_[first];
  const NoseComp comp = comps_[first];
  if (isArc(startUp.kind)) {
    return errorAt(startUp, fmt::format(
        "nose radius compensation ({}) cannot start in an arc block ({}): start it in a G00 "
        "or G01 block (Fanuc alarm PS0034)",
        sideCode(comp.side), kindCode(startUp.kind)));
  }
  for (std::size_t i = first + 1; i < end; ++i) {
    const ContourSegment& segment = path_[i];
    if (segment.kind == MoveKind::Dwell || comps_[i] == comp) continue;
    return errorAt(segment, fmt::format(
        "nose radius compensation changes while it is on ({} R{:g} tip {} becomes {} R{:g} tip "
        "{}): cancel it with G40 in a G00/G01 block before changing the side or the offset",
        sideCode(comp.side), comp.radiusMm, comp.tip, sideCode(comps_[i].side),
        comps_[i].radiusMm, comps_[i].tip));
  }
  const double sign = sideSign(comp.side);
  const double radiusMm = comp.radiusMm;
  const RZ tipShift = radiusMm * imaginaryTipDirection(comp.tip);

  std::vector<Curve> curves;
  std::vector<std::size_t> members;  // path index of each curve
  for (std::size_t i = first + 1; i < end; ++i) {
    if (path_[i].kind == MoveKind::Dwell) continue;
    auto curve = offsetCurve(path_[i], i, sign, radiusMm);
    if (!curve.ok()) return curve.error();
    curves.push_back(std::move(curve.value()));
    members.push_back(i);
  }
  for (std::size_t k = 0; k + 1 < curves.size(); ++k) {
    auto status = joinCorner(curves[k], curves[k + 1], path_[members[k]], path_[members[k + 1]],
                             sign, radiusMm);
    if (!status.ok()) return status;
  }
  for (std::size_t k = 0; k < curves.size(); ++k) {
    if (auto status = checkNotReversed(curves[k], path_[members[k]], radiusMm); !status.ok()) {
      return status;
    }
  }

  // Start-up: to the centre perpendicular to the next move at its start (type A).
  const RZ startCentre =
      curves.empty()
          ? RZ(startUp.to + sign * radiusMm * turnedLeft(tangentAt(startUp, startUp.to)))
          : curves.front().offset.from;
  ContourSegment up = startUp;
  up.to = startCentre + tipShift;
  push(up, first);

  std::size_t next = 0;
  for (std::size_t i = first + 1; i < end; ++i) {
    if (path_[i].kind == MoveKind::Dwell) {
      ContourSegment dwell = path_[i];
      dwell.from = dwell.to = *at_;
      push(dwell, i);
      continue;
    }
    const Curve& curve = curves[next++];
    ContourSegment tip = curve.offset;
    tip.from += tipShift;
    tip.to += tipShift;
    if (isArc(tip.kind)) tip.center += tipShift;
    if (!zeroLengthStraight(tip)) push(tip, i);
    for (ContourSegment corner : curve.cornerAfter) {
      corner.from += tipShift;
      corner.to += tipShift;
      if (!zeroLengthStraight(corner)) push(corner, i);
    }
  }
  cancelFrom_ = *at_;
  return success();
}

}  // namespace

namespace {

// What compensation does to a toolpath with no G41/G42 anywhere, done in place (a long CAM
// program rarely compensates, and its moves are the largest thing the interpreter holds):
// a dwell stands where the last move ended, a zero-length straight move is left out.
void passUncompensated(std::vector<Move>& moves) {
  std::optional<RZ> at;
  std::size_t kept = 0;
  for (Move& move : moves) {
    if (move.kind == MoveKind::Dwell && at) move.from = move.to = *at;
    at = move.to;
    const ContourSegment segment{move.kind, move.from, move.to, move.center, move.line, move.column};
    if (zeroLengthStraight(segment) && move.kind != MoveKind::Dwell) continue;
    if (&moves[kept] != &move) moves[kept] = std::move(move);
    ++kept;
  }
  moves.erase(moves.begin() + static_cast<std::ptrdiff_t>(kept), moves.end());
}

}  // namespace

Status compensateNoseRadius(std::vector<Move>& moves) {
  if (std::none_of(moves.begin(), moves.end(), [](const Move& m) { return m.noseComp.side != NoseSide::None; })) {
    passUncompensated(moves);
    return success();
  }
  std::vector<ContourSegment> path;
  std::vector<NoseComp> comps;
  for (const Move& m : moves) {
    path.push_back({m.kind, m.from, m.to, m.center, m.line, m.column});
    comps.push_back(m.noseComp);
  }
  auto pieces = PathCompensation(path, comps).run();
  if (!pieces.ok()) return pieces.error();
  std::vector<Move> compensated;
  compensated.reserve(pieces.value().size());
  for (const Piece& piece : pieces.value()) {
    if (zeroLengthStraight(piece.segment) && piece.segment.kind != MoveKind::Dwell) continue;
    Move move = moves[piece.source];
    move.kind = piece.segment.kind;
    move.from = piece.segment.from;
    move.to = piece.segment.to;
    move.center = piece.segment.center;
    compensated.push_back(move);
  }
  moves = std::move(compensated);
  return success();
}

Result<Contour> compensatedContour(const Contour& contour, const std::vector<NoseComp>& noseComps) {
  auto pieces = PathCompensation(contour, noseComps).run();
  if (!pieces.ok()) return pieces.error();
  Contour compensated;
  for (const Piece& piece : pieces.value()) compensated.push_back(piece.segment);
  return compensated;
}

}  // namespace lathesim::interp
