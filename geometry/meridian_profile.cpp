#include "geometry/meridian_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lathesim {
namespace {

constexpr double kAxisMm = 1e-9;  // an edge with both ends this close to r = 0 lies on the axis
constexpr int kBinsAcross = 96;   // bins along the longer side of the surface's bounds

double segmentDistanceSquared(const Segment& s, const RZ& p, RZ& nearest) {
  const RZ d = s.b - s.a;
  const double lengthSquared = d.squaredNorm();
  const double t = lengthSquared > 0 ? std::clamp((p - s.a).dot(d) / lengthSquared, 0.0, 1.0) : 0.0;
  nearest = s.a + t * d;
  return (p - nearest).squaredNorm();
}

/// The zero crossing between two samples of opposite sign, by linear interpolation.
RZ crossing(const RZ& a, float phiA, const RZ& b, float phiB) {
  const double t = static_cast<double>(phiA) / (static_cast<double>(phiA) - static_cast<double>(phiB));
  return a + t * (b - a);
}

}  // namespace

MeridianProfile MeridianProfile::fromPolygon(std::vector<RZ> points) {
  MeridianProfile profile;
  if (points.size() > 2 && points.front() == points.back()) {
    points.pop_back();
  } else if (!points.empty()) {
    if (std::abs(points.front().x()) > kAxisMm) points.insert(points.begin(), RZ(0.0, points.front().y()));
    if (std::abs(points.back().x()) > kAxisMm) points.push_back(RZ(0.0, points.back().y()));
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    const RZ& a = points[i];
    const RZ& b = points[(i + 1) % points.size()];
    const bool onAxis = std::abs(a.x()) <= kAxisMm && std::abs(b.x()) <= kAxisMm;
    if (!onAxis && a != b) profile.surface_.push_back({a, b});
  }
  profile.indexSurface();
  return profile;
}

MeridianProfile MeridianProfile::fromSurface(std::vector<Segment> surface) {
  MeridianProfile profile;
  for (Segment& s : surface)
    if (!(std::abs(s.a.x()) <= kAxisMm && std::abs(s.b.x()) <= kAxisMm) && s.a != s.b) profile.surface_.push_back(s);
  profile.indexSurface();
  return profile;
}

MeridianProfile MeridianProfile::fromSection(SampledSection section) {
  MeridianProfile profile;
  const double h = section.stepMm;
  auto position = [&](int i, int k) { return RZ(i * h, section.zFirstMm + k * h); };
  // Marching squares: each cell's corners in the order (i,k) (i+1,k) (i+1,k+1) (i,k+1); the
  // crossings on its edges, walked in that order, pair up into surface segments.
  for (int k = 0; k + 1 < section.zCount; ++k) {
    for (int i = 0; i + 1 < section.rCount; ++i) {
      const int ci[4] = {i, i + 1, i + 1, i};
      const int ck[4] = {k, k, k + 1, k + 1};
      float v[4];
      for (int c = 0; c < 4; ++c) v[c] = section.at(ci[c], ck[c]);
      RZ points[4];
      int count = 0;
      for (int e = 0; e < 4; ++e) {
        const int f = (e + 1) % 4;
        if ((v[e] < 0) != (v[f] < 0))
          points[count++] = crossing(position(ci[e], ck[e]), v[e], position(ci[f], ck[f]), v[f]);
      }
      if (count == 2) {
        profile.surface_.push_back({points[0], points[1]});
      } else if (count == 4) {
        // A saddle: the cell's mean decides whether the inside corners connect.
        const bool centreInside = (v[0] + v[1] + v[2] + v[3]) < 0;
        const bool firstCornerInside = v[0] < 0;
        if (centreInside == firstCornerInside) {
          profile.surface_.push_back({points[0], points[3]});
          profile.surface_.push_back({points[1], points[2]});
        } else {
          profile.surface_.push_back({points[0], points[1]});
          profile.surface_.push_back({points[2], points[3]});
        }
      }
    }
  }
  profile.section_ = std::move(section);
  profile.indexSurface();
  return profile;
}

void MeridianProfile::indexSurface() {
  if (surface_.empty()) return;
  lower_ = surface_.front().a;
  upper_ = lower_;
  for (const Segment& s : surface_) {
    lower_ = lower_.cwiseMin(s.a).cwiseMin(s.b);
    upper_ = upper_.cwiseMax(s.a).cwiseMax(s.b);
  }
  const RZ extent = upper_ - lower_;
  binMm_ = std::max(extent.maxCoeff() / kBinsAcross, 1e-3);
  binsR_ = static_cast<int>(extent.x() / binMm_) + 1;
  binsZ_ = static_cast<int>(extent.y() / binMm_) + 1;
  bins_.assign(static_cast<std::size_t>(binsR_) * binsZ_, {});
  auto binOf = [&](double v, double origin, int count) {
    return std::clamp(static_cast<int>((v - origin) / binMm_), 0, count - 1);
  };
  for (int n = 0; n < static_cast<int>(surface_.size()); ++n) {
    const Segment& s = surface_[n];
    const int r0 = binOf(std::min(s.a.x(), s.b.x()), lower_.x(), binsR_);
    const int r1 = binOf(std::max(s.a.x(), s.b.x()), lower_.x(), binsR_);
    const int z0 = binOf(std::min(s.a.y(), s.b.y()), lower_.y(), binsZ_);
    const int z1 = binOf(std::max(s.a.y(), s.b.y()), lower_.y(), binsZ_);
    for (int bz = z0; bz <= z1; ++bz)
      for (int br = r0; br <= r1; ++br) bins_[static_cast<std::size_t>(bz) * binsR_ + br].push_back(n);
  }
}

