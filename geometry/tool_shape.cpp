// Tool shapes are built in the drawing frame (Z to the right, X up — the vectors of
// iso-tools.md §2.11 are written (Z, X)) with an R-hand tool's theoretical sharp corner at the
// origin, then mirrored for L hand, moved so the imaginary tip is the origin, and finally
// turned into RZ = (radial, axial).

#include "geometry/tool_shape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace lathesim {
namespace {

using ZX = Eigen::Vector2d;  // drawing frame: x() = Z, y() = X

constexpr double kPi = std::numbers::pi;
double rad(double deg) { return deg * kPi / 180.0; }
ZX polar(double length, double angleRad) { return ZX(length * std::cos(angleRad), length * std::sin(angleRad)); }
RZ toRZ(const ZX& p) { return RZ(p.y(), p.x()); }

/// A nose arc's sagitta as a share of its radius, at most: beyond 4 m of radius the chords
/// follow it and stop growing in number. Without it a tool a comment names with a pitch of
/// 555 km (a 69 km nose) was drawn with 300 000 chords: seconds for one comment.
constexpr double kNoseArcRelativeTolerance = 1e-6;

/// Points on the arc of radius r about c from angle a0 to a1 (radians, a0 ≤ a1, ccw), with
/// every axis direction in between as a vertex and chords of sagitta < kNoseArcToleranceMm
/// (or r·kNoseArcRelativeTolerance for a radius no tool has).
void appendArc(std::vector<ZX>& out, const ZX& c, double r, double a0, double a1) {
  const double sagitta = std::max(kNoseArcToleranceMm, r * kNoseArcRelativeTolerance);
  const double step = 2.0 * std::acos(std::max(1.0 - sagitta / r, 0.0));
  std::vector<double> breaks{a0};
  for (int k = static_cast<int>(std::floor(a0 / (kPi / 2))) + 1; k * (kPi / 2) < a1; ++k) breaks.push_back(k * (kPi / 2));
  breaks.push_back(a1);
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double span = breaks[i + 1] - breaks[i];
    const int pieces = std::max(1, static_cast<int>(std::ceil(span / std::min(step, kPi / 4))));
    for (int j = 0; j < pieces; ++j) {
      const double a = breaks[i] + span * j / pieces;
      // Exact axis directions, so the touch-off extremes carry no rounding.
      const double ca = j == 0 ? std::round(std::cos(a) * 1e12) / 1e12 : std::cos(a);
      const double sa = j == 0 ? std::round(std::sin(a) * 1e12) / 1e12 : std::sin(a);
      out.push_back(c + r * ZX(ca, sa));
    }
  }
  out.push_back(c + r * ZX(std::cos(a1), std::sin(a1)));
}

/// The convex polygon `corners` (any order) with every corner rounded by r: the Minkowski
/// sum with a disc of radius r, as chords. One corner: a circle.
std::vector<ZX> roundedOutline(const std::vector<ZX>& corners, double r) {
  const ConvexPolygon hull = ConvexPolygon::hullOf(corners);  // ccw in the drawing frame
  const auto& v = hull.vertices();
  if (r <= 0.0) return v;
  std::vector<ZX> out;
  if (v.size() == 1) {
    appendArc(out, v[0], r, 0.0, 2.0 * kPi);
    return out;
  }
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    const ZX e0 = v[i] - v[(i + n - 1) % n];
    const ZX e1 = v[(i + 1) % n] - v[i];
    const double a0 = std::atan2(-e0.x(), e0.y());  // outward normal (e.y, −e.x)
    double a1 = std::atan2(-e1.x(), e1.y());
    while (a1 < a0) a1 += 2.0 * kPi;
    appendArc(out, v[i], r, a0, a1);
  }
  return out;
}

/// An outline in the drawing frame, moved by `shift`, as an RZ polygon.
ConvexPolygon placed(const std::vector<ZX>& points, const ZX& shift) {
  std::vector<RZ> rz;
  rz.reserve(points.size());
  for (const ZX& p : points) rz.push_back(toRZ(p + shift));
  return ConvexPolygon::hullOf(rz);
}

