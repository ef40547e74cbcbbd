#include "measure/volume_checks.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "sim/stock.hpp"

namespace lathesim::measure {

std::optional<std::string> barVolumeProblem(const sim::StockSpec& bar, double levelSetMm3, double voxelMm) {
  const double r = bar.diameterMm / 2.0;
  const double exact = std::numbers::pi * r * r * bar.lengthMm;
  const double tolerance = sim::volumeToleranceMm3(2.0 * std::numbers::pi * r * (r + bar.lengthMm), voxelMm);
  if (std::abs(levelSetMm3 - exact) <= tolerance) return std::nullopt;
  return fmt::format(
      "the bar's level set holds {:.1f} mm³ where the Φ{:g}×{:g} bar is {:.1f} mm³, {:+.1f} mm³ off, beyond the "
      "{:.1f} mm³ tolerance: the volumes in this report are not to be trusted",
      levelSetMm3, bar.diameterMm, bar.lengthMm, exact, levelSetMm3 - exact, tolerance);
}

std::optional<std::string> meshVolumeProblem(double levelSetMm3, const TriangleMesh& mesh, double voxelMm) {
  const double meshMm3 = enclosedVolumeMm3(mesh);
  const double tolerance = sim::volumeToleranceMm3(surfaceAreaMm2(mesh), voxelMm);
  if (std::abs(levelSetMm3 - meshMm3) <= tolerance) return std::nullopt;
  return fmt::format(
      "the part's level set holds {:.1f} mm³ and its mesh encloses {:.1f} mm³, {:+.1f} mm³ apart, beyond the "
      "{:.1f} mm³ tolerance: the volumes in this report are not to be trusted",
      levelSetMm3, meshMm3, meshMm3 - levelSetMm3, tolerance);
}

std::optional<std::string> meshClosureProblem(const TriangleMesh& mesh) {
  if (isClosedAndOriented(mesh)) return std::nullopt;
  return std::string("the part's mesh is not closed and manifold: part.stl has edges not shared by exactly two "
                     "triangles, and its volume is not to be trusted");
}

}  // namespace lathesim::measure
