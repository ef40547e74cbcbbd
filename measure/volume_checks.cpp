#include "measure/volume_checks.hpp"

#include <cmath>

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

std::optional<std::string> meshVolumeProblem(double levelSetMm3, const TriangleMesh& mesh, double voxelMm,
                                             std::string_view solid) {
  const double meshMm3 = enclosedVolumeMm3(mesh);
  const double tolerance = sim::volumeToleranceMm3(surfaceAreaMm2(mesh), voxelMm);
  if (std::abs(levelSetMm3 - meshMm3) <= tolerance) return std::nullopt;
  return fmt::format(
      "the {}'s level set holds {:.1f} mm³ and its mesh encloses {:.1f} mm³, {:+.1f} mm³ apart, beyond the "
      "{:.1f} mm³ tolerance: the volumes in this report are not to be trusted",
      solid, levelSetMm3, meshMm3, meshMm3 - levelSetMm3, tolerance);
}

std::optional<std::string> meshClosureProblem(const TriangleMesh& mesh, std::string_view solid) {
  if (isClosedAndOriented(mesh)) return std::nullopt;
  return fmt::format("the {0}'s mesh is not closed and manifold: {0}.stl has edges not shared by exactly two "
                     "triangles, and its volume is not to be trusted",
                     solid);
}

}  // namespace lathesim::measure
