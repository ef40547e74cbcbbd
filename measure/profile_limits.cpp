#include "measure/profile_limits.hpp"

#include <cmath>
#include <limits>

#include "measure/size_check.hpp"

namespace lathesim::measure {
namespace {

Band looser(const Band& a, const Band& b) { return {std::min(a.lowerMm, b.lowerMm), std::max(a.upperMm, b.upperMm)}; }

double distanceToChord(const RZ& p, const RZ& a, const RZ& b) {
  const RZ ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

}  // namespace

RZ outwardNormal(const MeridianProfile& drawing, const DrawnLine& line) {
  const RZ along = (line.to - line.from).normalized();
  const RZ left(-along.y(), along.x());
  const RZ middle = (line.from + line.to) / 2;
  return drawing.contains(middle + 1e-3 * left) ? RZ(-left) : left;
}

Band normalBand(const MeridianProfile& drawing, const DrawnLine& line, const Tolerance& tolerance) {
  if (!line.diameter() && !line.face()) return {tolerance.lowerMm, tolerance.upperMm};  // stated normal to it
  const RZ out = outwardNormal(drawing, line);
  // The size grows along +r (a diameter, by twice the radius) or +z (a face's Z); excess is
  // the surface moving out of the material.
  const double scale = line.diameter() ? 0.5 : 1.0;
  const double outwardIsGrowth = line.diameter() ? out.x() : out.y();
  if (outwardIsGrowth > 0) return {scale * tolerance.lowerMm, scale * tolerance.upperMm};
  return {-scale * tolerance.upperMm, -scale * tolerance.lowerMm};
}

ProfileLimits::ProfileLimits(const MeridianProfile& drawing, std::vector<RZ> outline, const std::vector<DrawnLine>& lines,
                             char generalClass, double cornerRadiusMm, double sizeMarginMm)
    : lines_(lines), cornerRadiusMm_(cornerRadiusMm), sizeMarginMm_(sizeMarginMm) {
  const double datumZ = datumZOf(lines);
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const DrawnLine& line = lines[n];
    for (std::size_t p = line.outlineFrom; p < line.outlineTo; ++p) pieces_.push_back({outline[p], outline[p + 1], n});
    sized_.push_back(line.diameter() || line.face());
    if (line.tolerance) {
      bands_.push_back(normalBand(drawing, line, *line.tolerance));
    } else {
      const Tolerance general = generalTolerance(line, generalClass, datumZ);
      // A taper or an arc: its greatest diameter's tolerance, half of it normal to the surface.
      bands_.push_back(sized_.back() ? normalBand(drawing, line, general) : Band{general.lowerMm / 2, general.upperMm / 2});
    }
    measured_.push_back(bands_.back());
  }
  const bool closedAsGiven = outline.size() > 2 && outline.front() == outline.back();
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const std::size_t next = n + 1 < lines.size() ? n + 1 : (closedAsGiven ? 0 : lines.size());
    if (next == lines.size() || next == n) continue;
    const RZ corner = outline[lines[n].outlineTo];
    if (corner.x() <= 0) continue;  // on the axis: no corner of the part
    const RZ a = (outline[lines[n].outlineTo - 1] - corner).normalized();
    const RZ b = (outline[lines[next].outlineFrom + 1] - corner).normalized();
    const double angle = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
    if (angle > M_PI - 1e-3 || angle < 1e-3) continue;  // tangent: no corner
    const bool concave = !drawing.contains(corner + 1e-3 * (a + b).normalized());
    corners_.push_back({corner, cornerRadiusMm / std::tan(angle / 2), concave});
  }
}

void ProfileLimits::explainedBySize(std::size_t line, double lowMm, double highMm) {
  measured_[line] = looser(bands_[line], {lowMm, highMm});
}

std::optional<Band> ProfileLimits::at(const RZ& onDrawing) const {
  const Piece* nearest = nullptr;
  double best = std::numeric_limits<double>::infinity();
  for (const Piece& piece : pieces_) {
    const double d = distanceToChord(onDrawing, piece.a, piece.b);
    if (d < best) best = d, nearest = &piece;
  }
  if (nearest == nullptr) return std::nullopt;
  const DrawnLine& line = lines_[nearest->line];
  const double fromStart = (onDrawing - line.from).norm(), fromEnd = (onDrawing - line.to).norm();
  const double length = (line.to - line.from).norm();
  // A size check measures the line off its ends (or, too short for that, at its middle only).
  if (sized_[nearest->line] && std::min(fromStart, fromEnd) > sizeMarginMm_ && length > 2 * sizeMarginMm_)
    return std::nullopt;
  Band band = measured_[nearest->line];
  // Near a corner the looser of both lines' bands.
  for (std::size_t n = 0; n < lines_.size(); ++n)
    if (n != nearest->line && ((lines_[n].to - onDrawing).norm() <= sizeMarginMm_ || (lines_[n].from - onDrawing).norm() <= sizeMarginMm_) &&
        (lines_[n].to == line.from || lines_[n].to == line.to || lines_[n].from == line.from || lines_[n].from == line.to))
      band = looser(band, measured_[n]);
  for (const Corner& corner : corners_) {
    const double s = (onDrawing - corner.at).norm();
    if (s >= corner.tangentMm) continue;
    const double r = cornerRadiusMm_, off = corner.tangentMm - s;
    const double allowance = r - std::sqrt(std::max(0.0, r * r - off * off));
    if (corner.concave) band.upperMm = std::max(band.upperMm, band.upperMm + allowance);
    else band.lowerMm = std::min(band.lowerMm, band.lowerMm - allowance);
  }
  return band;
}

}  // namespace lathesim::measure
