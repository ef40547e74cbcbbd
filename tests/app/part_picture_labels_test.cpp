// The bundled parts' pictures (every directory of parts/, in each of the three views, as
// `run` draws them: its dimensions from the simulated section, its crashes, its title block):
// no two labels overlap, none crosses a dimension or extension line or a leader, and no leader
// crosses a dimension line or another leader; each frames the bar, the jaws' working faces and
// the tool with its holder, or says in its title block that the tool is off the picture. And
// the positions the labels print are the program's own words under G55 and a tool offset.
// The layout is read from the renderer (render::partImageLayout) without drawing the picture.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/collision_diagnostics.hpp"
#include "app/part_pictures.hpp"
#include "setup/collision_checks.hpp"
#include "interp/motion/cycle_time.hpp"
#include "setup/job.hpp"
#include "render/drawn_toolpath.hpp"
#include "render/part_image.hpp"
#include "tests/support/files.hpp"
#include "tests/support/label_boxes.hpp"
#include "tests/support/lathesim_process.hpp"
#include "sim/simulate.hpp"
#include "sim/stock.hpp"

namespace lathesim::app {
namespace {

namespace fs = std::filesystem;

constexpr int kPictureWidthPx = 1600, kPictureHeightPx = 1200;  // run's own size

std::vector<fs::path> partDirectories() {
  std::vector<fs::path> parts;
  for (const auto& entry : fs::directory_iterator(LATHESIM_PARTS_DIR))
    if (entry.is_directory()) parts.push_back(entry.path());
  std::sort(parts.begin(), parts.end());
  return parts;
}

/// A program's picture as `run` sets it up (its view still to choose).
struct PictureSetUp {
  interp::Toolpath toolpath;  // as drawn
  render::PartImageOptions options;
};

/// Nullopt when the program alarms (it draws no picture).
std::optional<PictureSetUp> pictureOf(const fs::path& program, const std::optional<fs::path>& setupFile) {
  setup::JobRequest request;
  request.program = program;
  request.setup = setupFile;
  auto loaded = setup::loadJob(request);
  if (!loaded.value) return std::nullopt;
  const setup::Job& job = *loaded.value;
  const double voxel = job.setup.voxelMm.value_or(setup::kDefaultVoxelMm);
  sim::Stock stock(job.setup.stock, voxel);
  sim::ToolOutlines outlines;
  for (const auto& tool : job.setup.tools) outlines.emplace(tool.number, tool.outline);
  const sim::CollisionChecks checks = setup::collisionChecksOf(job.setup);
  const sim::SimulationResult result = sim::simulate(job.toolpath, outlines, stock, {{}, &checks, {}, {}});
  const sim::Stock& part = result.part ? *result.part : stock;
  render::DrawnToolpath drawn(drawnToleranceMm(job.setup, kPictureWidthPx, kPictureHeightPx));
  for (const interp::Move& move : job.toolpath.moves) drawn.take(move);
  PictureSetUp picture{drawn.toolpath(job.toolpath), {}};
  picture.options = partPictureOptions(job.setup, picture.toolpath, pictureTitle(program.string(), std::nullopt),
                                       kPictureWidthPx, kPictureHeightPx);
  picture.options.subtitle = pictureSubtitle(job.setup, toolsUsedBy(job.toolpath.moves), interp::cycleTimeS(job.toolpath));
  addPartSection(picture.options, part.meridianSection(), voxel);
  picture.options.crashes = crashMarksOf(result.collisions);
  return picture;
}

std::optional<PictureSetUp> bundledPicture(const fs::path& dir) {
  const fs::path setupFile = dir / "setup.toml";
  return pictureOf(dir / "program.nc", fs::exists(setupFile) ? std::optional(setupFile) : std::nullopt);
}

constexpr render::PartView kViews[] = {render::PartView::Iso, render::PartView::Front, render::PartView::Section};

TEST(PartPictureLabels, NoLabelOverprintsAnotherOrADimensionInAnyBundledPart) {
  ::unsetenv("DISPLAY");
  int pictures = 0;
  for (const fs::path& dir : partDirectories()) {
    SCOPED_TRACE(dir.filename().string());
    std::optional<PictureSetUp> picture = bundledPicture(dir);
    if (!picture) continue;
    for (const render::PartView view : kViews) {
      picture->options.view = view;
      const render::PictureLayout layout = render::partImageLayout(TriangleMesh{}, picture->toolpath, picture->options);
      ++pictures;
      const std::string where = std::string(render::viewName(view)) + " view";
      ASSERT_GE(layout.labels.size(), 2u) << where;
      EXPECT_EQ(layout.labels[0].text, (dir / "program.nc").string()) << where;
      EXPECT_NE(layout.labels[1].text.find("cycle time"), std::string::npos) << where;
      for (const std::string& overprint : test::overprints(layout)) ADD_FAILURE() << where << ": " << overprint;
    }
  }
  EXPECT_GE(pictures, 3 * 25) << "the bundled parts that run";
}

/// The title block's line that says the tool is not drawn whole, if any: a label at the
/// picture's top that says "off the picture".
const render::PictureLabel* offPictureNote(const render::PictureLayout& layout, int heightPx) {
  for (const render::PictureLabel& l : layout.labels)
    if (l.text.find("off the picture") != std::string::npos && l.bottom > 0.85 * heightPx) return &l;
  return nullptr;
}

// The frame contains what the picture shows: the bar whole (its end circles all round), the
// jaws' working faces (each jaw's gripping face at the bar's front end), and the tool's
// insert and holder at their real thickness behind the meridian plane, every corner inside
// the picture's pixels; or the title block says that the tool is off the picture.
TEST(PartPictureFrame, TheBarTheJawsFacesAndTheToolAreInTheFrameOrSaidOff) {
  ::unsetenv("DISPLAY");
  int toolWhole = 0, toolOff = 0;
  for (const fs::path& dir : partDirectories()) {
    SCOPED_TRACE(dir.filename().string());
    std::optional<PictureSetUp> picture = bundledPicture(dir);
    if (!picture) continue;
    const render::PartImageOptions& o = picture->options;
    for (const render::PartView view : kViews) {
      picture->options.view = view;
      const std::string where = std::string(render::viewName(view)) + " view";
      const render::PictureFrame frame = render::partPictureFrame(o, picture->toolpath, TriangleMesh{});
      const auto expectInside = [&](const Eigen::Vector3d& p, const std::string& what) {
        const Eigen::Vector2d px = frame.pixelOf(p);
        EXPECT_TRUE(px.x() >= 0 && px.x() <= kPictureWidthPx && px.y() >= 0 && px.y() <= kPictureHeightPx)
            << where << ": " << what << " at (" << p.transpose() << ") mm is drawn at (" << px.transpose() << ") px";
      };
      ASSERT_TRUE(o.bar && o.chuck) << "every bundled part has a bar in a chuck";
      for (const double z : {o.bar->zLowMm, o.bar->zHighMm})
        for (int k = 0; k < 36; ++k) {
          const double a = k * M_PI / 18;
          expectInside({o.bar->radiusMm * std::cos(a), o.bar->radiusMm * std::sin(a), z}, "the bar's edge");
        }
      // Three jaws, one straight up (+x), 120° apart; each grips over its width at the inner
      // radius (the jaws' half width: 0.18 of their outer radius, render/machine_meshes.hpp's
      // kJawHalfWidthPerRadius).
      for (int jaw = 0; jaw < 3; ++jaw) {
        const double a = jaw * 2 * M_PI / 3;
        const Eigen::Vector3d out(std::cos(a), std::sin(a), 0), side(-std::sin(a), std::cos(a), 0);
        for (const double s : {-1.0, 0.0, 1.0})
          expectInside(out * o.chuck->jawInnerRadiusMm + side * (s * 0.18 * o.chuck->jawOuterRadiusMm) +
                           Eigen::Vector3d(0, 0, o.chuck->jawZHighMm),
                       "a jaw's working face");
      }
      ASSERT_TRUE(o.tool.has_value()) << where;
      const render::PictureLayout layout = render::partImageLayout(TriangleMesh{}, picture->toolpath, o);
      if (const render::PictureLabel* note = offPictureNote(layout, kPictureHeightPx)) {
        // A still frames the tool whole when it stands near: drawn, never cut by the edge.
        EXPECT_EQ(note->text.find("runs off"), std::string::npos) << where << ": " << note->text;
        ++toolOff;
        continue;
      }
      ++toolWhole;
      const render::ToolPicture& t = *o.tool;
      const bool realSize = t.holderHeightMm > 0 && t.insertThicknessMm > 0;
      for (const auto& [outline, behindMm] : {std::pair{t.insert, t.insertThicknessMm}, std::pair{t.holder, t.holderHeightMm}})
        for (const RZ& corner : outline)
          for (const double depth : {0.0, realSize ? behindMm : 0.0}) {
            const RZ at = t.position + corner;
            expectInside({at.x(), -depth, at.y()}, "the tool (unsaid off the picture)");
          }
    }
  }
  // Both kinds are among the bundled parts, so that neither branch goes untried.
  EXPECT_GE(toolWhole, 3);
  EXPECT_GE(toolOff, 3);
}

// A Φ60 × 60 bar; the last rapid leaves the picture for X300 Z150 as the program writes it,
// where the tool ends (off the picture). Under G55 (its zero 10 mm towards the chuck), the
// tool offset 1 (X +0.4 on the diameter, Z +0.3), and both, the setup's frame puts that point
// at X300 Z140, X300.4 Z150.3 and X300.4 Z140.3: the labels still say X300 Z150.
TEST(PartPictureLabels, PositionsArePrintedInTheProgramsOwnWords) {
  ::unsetenv("DISPLAY");
  test::ScratchDir dir("program-words");
  const std::string stock = "[stock]\ndiameter = 60\nlength = 60\nface_z = 0\n[machine]\nstart = [200, 200]\n";
  const std::string g55 = "[[work_offset]]\ncode = \"G55\"\nz = -10.0\n";
  const std::string offset = "[[offset]]\nnumber = 1\nx = 0.4\nz = 0.3\n";
  struct Case {
    std::string name, setup, program;
  };
  const std::string moves = "G00 X40 Z2\nG01 Z-20 F0.2\nG01 X50\nG00 X300 Z150\nM30\n";
  for (const Case& c : {Case{"g55", stock + g55, "T0100\nG55\n" + moves}, Case{"offset", stock + offset, "T0101\n" + moves},
                        Case{"both", stock + g55 + offset, "T0101\nG55\n" + moves}}) {
    SCOPED_TRACE(c.name);
    test::writeFile(dir.path() / (c.name + ".toml"), c.setup);
    test::writeFile(dir.path() / (c.name + ".nc"), c.program);
    std::optional<PictureSetUp> picture = pictureOf(dir.path() / (c.name + ".nc"), dir.path() / (c.name + ".toml"));
    ASSERT_TRUE(picture.has_value());
    ASSERT_FALSE(picture->toolpath.moves.empty());
    const RZ setupEnd = picture->toolpath.moves.back().to;
    EXPECT_FALSE(std::abs(setupEnd.x() - 150) < 1e-9 && std::abs(setupEnd.y() - 150) < 1e-9)
        << "the setup's frame differs from the program's";
    for (const render::PartView view : kViews) {
      picture->options.view = view;
      const render::PictureLayout layout = render::partImageLayout(TriangleMesh{}, picture->toolpath, picture->options);
      const std::string where = std::string(render::viewName(view)) + " view";
      EXPECT_TRUE(std::any_of(layout.labels.begin(), layout.labels.end(),
                              [](const render::PictureLabel& l) { return l.text == "to X300 Z150"; }))
          << where;
      const render::PictureLabel* note = offPictureNote(layout, kPictureHeightPx);
      ASSERT_NE(note, nullptr) << where;
      EXPECT_EQ(note->text, "the tool is off the picture, at X300 Z150 (the gold arrow at the edge)") << where;
      for (const render::PictureLabel& l : layout.labels) {
        EXPECT_EQ(l.text.find("300.4"), std::string::npos) << where << ": " << l.text;
        EXPECT_EQ(l.text.find("Z140"), std::string::npos) << where << ": " << l.text;
        EXPECT_EQ(l.text.find("Z150.3"), std::string::npos) << where << ": " << l.text;
      }
    }
  }
}

}  // namespace
}  // namespace lathesim::app