/// Canonical sharp corners about the insert centre, the cutting corner at angle 0.
std::vector<ZX> canonicalCorners(const IsoInsert& insert) {
  const double d = insert.inscribedCircleMm;
  const double eps = rad(insert.noseAngleDeg);
  std::vector<ZX> corners;
  switch (insert.shape) {
    case 'C': case 'D': case 'E': case 'M': case 'V': {
      const double l = d / std::sin(eps);  // rhombus, §1.10
      corners = {ZX(l * std::cos(eps / 2), 0), ZX(0, l * std::sin(eps / 2)), ZX(-l * std::cos(eps / 2), 0),
                 ZX(0, -l * std::sin(eps / 2))};
      break;
    }
    case 'W':  // 80° corners at (d/2)/sin 40°, 160° corners at (d/2)/sin 80°, alternating every 60°
      for (int k = 0; k < 6; ++k) corners.push_back(polar((d / 2) / std::sin(rad(k % 2 ? 80 : 40)), rad(60.0 * k)));
      break;
    default: {  // regular n-gon: S T P H O
      const int n = static_cast<int>(std::lround(360.0 / (180.0 - insert.noseAngleDeg)));
      for (int k = 0; k < n; ++k) corners.push_back(polar((d / 2) / std::cos(kPi / n), 2.0 * kPi * k / n));
    }
  }
  return corners;
}

std::optional<int> checkedTip(std::optional<int> tip, int fallback, std::initializer_list<int> allowed,
                              const std::string& toolName, std::string& problem) {
  const int t = tip.value_or(fallback);
  if (std::find(allowed.begin(), allowed.end(), t) != allowed.end()) return t;
  std::string list;
  for (int a : allowed) list += (list.empty() ? "" : ", ") + std::to_string(a);
  problem = "tip " + std::to_string(t) + " does not apply to " + toolName + "; expected " + list;
  return std::nullopt;
}

BuiltTool failed(std::string problem) { return {std::nullopt, std::move(problem), {}}; }

}  // namespace

int defaultTipNumber(const IsoHolder& holder) {
  return holder.hand == 'L' ? 4 : holder.hand == 'N' ? 8 : 3;
}

