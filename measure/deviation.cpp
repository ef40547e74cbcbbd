#include "measure/deviation.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace lathesim::measure {
namespace {

double ramp(double signedMm, double h) { return std::clamp(0.5 - signedMm / h, 0.0, 1.0); }

bool ignoredAt(const std::vector<ZRange>& ignored, double z) {
  return std::any_of(ignored.begin(), ignored.end(), [z](const ZRange& r) { return r.contains(z); });
}

void measureVolumes(const SampledSection& s, const MeridianProfile& drawing, const std::vector<ZRange>& ignored,
                    DeviationReport& report) {
  const double h = s.stepMm;
  for (int k = 0; k < s.zCount; ++k) {
    if (ignoredAt(ignored, s.zFirstMm + k * h)) continue;
    for (int i = 0; i < s.rCount; ++i) {
      const RZ p(i * h, s.zFirstMm + k * h);
      const double partInside = ramp(s.at(i, k), h);
      const double drawingInside = ramp(drawing.signedDistance(p).signedMm, h);
      // The ring of revolution the sample stands for; at the axis, the disc of radius h/2.
      const double weight = i == 0 ? M_PI * h * h * h / 4 : 2 * M_PI * p.x() * h * h;
      report.excessVolumeMm3 += std::max(0.0, partInside - drawingInside) * weight;
      report.gougeVolumeMm3 += std::max(0.0, drawingInside - partInside) * weight;
    }
  }
}

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int a) { return parent[a] == a ? a : parent[a] = find(parent[a]); }
  void join(int a, int b) { parent[find(a)] = find(b); }
};

std::vector<DeviationRegion> groupRegions(const std::vector<DeviationSample>& samples,
                                          const std::vector<std::optional<Band>>& bands, double uncertaintyMm,
                                          double linkMm) {
  std::vector<int> beyond;
  for (int n = 0; n < static_cast<int>(samples.size()); ++n)
    if (bands[n] && verdictOf(bands[n]->beyond(samples[n].mm), uncertaintyMm) != Verdict::Within) beyond.push_back(n);
  const auto midpoint = [&](int n) -> RZ { return (samples[n].at + samples[n].nearest) / 2; };
  const auto cellOf = [&](const RZ& p) {
    return std::pair<long, long>(static_cast<long>(std::floor(p.x() / linkMm)), static_cast<long>(std::floor(p.y() / linkMm)));
  };
  const auto key = [](long a, long b) { return a * 1000003L + b; };
  std::unordered_map<long, std::vector<int>> cells;  // index into `beyond`
  for (int m = 0; m < static_cast<int>(beyond.size()); ++m) {
    const auto [cr, cz] = cellOf(midpoint(beyond[m]));
    cells[key(cr, cz)].push_back(m);
  }
  UnionFind groups(static_cast<int>(beyond.size()));
  for (int m = 0; m < static_cast<int>(beyond.size()); ++m) {
    const RZ p = midpoint(beyond[m]);
    const bool gouge = samples[beyond[m]].mm < 0;
    const auto [cr, cz] = cellOf(p);
    for (long dr = -1; dr <= 1; ++dr)
      for (long dz = -1; dz <= 1; ++dz) {
        const auto found = cells.find(key(cr + dr, cz + dz));
        if (found == cells.end()) continue;
        for (int other : found->second)
          if ((samples[beyond[other]].mm < 0) == gouge && (midpoint(beyond[other]) - p).norm() <= linkMm)
            groups.join(m, other);
      }
  }
  std::unordered_map<int, DeviationRegion> byRoot;
  for (int m = 0; m < static_cast<int>(beyond.size()); ++m) {
    const DeviationSample& s = samples[beyond[m]];
    auto [it, fresh] = byRoot.try_emplace(groups.find(m));
    DeviationRegion& region = it->second;
    const Band& band = *bands[beyond[m]];
    if (fresh) {
      region.gouge = s.mm < 0;
      region.lower = s.at.cwiseMin(s.nearest);
      region.upper = s.at.cwiseMax(s.nearest);
      region.beyondMm = -INFINITY;
    }
    region.lower = region.lower.cwiseMin(s.at).cwiseMin(s.nearest);
    region.upper = region.upper.cwiseMax(s.at).cwiseMax(s.nearest);
    if (std::abs(s.mm) > region.maxMm) region.maxMm = std::abs(s.mm), region.at = s.at;
    if (band.beyond(s.mm) > region.beyondMm) {
      region.beyondMm = band.beyond(s.mm), region.band = band;
      region.worstAt = s.at, region.worstOnPart = s.onPart ? s.at : s.nearest;
    }
    region.midpoints.push_back(midpoint(beyond[m]));
  }
  std::vector<DeviationRegion> regions;
  for (auto& [root, region] : byRoot) {
    region.verdict = verdictOf(region.beyondMm, uncertaintyMm);
    regions.push_back(std::move(region));
  }
  std::sort(regions.begin(), regions.end(), [](const auto& a, const auto& b) { return a.beyondMm > b.beyondMm; });
  return regions;
}

}  // namespace

