#pragma once
// Meshes and toolpaths the render tests draw and write.

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include "geometry/triangle_mesh.hpp"
#include "interp/base/move.hpp"

namespace lathesim::render::test {

/// A closed cylinder about the Z axis, radius `radiusMm`, from z = 0 to `lengthMm`, with
/// `segments` facets around and `rings` bands along; counter-clockwise seen from outside.
inline TriangleMesh cylinder(double radiusMm, double lengthMm, int segments, int rings = 1) {
  TriangleMesh mesh;
  auto vertex = [&](int ring, int k) {
    return static_cast<std::uint32_t>(ring * segments + (k % segments));
  };
  for (int ring = 0; ring <= rings; ++ring) {
    const double z = lengthMm * ring / rings;
    for (int k = 0; k < segments; ++k) {
      const double a = 2.0 * M_PI * k / segments;
      mesh.vertices.emplace_back(radiusMm * std::cos(a), radiusMm * std::sin(a), z);
    }
  }
  for (int ring = 0; ring < rings; ++ring) {
    for (int k = 0; k < segments; ++k) {
      const auto a = vertex(ring, k), b = vertex(ring, k + 1);
      const auto c = vertex(ring + 1, k + 1), d = vertex(ring + 1, k);
      mesh.triangles.push_back({a, b, c});
      mesh.triangles.push_back({a, c, d});
    }
  }
  // End caps: a centre vertex each; z = 0 faces −Z, z = length faces +Z.
  const auto bottom = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.emplace_back(0.0f, 0.0f, 0.0f);
  const auto top = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.emplace_back(0.0f, 0.0f, static_cast<float>(lengthMm));
  for (int k = 0; k < segments; ++k) {
    mesh.triangles.push_back({bottom, vertex(0, k + 1), vertex(0, k)});
    mesh.triangles.push_back({top, vertex(rings, k), vertex(rings, k + 1)});
  }
  return mesh;
}

/// The closed solid swept by the profile (r, z) about the Z axis. The profile starts and
/// ends on the axis (r = 0) and runs with the material on its left going −Z → +Z along the
/// outside, e.g. (0,0) (30,0) (30,60) (0,60). Each profile edge is cut into `pieces`.
inline TriangleMesh revolved(const std::vector<RZ>& profile, int segments, int pieces = 1) {
  std::vector<RZ> points;
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    for (int j = 0; j < pieces; ++j) {
      points.push_back(profile[i] + (profile[i + 1] - profile[i]) * (double(j) / pieces));
    }
  }
  points.push_back(profile.back());
  TriangleMesh mesh;
  std::vector<std::uint32_t> first;  // index of each profile point's first vertex
  for (const RZ& p : points) {
    first.push_back(static_cast<std::uint32_t>(mesh.vertices.size()));
    const int copies = p.x() == 0.0 ? 1 : segments;
    for (int k = 0; k < copies; ++k) {
      const double a = 2.0 * M_PI * k / segments;
      mesh.vertices.emplace_back(p.x() * std::cos(a), p.x() * std::sin(a), p.y());
    }
  }
  auto at = [&](std::size_t i, int k) {
    return points[i].x() == 0.0 ? first[i] : first[i] + static_cast<std::uint32_t>(k % segments);
  };
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    for (int k = 0; k < segments; ++k) {
      const auto a = at(i, k), b = at(i, k + 1), c = at(i + 1, k + 1), d = at(i + 1, k);
      if (a != b && b != c && c != a) mesh.triangles.push_back({a, b, c});
      if (a != c && c != d && d != a) mesh.triangles.push_back({a, c, d});
    }
  }
  return mesh;
}

inline interp::Move move(interp::MoveKind kind, double r0, double z0, double r1, double z1,
                         int line, double feed) {
  interp::Move m;
  m.kind = kind;
  m.from = RZ(r0, z0);
  m.to = RZ(r1, z1);
  m.line = line;
  m.feed = feed;
  return m;
}

/// One rapid approach above the bar's free end (+Z), then one feed along it.
inline interp::Toolpath rapidThenFeed() {
  interp::Toolpath path;
  path.programName = "test.nc";
  path.moves.push_back(move(interp::MoveKind::Rapid, 45, 80, 29, 62, 3, 0.0));
  path.moves.push_back(move(interp::MoveKind::Feed, 29, 62, 29, 10, 4, 0.2));
  return path;
}

/// A unique scratch directory, removed with everything in it when this goes out of scope.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
    path_ = std::filesystem::temp_directory_path() /
            ("lathesim-render-test-" + std::to_string(::getpid()) + "-" +
             std::to_string(stamp) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace lathesim::render::test
