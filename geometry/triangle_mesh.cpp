#include "geometry/triangle_mesh.hpp"

#include <algorithm>
#include <tuple>

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
  // The vertices sorted by position, and by index among equal positions: each run of equal
  // positions becomes its first vertex, and the vertices kept keep their order. (A sort
  // rather than a hash map of positions: a part has millions of vertices, and the map's
  // allocation per entry made it several times slower.)
  struct Keyed {
    float x, y, z;
    std::uint32_t index;
  };
  std::vector<Keyed> sorted(mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Eigen::Vector3f& p = mesh.vertices[v];
    sorted[v] = {p.x() + 0.0f, p.y() + 0.0f, p.z() + 0.0f, static_cast<std::uint32_t>(v)};  // + 0.0f: -0 is +0
  }
  std::sort(sorted.begin(), sorted.end(), [](const Keyed& a, const Keyed& b) {
    return std::tie(a.x, a.y, a.z, a.index) < std::tie(b.x, b.y, b.z, b.index);
  });
  std::vector<std::uint32_t> firstOf(mesh.vertices.size());  // the first vertex at each one's position
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    const bool samePlace = i > 0 && sorted[i].x == sorted[i - 1].x && sorted[i].y == sorted[i - 1].y &&
                           sorted[i].z == sorted[i - 1].z;
    firstOf[sorted[i].index] = samePlace ? firstOf[sorted[i - 1].index] : sorted[i].index;
  }
  std::vector<std::uint32_t> newIndex(mesh.vertices.size());
  std::vector<Eigen::Vector3f> welded;
  welded.reserve(mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (firstOf[v] == v) {
      newIndex[v] = static_cast<std::uint32_t>(welded.size());
      welded.push_back(mesh.vertices[v]);
    } else {
      newIndex[v] = newIndex[firstOf[v]];  // an earlier vertex: already numbered
    }
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
  // A directed edge (a→b) must appear exactly once, and its reverse exactly once. Each
  // vertex's outgoing edges are gathered by a counting sort (its few neighbours, in linear
  // time: several times faster than sorting a part's millions of edges); then no vertex may
  // list a neighbour twice, and b must list a wherever a lists b.
  if (mesh.triangles.empty()) return false;
  std::uint32_t highest = 0;
  for (const auto& t : mesh.triangles) highest = std::max({highest, t[0], t[1], t[2]});
  std::vector<std::size_t> first(std::size_t{highest} + 2, 0);  // vertex v's edges: first[v] … first[v + 1]
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      if (t[i] == t[(i + 1) % 3]) return false;  // degenerate edge
      ++first[std::size_t{t[i]} + 1];
    }
  for (std::size_t v = 1; v < first.size(); ++v) first[v] += first[v - 1];
  std::vector<std::uint32_t> to(first.back());
  std::vector<std::size_t> next(first.begin(), first.end() - 1);
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) to[next[t[i]]++] = t[(i + 1) % 3];
  for (std::size_t a = 0; a + 1 < first.size(); ++a)
    for (std::size_t e = first[a]; e < first[a + 1]; ++e) {
      const std::uint32_t b = to[e];
      if (std::find(to.begin() + first[a], to.begin() + e, b) != to.begin() + e) return false;  // a→b twice
      if (std::find(to.begin() + first[b], to.begin() + first[b + 1], a) == to.begin() + first[b + 1])
        return false;  // no b→a
    }
  return true;
}

}  // namespace lathesim
