#include "measure/volume_checks.hpp"

#include <cmath>
#include <vector>

#include <tbb/parallel_for.h>

#include <fmt/format.h>

#include "sim/stock.hpp"

namespace lathesim::measure {

std::optional<std::string> barVolumeProblem(const sim::StockSpec& bar, double levelSetMm3, double voxelMm) {
  const double exact = sim::exactVolumeMm3(bar);
  const double tolerance = sim::volumeToleranceMm3(sim::surfaceAreaMm2(bar), voxelMm);
  if (std::abs(levelSetMm3 - exact) <= tolerance) return std::nullopt;
  const std::string bore = bar.boreMm > 0.0 ? fmt::format(" (bore Φ{:g})", bar.boreMm) : "";
  return fmt::format(
      "the bar's level set holds {:.1f} mm³ where the Φ{:g}×{:g}{} bar is {:.1f} mm³, {:+.1f} mm³ off, beyond the "
      "{:.1f} mm³ tolerance: the volumes in this report are not to be trusted",
      levelSetMm3, bar.diameterMm, bar.lengthMm, bore, exact, levelSetMm3 - exact, tolerance);
}

namespace {

std::optional<std::string> volumeProblem(double levelSetMm3, double meshMm3, double meshAreaMm2, double voxelMm,
                                         std::string_view solid) {
  const double tolerance = sim::volumeToleranceMm3(meshAreaMm2, voxelMm);
  if (std::abs(levelSetMm3 - meshMm3) <= tolerance) return std::nullopt;
  return fmt::format(
      "the {}'s level set holds {:.1f} mm³ and its mesh encloses {:.1f} mm³, {:+.1f} mm³ apart, beyond the "
      "{:.1f} mm³ tolerance: the volumes in this report are not to be trusted",
      solid, levelSetMm3, meshMm3, meshMm3 - levelSetMm3, tolerance);
}

struct VolumeAndArea {
  double volumeMm3 = 0, areaMm2 = 0;
};

// Each triangle's terms computed in parallel and then summed in triangle order, by the very
// expressions enclosedVolumeMm3 and surfaceAreaMm2 use: the same sums to the last bit.
VolumeAndArea volumeAndAreaOf(const TriangleMesh& mesh) {
  std::vector<double> sixVolume(mesh.triangles.size()), twiceArea(mesh.triangles.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.triangles.size(), 4096), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const auto& t = mesh.triangles[i];
      const Eigen::Vector3d a = mesh.vertices[t[0]].cast<double>();
      const Eigen::Vector3d b = mesh.vertices[t[1]].cast<double>();
      const Eigen::Vector3d c = mesh.vertices[t[2]].cast<double>();
      sixVolume[i] = a.dot(b.cross(c));
      twiceArea[i] = (b - a).cross(c - a).norm();
    }
  });
  double sixTimesVolume = 0.0, twiceTheArea = 0.0;
  for (const double v : sixVolume) sixTimesVolume += v;
  for (const double a : twiceArea) twiceTheArea += a;
  return {sixTimesVolume / 6.0, twiceTheArea / 2.0};
}

}  // namespace

std::optional<std::string> meshVolumeProblem(double levelSetMm3, const TriangleMesh& mesh, double voxelMm,
                                             std::string_view solid) {
  return volumeProblem(levelSetMm3, enclosedVolumeMm3(mesh), surfaceAreaMm2(mesh), voxelMm, solid);
}

std::optional<std::string> meshClosureProblem(const TriangleMesh& mesh, std::string_view solid) {
  if (isClosedAndOriented(mesh)) return std::nullopt;
  return fmt::format("the {0}'s mesh is not closed and manifold: {0}.stl has edges not shared by exactly two "
                     "triangles, and its volume is not to be trusted",
                     solid);
}

MeshCheck checkMesh(TriangleMesh& mesh, double levelSetMm3, double voxelMm, std::string_view solid) {
  MeshCheck check;
  VolumeAndArea whole = volumeAndAreaOf(mesh);
  check.volumeProblem = volumeProblem(levelSetMm3, whole.volumeMm3, whole.areaMm2, voxelMm, solid);
  check.crumbs = dropCrumbs(mesh, voxelMm);
  if (check.crumbs.count > 0) whole = volumeAndAreaOf(mesh);  // the same triangles in the same order otherwise
  check.closureProblem = meshClosureProblem(mesh, solid);
  check.volumeMm3 = whole.volumeMm3;
  check.areaMm2 = whole.areaMm2;
  return check;
}

}  // namespace lathesim::measure
