#include "geometry/part_dimensions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lathesim {
namespace {

struct Face {
  double at = 0;           // r of a cylindrical face, z of a square one
  double low = 0, high = 0;  // its extent along the other axis
  double size() const { return high - low; }
};

/// Faces along one axis (`along` 1: cylindrical, varying z; 0: square, varying r): the longest
/// runs of consecutive polyline points whose other coordinate stays within `tolerance` of the
/// run's first, at least `minSize` long; placed at that coordinate's mean over the run.
std::vector<Face> facesAlong(const std::vector<std::vector<RZ>>& polylines, int along, double tolerance, double minSize) {
  const int across = 1 - along;
  std::vector<Face> faces;
  for (const auto& line : polylines)
    for (std::size_t i = 0; i + 1 < line.size();) {
      std::size_t j = i;
      double sum = line[i][across], low = line[i][along], high = low;
      while (j + 1 < line.size() && std::abs(line[j + 1][across] - line[i][across]) <= tolerance) {
        ++j;
        sum += line[j][across];
        low = std::min(low, line[j][along]), high = std::max(high, line[j][along]);
      }
      if (j > i && high - low >= minSize) faces.push_back({sum / static_cast<double>(j - i + 1), low, high});
      i = std::max(j, i + 1);
    }
  std::sort(faces.begin(), faces.end(), [](const Face& x, const Face& y) { return x.size() > y.size(); });
  return faces;
}

}  // namespace

PartDimensions mainDimensions(const MeridianProfile& profile, const std::vector<std::vector<RZ>>& polylines,
                              const DimensionRules& rules) {
  PartDimensions dims;
  double zMin = std::numeric_limits<double>::infinity(), zMax = -zMin;
  for (const auto& line : polylines)
    for (const RZ& p : line) zMin = std::min(zMin, p.y()), zMax = std::max(zMax, p.y());
  if (!(zMin < zMax)) return dims;
  const double merge = 2 * rules.flatToleranceMm;
  const double probe = std::max(rules.flatToleranceMm, 1e-3);

  // Diameters: the longest face of each distinct diameter, the longest first.
  for (const Face& f : facesAlong(polylines, 1, rules.flatToleranceMm, rules.minFaceMm)) {
    if (f.at <= merge) continue;  // the axis
    if (static_cast<int>(dims.diameters.size()) >= rules.maxDiameters) break;
    const bool known = std::any_of(dims.diameters.begin(), dims.diameters.end(),
                                   [&](const DiameterDimension& d) { return std::abs(d.diameterMm - 2 * f.at) <= 2 * merge; });
    if (known) continue;
    const double zMiddle = 0.5 * (f.low + f.high);
    const bool bore = profile.contains(RZ(f.at + probe, zMiddle)) && !profile.contains(RZ(f.at - probe, zMiddle));
    dims.diameters.push_back({2 * f.at, f.low, f.high, bore});
  }
  std::sort(dims.diameters.begin(), dims.diameters.end(),
            [](const DiameterDimension& a, const DiameterDimension& b) { return a.zLowMm + a.zHighMm < b.zLowMm + b.zHighMm; });

  // How far out the part reaches at a face square to the axis: its largest r there.
  auto reachAt = [&](double z) {
    double reach = 0;
    for (const Face& f : facesAlong(polylines, 0, rules.flatToleranceMm, 0.0))
      if (std::abs(f.at - z) <= merge) reach = std::max(reach, f.high);
    return reach;
  };
  // Lengths: from the right-hand end to the largest shoulders, then the overall length.
  std::vector<double> shoulders;
  for (const Face& f : facesAlong(polylines, 0, rules.flatToleranceMm, rules.minFaceMm)) {
    if (static_cast<int>(shoulders.size()) + 1 >= rules.maxLengths) break;
    if (std::abs(f.at - zMin) <= merge || std::abs(f.at - zMax) <= merge) continue;
    if (std::any_of(shoulders.begin(), shoulders.end(), [&](double z) { return std::abs(z - f.at) <= merge; })) continue;
    shoulders.push_back(f.at);
  }
  std::sort(shoulders.begin(), shoulders.end(), std::greater<>());  // nearest the right-hand end first
  const double rightReach = reachAt(zMax);
  for (double z : shoulders) dims.lengths.push_back({z, zMax, reachAt(z), rightReach});
  dims.lengths.push_back({zMin, zMax, reachAt(zMin), rightReach});
  return dims;
}

}  // namespace lathesim
