#include "geometry/triangle_mesh.hpp"

#include <unordered_map>

namespace lathesim {

double enclosedVolumeMm3(const TriangleMesh& mesh) {
  // Sum of signed tetrahedra against the origin; double accumulation because a
  // large part has millions of triangles whose terms mostly cancel.
  double sixTimesVolume = 0.0;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[t[0]].cast<double>();
    const Eigen::Vector3d b = mesh.vertices[t[1]].cast<double>();
    const Eigen::Vector3d c = mesh.vertices[t[2]].cast<double>();
    sixTimesVolume += a.dot(b.cross(c));
  }
  return sixTimesVolume / 6.0;
}

bool isClosedAndOriented(const TriangleMesh& mesh) {
  // A directed edge (a→b) must appear exactly once, and its reverse exactly once.
  std::unordered_map<std::uint64_t, int> directed;
  directed.reserve(mesh.triangles.size() * 3);
  auto key = [](std::uint32_t a, std::uint32_t b) { return (std::uint64_t{a} << 32) | b; };
  for (const auto& t : mesh.triangles) {
    for (int i = 0; i < 3; ++i) {
      if (t[i] == t[(i + 1) % 3]) return false;  // degenerate edge
      if (++directed[key(t[i], t[(i + 1) % 3])] > 1) return false;
    }
  }
  for (const auto& [edge, count] : directed) {
    const auto a = static_cast<std::uint32_t>(edge >> 32);
    const auto b = static_cast<std::uint32_t>(edge & 0xffffffffu);
    if (directed.find(key(b, a)) == directed.end()) return false;
  }
  return !mesh.triangles.empty();
}

}  // namespace lathesim