BuiltTool turningTool(const IsoInsert& insert, const IsoHolder& holder, std::optional<int> tipNumber) {
  if (insert.shape != holder.insertShape)
    return failed("insert " + insert.code + " is shape " + std::string(1, insert.shape) + " but holder " + holder.code +
                  " seats shape " + std::string(1, holder.insertShape));
  if (tipNumber && (*tipNumber < 0 || *tipNumber > 9))
    return failed("tip " + std::to_string(*tipNumber) + " is not a tip number; expected 0..9");
  BuiltTool built;
  if (insert.sizeCode != holder.edgeSizeCode)
    built.warnings.push_back("insert " + insert.code + " has size " + insert.sizeCode + " but holder " + holder.code +
                             " seats size " + holder.edgeSizeCode + " (the insert's own size is used)");
  if (insert.clearance != holder.clearance)
    built.warnings.push_back("insert " + insert.code + " has clearance " + std::string(1, insert.clearance) +
                             " but holder " + holder.code + " is made for clearance " + std::string(1, holder.clearance));

  const double r = insert.noseRadiusMm;
  const double d = insert.inscribedCircleMm;
  std::vector<ZX> sharp;  // the insert's sharp corners, drawing frame, sharp cutting corner at the origin
  ZX centre, noseCentre;
  if (insert.round()) {
    centre = noseCentre = ZX(r, r);  // the origin is then the tip-3 point of the circle
    sharp = {centre};
  } else {
    const double eps = rad(insert.noseAngleDeg);
    const double kr = rad(holder.enteringAngleDeg);
    const double beta = holder.family == HolderFamily::Side ? kPi - kr - eps / 2
                        : holder.family == HolderFamily::End ? kr - kPi / 2 + eps / 2
                                                             : kPi / 2;
    const double cornerToCentre = (d / 2) / std::sin(eps / 2);
    centre = polar(cornerToCentre, beta);
    noseCentre = polar(r / std::sin(eps / 2), beta);
    const Eigen::Rotation2Dd turn(beta + kPi);
    for (const ZX& c : canonicalCorners(insert)) sharp.push_back(centre + turn * c);
  }
  // The cutter: every corner pulled toward the centre by r (the inset polygon, homothetic for
  // a polygon with an inscribed circle), then rounded by r.
  std::vector<ZX> inset;
  const double scale = insert.round() ? 0.0 : (d / 2 - r) / (d / 2);
  for (const ZX& c : sharp) inset.push_back(centre + scale * (c - centre));

  // The holder: shank along +X from the top of the insert to l1, between Z = f − b and f
  // (§2.11); the head joins it to the insert's centre and its non-cutting corners pulled 30 %
  // toward the centre, so the head stays clear of both cutting edges.
  const double f = holder.functionalWidthMm();
  const double b = holder.shankWidthMm;
  double top = 0.0;
  for (const ZX& c : sharp) top = std::max(top, c.y() + (insert.round() ? r : 0.0));
  std::vector<ZX> body{ZX(f - b, top), ZX(f, top), ZX(f, holder.lengthMm), ZX(f - b, holder.lengthMm), centre};
  for (std::size_t i = insert.round() ? sharp.size() : 1; i < sharp.size(); ++i)
    body.push_back(centre + 0.7 * (sharp[i] - centre));
  // canonicalCorners puts the cutting corner first, so sharp[0] is the one left out above.

  const bool left = holder.hand == 'L';
  const auto mirrored = [left](std::vector<ZX> points) {
    if (left)
      for (ZX& p : points) p.x() = -p.x();
    return points;
  };
  const ZX mirroredNose = left ? ZX(-noseCentre.x(), noseCentre.y()) : noseCentre;

  const int tip = tipNumber.value_or(defaultTipNumber(holder));
  const RZ s = imaginaryTipDirection(tip);
  const ZX point = mirroredNose + r * ZX(s.y(), s.x());
  ToolShape tool{placed(roundedOutline(mirrored(inset), r), -point), placed(mirrored(body), -point), tip, r,
                 toRZ(mirroredNose - point), toRZ(-point)};
  if (insert.round()) tool.sharpCorner = tool.noseCentre;
  built.tool = std::move(tool);
  return built;
}

BuiltTool grooveTool(double widthMm, double leftRadiusMm, double rightRadiusMm, double depthMm,
                     std::optional<int> tipNumber) {
  if (!(widthMm > 0) || !(depthMm > 0)) return failed("a groove tool needs a positive width and depth");
  const double rl = leftRadiusMm, rr = rightRadiusMm;
  if (!(rl >= 0) || !(rr >= 0) || rl + rr > widthMm || std::max(rl, rr) > depthMm)
    return failed("corner radii " + std::to_string(rl) + " and " + std::to_string(rr) + " mm do not fit a " +
                  std::to_string(widthMm) + " mm wide blade (together at most its width)");
  std::string problem;
  const auto tip = checkedTip(tipNumber, 3, {3, 4, 8}, "a groove tool", problem);
  if (!tip) return failed(problem);
  // Drawing frame: the blade spans Z 0..width, X 0..depth; its end (X 0) cuts.
  const ZX leftNose(rl, rl), rightNose(widthMm - rr, rr);
  std::vector<ZX> outline;
  appendArc(outline, leftNose, rl, kPi, 1.5 * kPi);
  appendArc(outline, rightNose, rr, 1.5 * kPi, 2.0 * kPi);
  outline.push_back(ZX(widthMm, depthMm));
  outline.push_back(ZX(0, depthMm));
  const double r = *tip == 3 ? rl : *tip == 4 ? rr : std::min(rl, rr);
  const ZX nose = *tip == 3 ? leftNose : *tip == 4 ? rightNose : ZX(widthMm / 2, r);
  const RZ s = imaginaryTipDirection(*tip);
  const ZX point = nose + r * ZX(s.y(), s.x());
  const std::vector<ZX> blade{ZX(0, depthMm), ZX(widthMm, depthMm), ZX(widthMm, depthMm + 30.0), ZX(0, depthMm + 30.0)};
  ToolShape tool{placed(outline, -point), placed(blade, -point), *tip, r, toRZ(nose - point),
                 toRZ(ZX(*tip == 4 ? widthMm : *tip == 8 ? widthMm / 2 : 0.0, 0.0) - point)};
  return {std::move(tool), {}, {}};
}

