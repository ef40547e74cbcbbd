#include "geometry/mesh_shells.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace lathesim {
namespace {

// Union-find over vertices, with path halving.
class Components {
 public:
  explicit Components(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::uint32_t{0}); }
  std::uint32_t find(std::uint32_t v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }
  void unite(std::uint32_t a, std::uint32_t b) { parent_[find(a)] = find(b); }

 private:
  std::vector<std::uint32_t> parent_;
};

}  // namespace

std::vector<Shell> shellsOf(const TriangleMesh& mesh) {
  Components components(mesh.vertices.size());
  for (const auto& t : mesh.triangles) {
    components.unite(t[0], t[1]);
    components.unite(t[1], t[2]);
  }
  std::vector<Shell> shells;
  std::vector<std::int64_t> shellOfRoot(mesh.vertices.size(), -1);
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    std::int64_t& shell = shellOfRoot[components.find(t[0])];
    if (shell < 0) {
      shell = static_cast<std::int64_t>(shells.size());
      shells.emplace_back();
    }
    Shell& s = shells[static_cast<std::size_t>(shell)];
    s.triangles.push_back(i);
    const Eigen::Vector3d a = mesh.vertices[t[0]].cast<double>();
    const Eigen::Vector3d b = mesh.vertices[t[1]].cast<double>();
    const Eigen::Vector3d c = mesh.vertices[t[2]].cast<double>();
    s.volumeMm3 += a.dot(b.cross(c)) / 6.0;
    s.areaMm2 += (b - a).cross(c - a).norm() / 2.0;
  }
  return shells;
}

DroppedCrumbs dropCrumbs(TriangleMesh& mesh, double thicknessMm) {
  const std::vector<Shell> shells = shellsOf(mesh);
  // The largest shell is the part, however thin.
  const auto largest = std::max_element(shells.begin(), shells.end(),
                                        [](const Shell& a, const Shell& b) { return a.volumeMm3 < b.volumeMm3; });
  DroppedCrumbs dropped;
  std::vector<char> drop(mesh.triangles.size(), 0);
  for (auto shell = shells.begin(); shell != shells.end(); ++shell) {
    if (shell == largest || 2.0 * std::abs(shell->volumeMm3) >= thicknessMm * shell->areaMm2) continue;
    ++dropped.count;
    dropped.volumeMm3 += shell->volumeMm3;
    for (std::size_t t : shell->triangles) drop[t] = 1;
  }
  std::size_t kept = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (!drop[t]) mesh.triangles[kept++] = mesh.triangles[t];
  mesh.triangles.resize(kept);
  return dropped;
}

}  // namespace lathesim
