#include "geometry/profile_polylines.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace lathesim {
namespace {

struct EndKey {
  std::int64_t r, z;
  bool operator==(const EndKey&) const = default;
};
struct EndKeyHash {
  std::size_t operator()(const EndKey& k) const {
    return std::hash<std::int64_t>()(k.r) ^ (std::hash<std::int64_t>()(k.z) * 0x9E3779B97F4A7C15ULL);
  }
};

void simplifyRange(const std::vector<RZ>& points, std::size_t first, std::size_t last, double tolerance,
                   std::vector<bool>& keep) {
  if (last <= first + 1) return;
  const RZ a = points[first], b = points[last];
  const RZ ab = b - a;
  const double length = ab.norm();
  double farthest = -1;
  std::size_t at = first;
  for (std::size_t i = first + 1; i < last; ++i) {
    const RZ ap = points[i] - a;
    const double d = length > 0 ? std::abs(ab.x() * ap.y() - ab.y() * ap.x()) / length : ap.norm();
    if (d > farthest) farthest = d, at = i;
  }
  if (farthest <= tolerance) return;
  keep[at] = true;
  simplifyRange(points, first, at, tolerance, keep);
  simplifyRange(points, at, last, tolerance, keep);
}

/// Is the material on the right of the polyline? Asked at its longest segment, a little to
/// each side of its middle (a hundredth of its length, at most `probeMm`).
bool materialOnRight(const std::vector<RZ>& line, const MeridianProfile& profile, double probeMm) {
  std::size_t longest = 0;
  for (std::size_t i = 1; i + 1 < line.size(); ++i)
    if ((line[i + 1] - line[i]).squaredNorm() > (line[longest + 1] - line[longest]).squaredNorm()) longest = i;
  const RZ a = line[longest], b = line[longest + 1];
  const RZ along = b - a;
  const double length = along.norm();
  if (length == 0) return true;
  const RZ right = RZ(along.y(), -along.x()) / length;  // r across, z up: (dr, dz) turned clockwise
  const double step = std::min(probeMm, 0.01 * length);
  const RZ middle = 0.5 * (a + b);
  const bool rightInside = profile.contains(middle + step * right);
  const bool leftInside = profile.contains(middle - step * right);
  return rightInside || !leftInside;
}

}  // namespace

std::vector<std::vector<RZ>> chainSegments(const std::vector<Segment>& segments, double weldMm) {
  const double scale = 1.0 / std::max(weldMm, 1e-12);
  auto key = [&](const RZ& p) { return EndKey{std::llround(p.x() * scale), std::llround(p.y() * scale)}; };
  std::unordered_map<EndKey, std::vector<std::size_t>, EndKeyHash> ends;  // key → 2·segment + end
  ends.reserve(2 * segments.size());
  // A segment whose ends weld together is no segment (marching squares makes one where a
  // sample lies exactly on the surface): it is left out, and its ends are one point.
  std::vector<bool> used(segments.size(), false);
  for (std::size_t s = 0; s < segments.size(); ++s) {
    if (key(segments[s].a) == key(segments[s].b)) {
      used[s] = true;
      continue;
    }
    ends[key(segments[s].a)].push_back(2 * s);
    ends[key(segments[s].b)].push_back(2 * s + 1);
  }
  auto endPoint = [&](std::size_t end) { return end % 2 ? segments[end / 2].b : segments[end / 2].a; };
  // From `end`'s point, walk on through the other end of each unused segment met there.
  auto walk = [&](std::size_t end, std::vector<RZ>& line) {
    for (;;) {
      const auto& here = ends[key(endPoint(end))];
      if (here.size() != 2) return;  // a chain's end, or a junction
      const std::size_t next = here[0] / 2 == end / 2 ? here[1] : here[0];
      if (used[next / 2]) return;
      used[next / 2] = true;
      end = next ^ 1;  // the segment's far end
      line.push_back(endPoint(end));
    }
  };
  std::vector<std::vector<RZ>> lines;
  auto chainFrom = [&](std::size_t end) {
    used[end / 2] = true;
    std::vector<RZ> line{endPoint(end), endPoint(end ^ 1)};
    walk(end ^ 1, line);
    std::vector<RZ> back;
    walk(end, back);  // the other way, when `end` was not a chain's end
    std::reverse(back.begin(), back.end());
    back.insert(back.end(), line.begin(), line.end());
    // A loop ends where it began: exactly, so that it reads as closed.
    if (back.size() > 2 && key(back.front()) == key(back.back())) back.back() = back.front();
    lines.push_back(std::move(back));
  };
  // Open chains first, from their ends, so that none is cut in two; then the loops.
  for (std::size_t s = 0; s < segments.size(); ++s)
    for (std::size_t end : {2 * s, 2 * s + 1})
      if (!used[s] && ends[key(endPoint(end))].size() != 2) chainFrom(end);
  for (std::size_t s = 0; s < segments.size(); ++s)
    if (!used[s]) chainFrom(2 * s);
  return lines;
}

std::vector<RZ> simplifyPolyline(const std::vector<RZ>& points, double toleranceMm) {
  if (points.size() <= 2) return points;
  std::vector<bool> keep(points.size(), false);
  keep.front() = keep.back() = true;
  std::size_t last = points.size() - 1;
  if ((points.front() - points.back()).norm() == 0.0) {
    // A loop: split it at its point farthest from the start, so both halves have a chord.
    std::size_t far = 0;
    for (std::size_t i = 1; i < last; ++i)
      if ((points[i] - points[0]).squaredNorm() > (points[far] - points[0]).squaredNorm()) far = i;
    keep[far] = true;
    simplifyRange(points, 0, far, toleranceMm, keep);
    simplifyRange(points, far, last, toleranceMm, keep);
  } else {
    simplifyRange(points, 0, last, toleranceMm, keep);
  }
  std::vector<RZ> kept;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (keep[i]) kept.push_back(points[i]);
  return kept;
}

std::vector<std::vector<RZ>> profilePolylines(const MeridianProfile& profile, double toleranceMm) {
  // Marching squares computes a crossing shared by two cells from either side: equal to far
  // below a micrometre.
  std::vector<std::vector<RZ>> lines = chainSegments(profile.surface(), 1e-6);
  for (auto& line : lines) {
    line = simplifyPolyline(line, toleranceMm);
    if (!materialOnRight(line, profile, toleranceMm)) std::reverse(line.begin(), line.end());
  }
  return lines;
}

}  // namespace lathesim
