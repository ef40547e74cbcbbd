#include "render/machine_meshes.hpp"

#include <cmath>

#include "geometry/revolved_mesh.hpp"

namespace lathesim::render {
namespace {

constexpr int kRoundSteps = 96;  // facets around the tailstock, as around the chuck body

void addQuad(TriangleMesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
  mesh.triangles.push_back({a, b, c});
  mesh.triangles.push_back({a, c, d});
}

}  // namespace

TriangleMesh jawsMesh(const ChuckPicture& c) {
  TriangleMesh mesh;
  const double half = kJawHalfWidthPerRadius * c.jawOuterRadiusMm;
  for (int jaw = 0; jaw < 3; ++jaw) {
    const double a = jaw * 2.0 * M_PI / 3.0;
    const Eigen::Vector3d out(std::cos(a), std::sin(a), 0), side(-std::sin(a), std::cos(a), 0);
    const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
    // Corner index = 4·(z high) + 2·(r outer) + (side +).
    for (double z : {c.jawZLowMm, c.jawZHighMm})
      for (double r : {c.jawInnerRadiusMm, c.jawOuterRadiusMm})
        for (double s : {-half, half}) mesh.vertices.push_back((out * r + side * s + Eigen::Vector3d(0, 0, z)).cast<float>());
    Eigen::Vector3f centre = Eigen::Vector3f::Zero();
    for (std::uint32_t k = 0; k < 8; ++k) centre += mesh.vertices[first + k] / 8.0f;
    // Each face's corners in order round it, turned to face away from the box's centre.
    const std::uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}};
    for (const auto& f : faces) {
      const Eigen::Vector3f& p0 = mesh.vertices[first + f[0]];
      const Eigen::Vector3f normal = (mesh.vertices[first + f[1]] - p0).cross(mesh.vertices[first + f[2]] - p0);
      const Eigen::Vector3f faceCentre =
          (p0 + mesh.vertices[first + f[1]] + mesh.vertices[first + f[2]] + mesh.vertices[first + f[3]]) / 4.0f;
      if (normal.dot(faceCentre - centre) > 0) addQuad(mesh, first + f[0], first + f[1], first + f[2], first + f[3]);
      else addQuad(mesh, first + f[3], first + f[2], first + f[1], first + f[0]);
    }
  }
  return mesh;
}

TriangleMesh tailstockMesh(const TailstockPicture& t) {
  // The material on the right (revolved_mesh.hpp): out at the quill's far end, down its
  // outside, along the cone to the point.
  const double zCone = t.coneEndZMm(), zEnd = zCone + t.quillLengthMm;
  return revolvedMesh({{{0, zEnd}, {t.quillRadiusMm, zEnd}, {t.quillRadiusMm, zCone}, {0, t.pointZMm}}}, kRoundSteps);
}

TriangleMesh slabMesh(const std::vector<RZ>& outline, const RZ& position, double yLow, double yHigh) {
  TriangleMesh mesh;
  const auto n = static_cast<std::uint32_t>(outline.size());
  if (n < 3) return mesh;
  for (double y : {yLow, yHigh})
    for (const RZ& p : outline)
      mesh.vertices.emplace_back(static_cast<float>(position.x() + p.x()), static_cast<float>(y),
                                 static_cast<float>(position.y() + p.y()));
  // The outline (r, z) counter-clockwise is clockwise seen from +y (x = r, z across): the
  // high cap reversed, the low cap as it is; a convex outline's caps are fans.
  double area = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    const RZ& a = outline[i];
    const RZ& b = outline[(i + 1) % n];
    area += a.x() * b.y() - b.x() * a.y();
  }
  const bool ccw = area > 0;
  for (std::uint32_t i = 1; i + 1 < n; ++i) {
    if (ccw) {
      mesh.triangles.push_back({0, i, i + 1});
      mesh.triangles.push_back({n, n + i + 1, n + i});
    } else {
      mesh.triangles.push_back({0, i + 1, i});
      mesh.triangles.push_back({n, n + i, n + i + 1});
    }
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    if (ccw) addQuad(mesh, i, n + i, n + j, j);
    else addQuad(mesh, i, j, n + j, n + i);
  }
  return mesh;
}

}  // namespace lathesim::render