DeviationReport measureDeviation(const SampledSection& section, const MeridianProfile& part,
                                 const MeridianProfile& drawing, double toleranceMm, const std::vector<ZRange>& ignored) {
  DeviationReport report = measureDeviation(
      section, part, drawing, [&](const RZ&) { return std::optional<Band>(Band{-toleranceMm, toleranceMm}); }, 0.0,
      ignored);
  report.toleranceMm = toleranceMm;
  return report;
}

DeviationReport measureDeviation(const SampledSection& section, const MeridianProfile& part,
                                 const MeridianProfile& drawing, const BandAt& bandAt, double uncertaintyMm,
                                 const std::vector<ZRange>& ignored) {
  DeviationReport report;
  report.uncertaintyMm = uncertaintyMm;
  const double h = section.stepMm;
  // The polyline's vertices: each a zero crossing on a grid line, on the true surface.
  // (Most are the end of one segment and the start of the next, so some appear twice.)
  for (const Segment& s : part.surface()) {
    for (const RZ& p : {s.a, s.b}) {
      if (ignoredAt(ignored, p.y())) continue;
      const SurfaceDistance d = drawing.signedDistance(p);
      report.samples.push_back({p, d.nearest, d.signedMm});
    }
  }
  for (const Segment& s : drawing.surface()) {
    // A drawing that is itself a section (--target-program) is sampled at its vertices only,
    // like the part: its chords are not its surface.
    const int steps = std::max(1, static_cast<int>(std::ceil((s.b - s.a).norm() / (h / 2))));
    std::vector<RZ> points{s.a, s.b};
    if (!drawing.fromSamples()) {  // each segment's end is the next one's start
      points.clear();
      for (int n = 0; n < steps; ++n) points.push_back(s.a + (s.b - s.a) * (static_cast<double>(n) / steps));
    }
    for (const RZ& q : points) {
      if (ignoredAt(ignored, q.y())) continue;
      const SurfaceDistance d = part.signedDistance(q);
      report.samples.push_back({q, d.nearest, -d.signedMm, false});
    }
  }
  for (const DeviationSample& s : report.samples) {
    if (s.mm > report.maxExcessMm) report.maxExcessMm = s.mm, report.maxExcessAt = s.at;
    if (-s.mm > report.maxGougeMm) report.maxGougeMm = -s.mm, report.maxGougeAt = s.at;
  }
  measureVolumes(section, drawing, ignored, report);
  // Each sample's band by the drawing's point it is measured at: its own on the drawing's
  // side, its nearest on the part's.
  std::vector<std::optional<Band>> bands;
  bands.reserve(report.samples.size());
  for (std::size_t n = 0; n < report.samples.size(); ++n)
    bands.push_back(bandAt(report.samples[n].onPart ? report.samples[n].nearest : report.samples[n].at));
  report.regions = groupRegions(report.samples, bands, uncertaintyMm, 2 * h);
  return report;
}

}  // namespace lathesim::measure
