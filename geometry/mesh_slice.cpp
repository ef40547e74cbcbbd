#include "geometry/mesh_slice.hpp"

#include <array>
#include <cmath>

namespace lathesim {
namespace {

constexpr double kOnPlaneMm = 1e-6;

}  // namespace

std::vector<Segment> meridianSlice(const TriangleMesh& mesh) {
  std::vector<Segment> slice;
  for (const auto& t : mesh.triangles) {
    std::array<Eigen::Vector3d, 3> v;
    for (int c = 0; c < 3; ++c) v[c] = mesh.vertices[t[c]].cast<double>();
    // A vertex on the plane counts as y ≥ 0, so a vertex shared by triangles on both sides
    // yields one crossing per triangle edge, never two. "On the plane" allows for rounding:
    // an exporter's vertex at angle 2π lands a few 1e-15 off it.
    for (auto& p : v)
      if (std::abs(p.y()) < kOnPlaneMm) p.y() = 0;
    std::vector<RZ> crossings;
    for (int e = 0; e < 3; ++e) {
      const Eigen::Vector3d& a = v[e];
      const Eigen::Vector3d& b = v[(e + 1) % 3];
      if ((a.y() < 0) == (b.y() < 0)) continue;
      const double s = a.y() / (a.y() - b.y());
      const Eigen::Vector3d p = a + s * (b - a);
      crossings.emplace_back(p.x(), p.z());
    }
    if (crossings.size() != 2) continue;
    RZ a = crossings[0], b = crossings[1];
    if (a.x() < 0 && b.x() < 0) continue;  // the other half-plane
    if (a.x() < 0 || b.x() < 0) {          // reaches across the axis: keep the x ≥ 0 part
      const RZ onAxis = a + (b - a) * (a.x() / (a.x() - b.x()));
      (a.x() < 0 ? a : b) = RZ(0.0, onAxis.y());
    }
    if (a != b) slice.push_back({a, b});
  }
  return slice;
}

}  // namespace lathesim
