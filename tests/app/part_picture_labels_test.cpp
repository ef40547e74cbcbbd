// The bundled parts' pictures (every directory of parts/, in each of the three views, as
// `run` draws them: its dimensions from the simulated section, its crashes, its title block):
// no two labels overlap, none crosses a dimension or extension line or a leader, and no leader
// crosses a dimension line or another leader. The layout is read from the renderer
// (render::partImageLayout) without drawing the picture.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "app/collision_diagnostics.hpp"
#include "app/part_pictures.hpp"
#include "setup/collision_checks.hpp"
#include "interp/motion/cycle_time.hpp"
#include "setup/job.hpp"
#include "render/drawn_toolpath.hpp"
#include "render/part_image.hpp"
#include "tests/support/label_boxes.hpp"
#include "sim/simulate.hpp"
#include "sim/stock.hpp"

namespace lathesim::app {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> partDirectories() {
  std::vector<fs::path> parts;
  for (const auto& entry : fs::directory_iterator(LATHESIM_PARTS_DIR))
    if (entry.is_directory()) parts.push_back(entry.path());
  std::sort(parts.begin(), parts.end());
  return parts;
}

TEST(PartPictureLabels, NoLabelOverprintsAnotherOrADimensionInAnyBundledPart) {
  ::unsetenv("DISPLAY");
  constexpr int kWidthPx = 1600, kHeightPx = 1200;  // run's own size
  int pictures = 0;
  for (const fs::path& dir : partDirectories()) {
    SCOPED_TRACE(dir.filename().string());
    setup::JobRequest request;
    request.program = dir / "program.nc";
    if (fs::exists(dir / "setup.toml")) request.setup = dir / "setup.toml";
    auto loaded = setup::loadJob(request);
    if (!loaded.value) continue;  // a part whose program alarms draws no picture
    const setup::Job& job = *loaded.value;
    const double voxel = job.setup.voxelMm.value_or(setup::kDefaultVoxelMm);
    sim::Stock stock(job.setup.stock, voxel);
    sim::ToolOutlines outlines;
    for (const auto& tool : job.setup.tools) outlines.emplace(tool.number, tool.outline);
    const sim::CollisionChecks checks = setup::collisionChecksOf(job.setup);
    const sim::SimulationResult result = sim::simulate(job.toolpath, outlines, stock, {{}, &checks, {}, {}});
    const sim::Stock& part = result.part ? *result.part : stock;
    render::DrawnToolpath drawn(drawnToleranceMm(job.setup, kWidthPx, kHeightPx));
    for (const interp::Move& move : job.toolpath.moves) drawn.take(move);
    const interp::Toolpath toolpath = drawn.toolpath(job.toolpath);
    render::PartImageOptions options =
        partPictureOptions(job.setup, toolpath, pictureTitle(request.program.string(), std::nullopt), kWidthPx, kHeightPx);
    options.subtitle = pictureSubtitle(job.setup, toolsUsedBy(job.toolpath.moves), interp::cycleTimeS(job.toolpath));
    addPartSection(options, part.meridianSection(), voxel);
    options.crashes = crashMarksOf(result.collisions);
    for (const render::PartView view : {render::PartView::Iso, render::PartView::Front, render::PartView::Section}) {
      options.view = view;
      const render::PictureLayout layout = render::partImageLayout(TriangleMesh{}, toolpath, options);
      ++pictures;
      const std::string where = std::string(render::viewName(view)) + " view";
      ASSERT_GE(layout.labels.size(), 2u) << where;
      EXPECT_EQ(layout.labels[0].text, request.program.string()) << where;
      EXPECT_NE(layout.labels[1].text.find("cycle time"), std::string::npos) << where;
      for (const std::string& overprint : test::overprints(layout)) ADD_FAILURE() << where << ": " << overprint;
    }
  }
  EXPECT_GE(pictures, 3 * 25) << "the bundled parts that run";
}

}  // namespace
}  // namespace lathesim::app
