// The part pictures' labels: no two overlap and none crosses a dimension line, however many
// crowd one place; a rapid's dog-leg corner is never labelled as a point of the program; the
// title block names the program and what the caller says under it.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "interp/interpreter.hpp"
#include "render/part_image.hpp"
#include "tests/support/label_boxes.hpp"
#include "tests/render/test_meshes.hpp"

namespace lathesim::render {
namespace {

void expectNoOverprint(const PictureLayout& layout, const std::string& what) {
  for (const PictureLabel& a : layout.labels) EXPECT_GT(a.right - a.left, 0) << what << ": '" << a.text << "' has no size";
  for (const std::string& overprint : lathesim::test::overprints(layout)) ADD_FAILURE() << what << ": " << overprint;
}

/// A Φ60 × 60 bar turned to five diameters 2 mm apart in steps 6 mm long (their figures all
/// want the middle of the part), three lengths, and eight moves that leave the picture at its
/// top edge close together (their "to …" labels want one place).
PartImageOptions crowded(PartView view) {
  PartImageOptions options;
  options.widthPx = 800;
  options.heightPx = 600;
  options.view = view;
  options.title = "crowded.nc";
  options.subtitle = "bar Ø60 × 60 · T01 CNMG120408 · cycle time 0:42.0";
  options.bar = BarOutline{30, -60, 0};
  options.chuck = ChuckPicture{30, 50, -80, -60, -180};
  for (int n = 0; n < 5; ++n)
    options.dimensions.diameters.push_back({50.0 - 2 * n, -30.0 - 6 * n, -24.0 - 6 * n, false});
  options.dimensions.lengths = {{-6, 0, 25, 25}, {-30, 0, 25, 25}, {-60, 0, 25, 25}};
  return options;
}

interp::Toolpath fan() {
  interp::Toolpath path;
  path.programName = "crowded.nc";
  for (int n = 0; n < 8; ++n) path.moves.push_back(test::move(interp::MoveKind::Rapid, 20, -10 - n, 300, -10 - n, n + 1, 0));
  return path;
}

TEST(PictureLabels, CrowdedLabelsNeitherOverlapNorCrossADimensionLine) {
  ::unsetenv("DISPLAY");
  for (const PartView view : {PartView::Iso, PartView::Front, PartView::Section}) {
    const PictureLayout layout = partImageLayout(TriangleMesh{}, fan(), crowded(view));
    ASSERT_GE(layout.labels.size(), 5u + 3u + 2u) << "the figures, the lengths, the title block";
    EXPECT_GE(layout.dimensionLines.size(), 5u + 3u * 3u);
    expectNoOverprint(layout, std::string(viewName(view)));
    // Each figure is there, once.
    for (const char* figure : {"Ø50.0", "Ø42.0", "6.0", "30.0", "60.0"})
      EXPECT_EQ(std::count_if(layout.labels.begin(), layout.labels.end(), [&](const PictureLabel& l) { return l.text == figure; }), 1)
          << figure;
  }
}

TEST(PictureLabels, TheTitleBlockNamesTheProgramAndTheLineUnderIt) {
  ::unsetenv("DISPLAY");
  const PictureLayout layout = partImageLayout(TriangleMesh{}, fan(), crowded(PartView::Iso));
  ASSERT_GE(layout.labels.size(), 2u);
  EXPECT_EQ(layout.labels[0].text, "crowded.nc");
  EXPECT_EQ(layout.labels[1].text, "bar Ø60 × 60 · T01 CNMG120408 · cycle time 0:42.0");
  EXPECT_LT(layout.labels[1].top, layout.labels[0].bottom) << "under the title";
  EXPECT_GT(layout.labels[0].top, 600 * 0.9) << "at the top";
}

// X200 Z200 → X30 Z2 under non-linear positioning (the default machine: X 6000 mm/min of
// radius, Z 8000): X arrives first, at the corner (r 15, Z86.667), then Z goes on alone (as
// interp's rapid_path_test works out). The corner lies above the picture: the leg that comes
// in is labelled from where the block started, X200 Z200, never from X30 Z86.667.
TEST(PictureLabels, ADogLegsCornerIsNotLabelledAsAProgrammedPoint) {
  ::unsetenv("DISPLAY");
  interp::InterpreterOptions options;
  options.startPosition = RZ(100, 200);
  options.toolNumbers = {1};
  options.control.rapidPath = interp::RapidPath::NonLinear;
  interp::InterpretResult result = interp::interpret("G00 X30 Z2\nG01 Z-20 F0.2\nM30\n", "dogleg.nc", options);
  ASSERT_TRUE(result.ok());
  ASSERT_EQ(result.toolpath.moves.size(), 3u) << "the rapid's two legs and the feed";
  ASSERT_NEAR(result.toolpath.moves[0].to.y(), 200 - 340.0 / 3, 1e-9);
  PartImageOptions picture = crowded(PartView::Front);
  picture.dimensions = {};
  const PictureLayout layout = partImageLayout(TriangleMesh{}, result.toolpath, picture);
  bool fromStart = false;
  for (const PictureLabel& l : layout.labels) {
    EXPECT_EQ(l.text.find("86.667"), std::string::npos) << l.text;
    fromStart = fromStart || l.text == "from X200 Z200";
  }
  EXPECT_TRUE(fromStart) << "the leg coming in is labelled from the block's start";
  // A rapid in one straight line is labelled from where it starts, as before.
  options.control.rapidPath = interp::RapidPath::Linear;
  result = interp::interpret("G00 X30 Z2\nG01 Z-20 F0.2\nM30\n", "dogleg.nc", options);
  const PictureLayout straight = partImageLayout(TriangleMesh{}, result.toolpath, picture);
  EXPECT_TRUE(std::any_of(straight.labels.begin(), straight.labels.end(),
                          [](const PictureLabel& l) { return l.text == "from X200 Z200"; }));
}

}  // namespace
}  // namespace lathesim::render
