#include "measure/size_check.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

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
      const double z = line.from.y();
      check.nominalMm = z;
      const double rLow = std::min(line.from.x(), line.to.x()), rHigh = std::max(line.from.x(), line.to.x());
      const bool materialBelow = outwardNormal(drawing, line).y() > 0;
      check.uncertaintyMm = surfaceUncertaintyMm(h);
      // The axis is no corner: only an end off it keeps the margin.
      int iFirst = static_cast<int>(std::ceil((rLow > 0 ? rLow + margin : 0.0) / h));
      int iLast = static_cast<int>(std::floor((rHigh - margin) / h));
      if (iFirst > iLast) iFirst = iLast = static_cast<int>(std::lround((rLow + rHigh) / 2 / h));
      for (int i = std::max(0, iFirst); i <= std::min(section.rCount - 1, iLast); ++i) {
        const auto phi = [&](int k) { return static_cast<double>(section.at(i, k)); };
        const Crossing c = nearestCrossing(phi, section.zCount, section.zFirstMm, h, materialBelow, z);
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
