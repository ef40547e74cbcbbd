#include "measure/size_check.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <utility>

#include "measure/profile_limits.hpp"

namespace lathesim::measure {
namespace {

struct Crossing {
  double at = 0;  // along the searched line, mm
  bool found = false;
};

/// Along `count` samples of φ (sample n at first + n·h), the crossing into the air going up
/// (material below) or into the material (material above) nearest `target`.
template <typename Phi>
Crossing nearestCrossing(const Phi& phi, int count, double first, double h, bool materialBelow, double target) {
  Crossing best;
  for (int n = 0; n + 1 < count; ++n) {
    const double a = phi(n), b = phi(n + 1);
    const bool crosses = materialBelow ? (a < 0 && b >= 0) : (a >= 0 && b < 0);
    if (!crosses) continue;
    const double at = first + (n + a / (a - b)) * h;
    if (!best.found || std::abs(at - target) < std::abs(best.at - target)) best = {at, true};
  }
  return best;
}

/// The drawing's surface on the row at `z`: its crossing nearest the radius `guess`.
std::optional<double> drawnRadiusOnRow(const MeridianProfile& drawing, double z, double guess) {
  std::optional<double> best;
  for (const Segment& s : drawing.surface()) {
    const double za = s.a.y(), zb = s.b.y();
    if (za == zb || z < std::min(za, zb) || z > std::max(za, zb)) continue;
    const double r = s.a.x() + (z - za) / (zb - za) * (s.b.x() - s.a.x());
    if (!best || std::abs(r - guess) < std::abs(*best - guess)) best = r;
  }
  return best;
}

/// The part beside one end of a face: the drawn line meeting the face at `end` (a diameter, a
/// taper, an arc) measured on its grid rows, off its ends by `margin`, as a diameter is (the
/// part's surface nearest the drawn one): per row, where the part is and how far that lies
/// from the drawing, towards the face's other end (> 0: standing over the face).
struct FaceEnd {
  RZ end{0, 0};
  double towardsFar = 1;    // +1: the face's other end lies at a greater radius
  std::vector<double> made;  // the part's surface on each row (radius)
  std::vector<double> over;  // how far it lies from the drawing's towards the face's other end
  /// Where the part beside the face is, at the face: the drawn end moved by the rows' median
  /// (a row next to a face that is not where drawn reads the face, not the neighbour).
  double madeAtFace() const {
    if (over.empty()) return end.x();
    std::vector<double> sorted = over;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    return end.x() + towardsFar * sorted[sorted.size() / 2];
  }
};

FaceEnd faceEnd(const SampledSection& section, const MeridianProfile& drawing, const DrawnLine* neighbour, const RZ& end,
                double farR, double margin) {
  FaceEnd result{end, farR > end.x() ? 1.0 : -1.0, {}, {}};
  if (neighbour == nullptr) return result;  // on the axis, or beside another face
  const double h = section.stepMm;
  const double zLow = std::min(neighbour->from.y(), neighbour->to.y()), zHigh = std::max(neighbour->from.y(), neighbour->to.y());
  int kFirst = static_cast<int>(std::ceil((zLow + margin - section.zFirstMm) / h));
  int kLast = static_cast<int>(std::floor((zHigh - margin - section.zFirstMm) / h));
  if (kFirst > kLast) kFirst = kLast = static_cast<int>(std::lround(((zLow + zHigh) / 2 - section.zFirstMm) / h));
  for (int k = std::max(0, kFirst); k <= std::min(section.zCount - 1, kLast); ++k) {
    const double z = section.zFirstMm + k * h;
    // The drawn line's radius on this row: its chord's, moved onto the drawing's surface (an arc).
    const double dz = neighbour->to.y() - neighbour->from.y();
    const double t = dz == 0 ? 0.5 : (z - neighbour->from.y()) / dz;  // an arc may end where it starts, in Z
    const auto drawn = drawnRadiusOnRow(drawing, z, neighbour->from.x() + t * (neighbour->to.x() - neighbour->from.x()));
    if (!drawn) continue;
    const bool materialInside = drawing.contains(RZ(*drawn - 1e-3, z));
    const auto phi = [&](int i) { return static_cast<double>(section.at(i, k)); };
    const Crossing c = nearestCrossing(phi, section.rCount, 0.0, h, materialInside, *drawn);
    const double made = c.found ? c.at : (phi(0) >= 0 ? 0.0 : (section.rCount - 1) * h);
    result.made.push_back(made);
    result.over.push_back((made - *drawn) * result.towardsFar);
  }
  return result;
}

/// How far the part beside `near` stands over the face (mm, ≥ 0): the face's columns within
/// it would cross the neighbour's material (an oversize diameter beside a shoulder) or its
/// air, and read another surface. A row whose surface lies at or past where the part beside
/// the other end is reads through the face (the face is not where drawn there: its columns
/// measure that) and is left out; nullopt when every row does so.
std::optional<double> reachOver(const FaceEnd& near, const FaceEnd& other, double margin) {
  const double otherMade = other.madeAtFace();
  double reach = 0;
  bool bounded = false;
  for (std::size_t n = 0; n < near.made.size(); ++n) {
    if ((near.made[n] - otherMade) * near.towardsFar >= -margin) continue;  // through the face
    bounded = true;
    reach = std::max(reach, near.over[n]);
  }
  if (!near.made.empty() && !bounded) return std::nullopt;
  return reach;
}

/// The grid columns a face (lines[index]) is measured on: its drawn span off its ends by
/// `margin` (the axis is no corner), narrowed by how far the part beside each end stands over
/// it. A face too short for that: its middle column, if the part leaves one. nullopt: no
/// column crosses the face alone.
std::optional<std::pair<int, int>> faceColumns(const SampledSection& section, const MeridianProfile& drawing,
                                               const std::vector<DrawnLine>& lines, std::size_t index, double margin) {
  const DrawnLine& face = lines[index];
  const double h = section.stepMm;
  const RZ inner = face.from.x() < face.to.x() ? face.from : face.to, outer = face.from.x() < face.to.x() ? face.to : face.from;
  const auto neighbourAt = [&](const RZ& end) -> const DrawnLine* {
    for (std::size_t n = 0; n < lines.size(); ++n)
      if (n != index && !lines[n].face() && (lines[n].from == end || lines[n].to == end)) return &lines[n];
    return nullptr;
  };
  const FaceEnd low = faceEnd(section, drawing, neighbourAt(inner), inner, outer.x(), margin);
  const FaceEnd high = faceEnd(section, drawing, neighbourAt(outer), outer, inner.x(), margin);
  const auto lowReach = reachOver(low, high, margin), highReach = reachOver(high, low, margin);
  if (!lowReach || !highReach) return std::nullopt;
  const double rLow = inner.x() + *lowReach, rHigh = outer.x() - *highReach;
  if (rLow >= rHigh) return std::nullopt;
  int first = static_cast<int>(std::ceil((rLow > 0 ? rLow + margin : 0.0) / h));
  int last = static_cast<int>(std::floor((rHigh - margin) / h));
  if (first <= last) return std::pair{first, last};
  const int middle = static_cast<int>(std::lround((rLow + rHigh) / 2 / h));
  if (middle * h <= rLow || middle * h >= rHigh) return std::nullopt;
  return std::pair{middle, middle};
}

std::string plusMinus(double value) {
  std::ostringstream text;
  text << "±" << value;
  return text.str();
}

}  // namespace

Tolerance generalTolerance(const DrawnLine& line, char generalClass, double datumZ) {
  const std::string name = std::string("ISO 2768-") + generalClass;
  std::ostringstream source;
  source.precision(6);
  double size = 0;
  if (line.face()) {
    size = std::abs(datumZ - line.from.y());
    source << name << " for the length " << size << " mm from the front face Z" << datumZ;
  } else {
    size = 2 * std::max(line.from.x(), line.to.x());
    source << name << " for Ø" << size;
  }
  // Class v has no tolerance for 0.5–3 mm; f stands in there (the tighter: never a pass v would not give).
  const double t = generalLinearTolerance(generalClass, size).value_or(*generalLinearTolerance('f', size));
  source << " (" << plusMinus(t) << ")";
  return {t, -t, source.str()};
}

double datumZOf(const std::vector<DrawnLine>& lines) {
  double datumZ = -INFINITY;
  for (const DrawnLine& line : lines) datumZ = std::max({datumZ, line.from.y(), line.to.y()});
  return datumZ;
}

std::vector<SizeCheck> checkSizes(const SampledSection& section, const MeridianProfile& drawing,
                                  const std::vector<DrawnLine>& lines, char generalClass, double cornerRadiusMm,
                                  const std::vector<ZRange>& ignored) {
  const double h = section.stepMm;
  const double datumZ = datumZOf(lines);
  const double margin = sizeMarginMm(cornerRadiusMm, h);
  std::vector<SizeCheck> checks;
  for (std::size_t index = 0; index < lines.size(); ++index) {
    const DrawnLine& line = lines[index];
    if (!line.diameter() && !line.face()) continue;
    const double zLow = std::min(line.from.y(), line.to.y()), zHigh = std::max(line.from.y(), line.to.y());
    // In a thread's zone: a diameter reaching into it (not only touching its end), a face inside it.
    if (std::any_of(ignored.begin(), ignored.end(), [&](const ZRange& r) {
          return zLow == zHigh ? r.contains(zLow) : r.lowMm < zHigh && r.highMm > zLow;
        }))
      continue;
    SizeCheck check;
    check.drawn = line;
    check.lineIndex = index;
    check.diameter = line.diameter();
    check.stated = line.tolerance.has_value();
    check.tolerance = line.tolerance ? *line.tolerance : generalTolerance(line, generalClass, datumZ);
    std::vector<std::pair<double, RZ>> figures;  // (diameter or Z, where)
    if (check.diameter) {
      const double radius = line.from.x();
      check.nominalMm = 2 * radius;
      check.bore = outwardNormal(drawing, line).x() < 0;
      check.uncertaintyMm = 2 * surfaceUncertaintyMm(h);
      // The grid rows along the line, off its ends; a line too short for that: its middle row.
      int kFirst = static_cast<int>(std::ceil((zLow + margin - section.zFirstMm) / h));
      int kLast = static_cast<int>(std::floor((zHigh - margin - section.zFirstMm) / h));
      if (kFirst > kLast) kFirst = kLast = static_cast<int>(std::lround(((zLow + zHigh) / 2 - section.zFirstMm) / h));
      for (int k = std::max(0, kFirst); k <= std::min(section.zCount - 1, kLast); ++k) {
        const auto phi = [&](int i) { return static_cast<double>(section.at(i, k)); };
        const Crossing c = nearestCrossing(phi, section.rCount, 0.0, h, !check.bore, radius);
        // No surface on the row: all air (a shaft's diameter 0) or all material (to the section's edge).
        const double r = c.found ? c.at : (phi(0) >= 0 ? 0.0 : (section.rCount - 1) * h);
        figures.emplace_back(2 * r, RZ(r, section.zFirstMm + k * h));
      }
    } else {
      check.nominalMm = line.from.y();
      check.uncertaintyMm = surfaceUncertaintyMm(h);
      const auto columns = faceColumns(section, drawing, lines, index, margin);
      if (!columns) {
        // No column crosses the face alone: a neighbour's excess (or a face missing) stands
        // over all of it. Undecided, never a neighbour's figure.
        check.probed = false;
        check.verdict = Verdict::Undecided;
        check.leastMm = check.greatestMm = check.worstMm = check.nominalMm;
        check.leastAt = check.greatestAt = check.worstAt = (line.from + line.to) / 2;
        checks.push_back(std::move(check));
        continue;
      }
      const bool materialBelow = outwardNormal(drawing, line).y() > 0;
      for (int i = std::max(0, columns->first); i <= std::min(section.rCount - 1, columns->second); ++i) {
        const auto phi = [&](int k) { return static_cast<double>(section.at(i, k)); };
        const Crossing c = nearestCrossing(phi, section.zCount, section.zFirstMm, h, materialBelow, check.nominalMm);
        const double top = section.zFirstMm + (section.zCount - 1) * h;
        const double at = c.found ? c.at : ((phi(0) < 0) == materialBelow ? top : section.zFirstMm);
        figures.emplace_back(at, RZ(i * h, at));
      }
    }
    check.measured = !figures.empty();
    if (!check.measured) continue;  // the line lies outside the section: the part has nothing there
    const auto [least, greatest] = std::minmax_element(
        figures.begin(), figures.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    check.leastMm = least->first, check.leastAt = least->second;
    check.greatestMm = greatest->first, check.greatestAt = greatest->second;
    const double low = check.nominalMm + check.tolerance.lowerMm, high = check.nominalMm + check.tolerance.upperMm;
    const bool leastWorse = low - check.leastMm >= check.greatestMm - high;
    check.outsideMm = leastWorse ? low - check.leastMm : check.greatestMm - high;
    check.worstMm = leastWorse ? check.leastMm : check.greatestMm;
    check.worstAt = leastWorse ? check.leastAt : check.greatestAt;
    check.verdict = verdictOf(check.outsideMm, check.uncertaintyMm);
    checks.push_back(std::move(check));
  }
  return checks;
}

}  // namespace lathesim::measure
