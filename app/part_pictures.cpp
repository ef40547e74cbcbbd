#include "app/part_pictures.hpp"

#include <algorithm>

#include "app/tool_picture.hpp"
#include "geometry/profile_polylines.hpp"
#include "sim/holder_check.hpp"

namespace lathesim::app {
namespace {

/// The chuck as the collision check sees it (sim::chuckRegions: the jaws, then the body).
render::ChuckPicture chuckPicture(const job::Setup& setup) {
  const std::vector<ConvexPolygon> regions = sim::chuckRegions(setup.chuck, setup.stock);
  auto bounds = [](const ConvexPolygon& p, RZ& low, RZ& high) {
    low = high = p.vertices().front();
    for (const RZ& v : p.vertices()) low = low.cwiseMin(v), high = high.cwiseMax(v);
  };
  RZ jawLow, jawHigh, bodyLow, bodyHigh;
  bounds(regions.at(0), jawLow, jawHigh);
  bounds(regions.at(1), bodyLow, bodyHigh);
  return {jawLow.x(), jawHigh.x(), jawLow.y(), jawHigh.y(), bodyLow.y()};
}

}  // namespace

render::PartImageOptions partPictureOptions(const job::Setup& setup, const interp::Toolpath& toolpath,
                                            const std::string& title, int widthPx, int heightPx) {
  render::PartImageOptions options;
  options.widthPx = widthPx;
  options.heightPx = heightPx;
  options.title = title;
  options.tool = toolPictureAtEnd(setup, toolpath);
  const sim::StockSpec& bar = setup.stock;
  options.bar = render::BarOutline{bar.diameterMm / 2, bar.faceZMm - bar.lengthMm, bar.faceZMm, bar.boreMm / 2};
  options.chuck = chuckPicture(setup);
  return options;
}

double drawnToleranceMm(const job::Setup& setup, int widthPx, int heightPx) {
  constexpr double kDrawnTolerancePx = 0.2;
  const sim::StockSpec& bar = setup.stock;
  const double mmPerPx = std::max(bar.lengthMm / std::max(widthPx, 1), bar.diameterMm / std::max(heightPx, 1));
  return kDrawnTolerancePx * mmPerPx;
}

void addPartSection(render::PartImageOptions& options, const SampledSection& section, double voxelMm) {
  const double barLengthMm = options.bar ? options.bar->zHighMm - options.bar->zLowMm : 0.0;
  // The surface points of a face cut flat agree to far below a voxel (φ is an exact distance
  // there); faces shorter than 4 % of the bar are not dimensioned.
  const MeridianProfile profile = MeridianProfile::fromSection(section);
  DimensionRules rules;
  rules.flatToleranceMm = 0.02 * voxelMm;
  rules.minFaceMm = std::max(4 * voxelMm, 0.04 * barLengthMm);
  rules.maxLengths = 3;
  options.dimensions = mainDimensions(profile, chainSegments(profile.surface(), 1e-6), rules);
  options.dimensionDecimals = voxelMm < 0.1 ? 2 : 1;
  options.section = section;
}

}  // namespace lathesim::app
