#include "geometry/triangle_mesh.hpp"

#include <algorithm>
#include <functional>
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

double surfaceAreaMm2(const TriangleMesh& mesh) {
  double twiceArea = 0.0;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[t[0]].cast<double>();
    twiceArea += (mesh.vertices[t[1]].cast<double>() - a).cross(mesh.vertices[t[2]].cast<double>() - a).norm();
  }
  return twiceArea / 2.0;
}

void weldCoincidentVertices(TriangleMesh& mesh) {
  struct PositionHash {
    std::size_t operator()(const std::array<float, 3>& p) const {
      std::size_t h = 0;
      for (float c : p) h = h * 0x9E3779B97F4A7C15ull + std::hash<float>()(c);
      return h;
    }
  };
  std::unordered_map<std::array<float, 3>, std::uint32_t, PositionHash> indexAt;
  indexAt.reserve(mesh.vertices.size());
  std::vector<Eigen::Vector3f> welded;
  welded.reserve(mesh.vertices.size());
  std::vector<std::uint32_t> newIndex(mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Eigen::Vector3f& p = mesh.vertices[v];
    // + 0.0f: -0 and +0 are one position
    const auto [at, added] = indexAt.try_emplace({p.x() + 0.0f, p.y() + 0.0f, p.z() + 0.0f},
                                                 static_cast<std::uint32_t>(welded.size()));
    if (added) welded.push_back(p);
    newIndex[v] = at->second;
  }
  for (auto& t : mesh.triangles)
    for (auto& corner : t) corner = newIndex[corner];
  mesh.vertices = std::move(welded);
}

std::size_t dropCollapsedTriangles(TriangleMesh& mesh) {
  const auto collapsed = [](const std::array<std::uint32_t, 3>& t) { return t[0] == t[1] || t[1] == t[2] || t[2] == t[0]; };
  const auto kept = std::remove_if(mesh.triangles.begin(), mesh.triangles.end(), collapsed);
  const auto dropped = static_cast<std::size_t>(mesh.triangles.end() - kept);
  mesh.triangles.erase(kept, mesh.triangles.end());
  return dropped;
}

bool isClosedAndOriented(const TriangleMesh& mesh) {
  // A directed edge (a→b) must appear exactly once, and its reverse exactly once. Each edge
  // is filed by its two ends, lower first, in `up` when it runs from the lower to the higher
  // and in `down` otherwise: then both lists hold no edge twice and hold the same edges.
  // (Sorted lists rather than a hash map: a mesh has millions of edges, and this is several
  // times faster.)
  std::vector<std::uint64_t> up, down;
  up.reserve(mesh.triangles.size() * 3 / 2 + 1);
  down.reserve(mesh.triangles.size() * 3 / 2 + 1);
  for (const auto& t : mesh.triangles) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = t[i], b = t[(i + 1) % 3];
      if (a == b) return false;  // degenerate edge
      if (a < b) up.push_back((std::uint64_t{a} << 32) | b);
      else down.push_back((std::uint64_t{b} << 32) | a);
    }
  }
  if (up.size() != down.size()) return false;
  std::sort(up.begin(), up.end());
  std::sort(down.begin(), down.end());
  return !mesh.triangles.empty() && std::adjacent_find(up.begin(), up.end()) == up.end() && up == down;
}

}  // namespace lathesim
