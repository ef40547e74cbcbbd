#include "measure/verdict.hpp"

#include <cmath>

#include "sim/move_sweep.hpp"

namespace lathesim::measure {
namespace {

// Where the part's surface lies in its section, as a fraction of the voxel: flat faces,
// cylinders and cones are exact (the revolved table holds their analytic distance: programmed
// surfaces swept across sub-voxel offsets measure within 1e-4 voxel, tests/app/
// inspection_cli_test.cpp SurfacesWithinTheirUncertainty); arcs are swept by chords whose
// sagitta is at most sim::kArcSagittaVoxels (1/20). A sixteenth bounds both with a margin.
constexpr double kSurfaceUncertaintyVoxels = 1.0 / 16;
static_assert(kSurfaceUncertaintyVoxels >= sim::kArcSagittaVoxels);

}  // namespace

double surfaceUncertaintyMm(double voxelMm) { return kSurfaceUncertaintyVoxels * voxelMm; }

const char* verdictName(Verdict verdict) {
  return verdict == Verdict::Within ? "within" : verdict == Verdict::Out ? "out" : "undecided";
}

Verdict verdictOf(double outsideMm, double uncertaintyMm) {
  if (outsideMm >= uncertaintyMm) return Verdict::Out;
  if (outsideMm <= -uncertaintyMm) return Verdict::Within;
  return Verdict::Undecided;
}

std::optional<double> decidingVoxelMm(double outsideMm, double voxelMm, double uncertaintyMm) {
  const double margin = std::abs(outsideMm);
  if (margin < 1e-3) return std::nullopt;
  // The uncertainty is proportional to the voxel: scale it under the margin, with a tenth to
  // spare, then round down to two significant figures.
  const double voxel = 0.9 * voxelMm * margin / uncertaintyMm;
  const double scale = std::pow(10.0, std::floor(std::log10(voxel)) - 1);
  return std::floor(voxel / scale) * scale;
}

}  // namespace lathesim::measure
