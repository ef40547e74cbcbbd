#include "geometry/revolved_mesh.hpp"

#include <algorithm>
#include <cmath>

namespace lathesim {
namespace {

constexpr double kOnAxisMm = 1e-9;

}  // namespace

TriangleMesh revolvedMesh(const std::vector<std::vector<RZ>>& polylines, int angularSteps) {
  const int n = std::max(angularSteps, 3);
  std::vector<double> cosines(n), sines(n);
  for (int k = 0; k < n; ++k) cosines[k] = std::cos(2.0 * M_PI * k / n), sines[k] = std::sin(2.0 * M_PI * k / n);
  TriangleMesh mesh;
  for (const auto& line : polylines) {
    // A loop's last point repeats its first: it joins the first ring, so the mesh stays
    // closed, and has no ring of its own (two vertices at one point).
    const bool loop = line.size() > 2 && line.front() == line.back();
    // The first vertex of each point's ring (one vertex for a point on the axis).
    std::vector<std::uint32_t> ring(line.size());
    for (std::size_t i = 0; i < line.size(); ++i) {
      ring[i] = static_cast<std::uint32_t>(mesh.vertices.size());
      if (loop && i + 1 == line.size()) {
        ring[i] = ring[0];
        continue;
      }
      const RZ& p = line[i];
      if (p.x() <= kOnAxisMm) {
        mesh.vertices.emplace_back(0.0f, 0.0f, static_cast<float>(p.y()));
        continue;
      }
      for (int k = 0; k < n; ++k)
        mesh.vertices.emplace_back(static_cast<float>(p.x() * cosines[k]), static_cast<float>(p.x() * sines[k]),
                                   static_cast<float>(p.y()));
    }
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      const bool aAxis = line[i].x() <= kOnAxisMm, bAxis = line[i + 1].x() <= kOnAxisMm;
      if (aAxis && bAxis) continue;  // along the axis: no surface
      const std::uint32_t a = ring[i], b = ring[i + 1];
      for (int k = 0; k < n; ++k) {
        const int next = (k + 1) % n;
        // Corners (s, θ): (a, k) (b, k) (b, k+1) (a, k+1), counter-clockwise from outside
        // when the material is on the polyline's right (revolved_mesh.hpp).
        const std::uint32_t a0 = aAxis ? a : a + k, a1 = aAxis ? a : a + next;
        const std::uint32_t b0 = bAxis ? b : b + k, b1 = bAxis ? b : b + next;
        if (!bAxis) mesh.triangles.push_back({a0, b0, b1});
        if (!aAxis) mesh.triangles.push_back({a0, b1, a1});
      }
    }
  }
  return mesh;
}

int angularStepsFor(double radiusMm, double toleranceMm) {
  if (!(radiusMm > toleranceMm) || !(toleranceMm > 0)) return 12;
  // A chord across the angle 2π/n strays r·(1 − cos(π/n)) from the circle.
  const double half = std::acos(1.0 - toleranceMm / radiusMm);
  return std::max(12, static_cast<int>(std::ceil(M_PI / half)));
}

}  // namespace lathesim
