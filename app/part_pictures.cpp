#include "app/part_pictures.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "app/tool_picture.hpp"
#include "geometry/profile_polylines.hpp"
#include "sim/holder_check.hpp"

namespace lathesim::app {
namespace {

/// The chuck as the collision check sees it (sim::chuckRegions: the jaws, then the body).
render::ChuckPicture chuckPicture(const setup::Setup& setup) {
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

/// What a tool is, in a few words, for the picture's subtitle.
std::string toolWords(const setup::Setup& setup, int number) {
  const auto tool = std::find_if(setup.tools.begin(), setup.tools.end(),
                                 [number](const setup::ToolDefinition& t) { return t.number == number; });
  std::string words = fmt::format("T{:02d}", number);
  if (tool == setup.tools.end()) return words;
  const setup::ToolFacts& f = tool->facts;
  if (!f.insert.empty()) return words + " " + f.insert;
  if (!f.insertShape.empty()) return words + " " + f.insertShape;
  return words + (f.kind == "polygon" ? " a polygon tool" : " the default tool");
}

std::string clockText(double seconds) {
  const int minutes = static_cast<int>(seconds / 60);
  return fmt::format("{}:{:04.1f}", minutes, seconds - 60.0 * minutes);
}

}  // namespace

std::string pictureTitle(const std::string& program, std::optional<int> atLine) {
  return atLine ? fmt::format("{}, at line {}", program, *atLine) : program;
}

std::string pictureSubtitle(const setup::Setup& setup, const std::vector<int>& toolsUsed, double cycleTimeS) {
  const sim::StockSpec& bar = setup.stock;
  // Ø, not Φ: the pictures' font has no Greek (the dimensions write Ø too).
  std::string text = fmt::format("bar Ø{:g} × {:g}", bar.diameterMm, bar.lengthMm);
  if (bar.boreMm > 0) text += fmt::format(", bore Ø{:g}", bar.boreMm);
  if (!setup.stockMaterial.empty()) text += " " + setup.stockMaterial;
  for (std::size_t n = 0; n < toolsUsed.size(); ++n) text += (n == 0 ? " · " : ", ") + toolWords(setup, toolsUsed[n]);
  return text + " · cycle time " + clockText(cycleTimeS);
}

std::vector<int> toolsUsedBy(const std::vector<interp::Move>& moves) {
  std::vector<int> tools;
  for (const interp::Move& move : moves)
    if (std::find(tools.begin(), tools.end(), move.tool) == tools.end()) tools.push_back(move.tool);
  return tools;
}

render::PartImageOptions partPictureOptions(const setup::Setup& setup, const interp::Toolpath& toolpath,
                                            const std::string& title, int widthPx, int heightPx) {
  render::PartImageOptions options;
  options.widthPx = widthPx;
  options.heightPx = heightPx;
  options.title = title;
  options.tool = toolPictureAtEnd(setup, toolpath);
  const sim::StockSpec& bar = setup.stock;
  options.bar = render::BarOutline{bar.diameterMm / 2, bar.faceZMm - bar.lengthMm, bar.faceZMm, bar.boreMm / 2};
  options.chuck = chuckPicture(setup);
  if (setup.tailstock) {
    const setup::Tailstock& t = *setup.tailstock;
    options.tailstock =
        render::TailstockPicture{t.pointZMm, t.quillDiameterMm / 2, setup::kQuillLengthPerDiameter * t.quillDiameterMm};
  }
  return options;
}

render::SceneMachine sceneMachine(const setup::Setup& setup, const interp::Toolpath& toolpath) {
  const render::PartImageOptions picture = partPictureOptions(setup, toolpath, "", 1, 1);
  return {picture.chuck, picture.tailstock, picture.tool};
}

double drawnToleranceMm(const setup::Setup& setup, int widthPx, int heightPx) {
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