BuiltTool threadTool(double profileDeg, double pitchMm, double noseRadiusMm, std::optional<int> tipNumber,
                     bool internal) {
  if (!(profileDeg > 0 && profileDeg < 180)) return failed("a thread profile angle must lie between 0° and 180°");
  if (!(pitchMm > 0)) return failed("a thread tool needs a positive pitch");
  std::string problem;
  const auto tip = internal ? checkedTip(tipNumber, 6, {6, 0}, "an internal thread tool", problem)
                            : checkedTip(tipNumber, 8, {8, 0}, "a thread tool", problem);
  if (!tip) return failed(problem);
  const double half = rad(profileDeg) / 2;
  const double height = pitchMm / (2 * std::tan(half));  // the fundamental triangle: width = pitch at the top
  const double r = noseRadiusMm;
  if (!(r >= 0) || r / std::sin(half) - r >= height)
    return failed("nose radius " + std::to_string(r) + " mm is too large for the profile");
  // The sharp V: apex at the origin; the nose centre on the axis of symmetry, r/sin(half) above it.
  const ZX nose(0, r / std::sin(half));
  const ZX point = *tip == 0 ? nose : ZX(0, nose.y() - r);
  // The inset triangle of the rounded V, then rounded by r, cut at the fundamental height.
  const double insetTop = height + 2 * r;  // tall enough; the cut at `height` is applied below
  std::vector<ZX> outline = roundedOutline({nose, ZX(-insetTop * std::tan(half), insetTop + nose.y()),
                                            ZX(insetTop * std::tan(half), insetTop + nose.y())}, r);
  std::vector<ZX> clipped;
  for (const ZX& p : outline)
    if (p.y() < height) clipped.push_back(p);
  clipped.push_back(ZX(-pitchMm / 2, height));
  clipped.push_back(ZX(pitchMm / 2, height));
  // An internal insert is the same V pointing outward: mirrored in X about its programmed point.
  const auto facing = [internal](const ZX& p) { return internal ? ZX(p.x(), -p.y()) : p; };
  for (ZX& p : clipped) p = facing(p - point);
  ToolShape tool{placed(clipped, ZX(0, 0)), std::nullopt, *tip, r, toRZ(facing(nose - point)), toRZ(facing(-point))};
  return {std::move(tool), {}, {}};
}

BuiltTool drillTool(double diameterMm, double pointAngleDeg, double lengthMm) {
  if (!(diameterMm > 0)) return failed("a drill needs a positive diameter");
  if (!(pointAngleDeg > 0 && pointAngleDeg <= 180)) return failed("a drill's point angle must lie in (0°, 180°]");
  const double radius = diameterMm / 2;
  const double pointLength = radius / std::tan(rad(pointAngleDeg) / 2);
  if (!(lengthMm > pointLength)) return failed("a drill's length must exceed its point length");
  // Radial first here (RZ): the profile is symmetric about the axis, apex at the programmed point.
  std::vector<RZ> profile{RZ(0, 0), RZ(radius, pointLength), RZ(radius, lengthMm), RZ(-radius, lengthMm),
                          RZ(-radius, pointLength)};
  ToolShape tool{ConvexPolygon::hullOf(profile), std::nullopt, 0, 0.0, RZ(0, 0), RZ(0, 0)};
  return {std::move(tool), {}, {}};
}

}  // namespace lathesim