std::optional<double> MeridianProfile::interpolatedPhi(const RZ& p, bool withinBandOnly) const {
  const SampledSection& s = *section_;
  const double u = p.x() / s.stepMm;
  const double w = (p.y() - s.zFirstMm) / s.stepMm;
  const int i = static_cast<int>(std::floor(u));
  const int k = static_cast<int>(std::floor(w));
  if (i < 0 || k < 0 || i + 1 >= s.rCount || k + 1 >= s.zCount) return std::nullopt;
  const float corners[4] = {s.at(i, k), s.at(i + 1, k), s.at(i + 1, k + 1), s.at(i, k + 1)};
  const double fu = u - i, fw = w - k;
  const double weights[4] = {(1 - fu) * (1 - fw), fu * (1 - fw), fu * fw, (1 - fu) * fw};
  double value = 0;
  for (int c = 0; c < 4; ++c) {
    if (weights[c] < 1e-9) continue;  // on a grid line or a sample: only the samples it lies between count
    if (withinBandOnly && std::abs(corners[c]) >= 0.999 * s.clampMm) return std::nullopt;
    value += weights[c] * corners[c];
  }
  return value;
}

bool MeridianProfile::contains(const RZ& p) const {
  if (section_) {
    const auto value = interpolatedPhi(p, false);
    return value && *value < 0;
  }
  // Crossing number along the ray from p away from the axis (+r): the axis edges that close
  // the outline lie behind it, so the surface alone decides. (Every segment is tested: the
  // bins would save little for the few hundred edges of a drawing.)
  bool inside = false;
  for (const Segment& s : surface_) {
    if ((s.a.y() > p.y()) != (s.b.y() > p.y())) {
      const double rAtZ = s.a.x() + (p.y() - s.a.y()) / (s.b.y() - s.a.y()) * (s.b.x() - s.a.x());
      if (p.x() < rAtZ) inside = !inside;
    }
  }
  return inside;
}

SurfaceDistance MeridianProfile::signedDistance(const RZ& p) const {
  const double sign = contains(p) ? -1.0 : 1.0;
  SurfaceDistance result{sign * std::numeric_limits<double>::infinity(), p};
  if (surface_.empty()) return result;
  // Search rings of bins outwards from p's bin until no unsearched bin can be nearer.
  const int startR = std::clamp(static_cast<int>(std::floor((p.x() - lower_.x()) / binMm_)), 0, binsR_ - 1);
  const int startZ = std::clamp(static_cast<int>(std::floor((p.y() - lower_.y()) / binMm_)), 0, binsZ_ - 1);
  double bestSquared = std::numeric_limits<double>::infinity();
  const int maxRing = std::max(binsR_, binsZ_);
  for (int ring = 0; ring <= maxRing; ++ring) {
    for (int bz = startZ - ring; bz <= startZ + ring; ++bz) {
      if (bz < 0 || bz >= binsZ_) continue;
      const bool edgeRow = bz == startZ - ring || bz == startZ + ring;
      for (int br = startR - ring; br <= startR + ring; br += edgeRow ? 1 : 2 * std::max(ring, 1)) {
        if (br < 0 || br >= binsR_) continue;
        for (int n : bins_[static_cast<std::size_t>(bz) * binsR_ + br]) {
          RZ nearest;
          const double d2 = segmentDistanceSquared(surface_[n], p, nearest);
          if (d2 < bestSquared) bestSquared = d2, result.nearest = nearest;
        }
      }
    }
    // Everything not yet searched lies outside the box of bins searched so far.
    const double boxLoR = lower_.x() + (startR - ring) * binMm_, boxHiR = lower_.x() + (startR + ring + 1) * binMm_;
    const double boxLoZ = lower_.y() + (startZ - ring) * binMm_, boxHiZ = lower_.y() + (startZ + ring + 1) * binMm_;
    const double clearance = std::min({p.x() - boxLoR, boxHiR - p.x(), p.y() - boxLoZ, boxHiZ - p.y()});
    if (clearance > 0 && bestSquared <= clearance * clearance) break;
  }
  result.signedMm = sign * std::sqrt(bestSquared);
  if (section_)
    if (const auto phi = interpolatedPhi(p, true)) result.signedMm = *phi;
  return result;
}

}  // namespace lathesim
