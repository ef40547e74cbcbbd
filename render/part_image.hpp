#pragma once
// The pictures a user looks at first: the finished part, framed, with the bar it came from as
// a faint ghost, the chuck's jaws, the tool where it stands, the toolpath and the main
// dimensions; seen from three sides (isometric, front, half-section).

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/meridian_profile.hpp"
#include "geometry/part_dimensions.hpp"
#include "geometry/triangle_mesh.hpp"
#include "interp/base/move.hpp"
#include "render/crash_mark.hpp"
#include "render/picture_frame.hpp"
#include "render/rgb_image.hpp"

namespace lathesim::render {

/// A tool as drawn: plain outlines in [radial, axial] mm from the programmed point, and
/// where that point stands (radius mm, Z mm).
struct ToolPicture {
  std::vector<RZ> insert;  // the cutter; drawn gold
  std::vector<RZ> holder;  // the holder body; may be empty (polygon-only tools); drawn steel grey
  RZ position{0, 0};
  /// Where the program's zero and the tool offset in force put `position` from the program's
  /// own words (interp::Move's workShift + offsetShift): a label says position − programShift.
  RZ programShift{0, 0};
  // Their thickness across the meridian plane (mm), the insert's rake face in the plane and
  // both behind it, as on the machine: the holder's shank height h and the insert's thickness.
  // 0: drawn as thin slabs about the plane, a fixed fraction of the picture thick.
  double holderHeightMm = 0;
  double insertThicknessMm = 0;
};

enum class PartView {
  Iso,      // turned 22° about the vertical so the end face shows (part.png)
  Front,    // as a drawing shows a turned part: X up, Z to the right
  Section,  // the front view cut open above the axis: the profile against the bar and the chuck
};
std::string_view viewName(PartView view);  // "iso", "front", "section"
std::optional<PartView> viewNamed(std::string_view name);

/// The bar before the program: drawn as a faint ghost around the part, and what the picture
/// frames.
struct BarOutline {
  double radiusMm = 0;
  double zLowMm = 0, zHighMm = 0;
  double boreRadiusMm = 0;  // a tube's bore; 0 for a solid bar
};

/// The chuck as the setup places it: its jaws grip the bar from `jawInnerRadiusMm` out to
/// `jawOuterRadiusMm` between `jawZLowMm` and `jawZHighMm`; its body reaches back from the
/// jaws to `bodyZLowMm`. Drawn as three jaws (one straight up) on the body.
struct ChuckPicture {
  double jawInnerRadiusMm = 0, jawOuterRadiusMm = 0;
  double jawZLowMm = 0, jawZHighMm = 0;
  double bodyZLowMm = 0;
};

/// The tailstock's live centre: a cone of 60° included angle from its point on the axis at
/// `pointZMm` out to the quill's radius, then the quill, a cylinder `quillLengthMm` long.
struct TailstockPicture {
  double pointZMm = 0;
  double quillRadiusMm = 0;
  double quillLengthMm = 0;
  /// Where the cone meets the quill.
  double coneEndZMm() const;
};

/// A part of the picture to frame instead of the whole: the box Z `zLowMm`…`zHighMm` ×
/// radius `radiusLowMm`…`radiusHighMm` of the meridian plane facing the viewer's up (a
/// thread's close-up: its profile on the silhouette, its grooves on the face below).
struct CloseUp {
  double zLowMm = 0, zHighMm = 0;
  double radiusLowMm = 0, radiusHighMm = 0;
};

struct PartImageOptions {
  int widthPx = 1600;
  int heightPx = 1200;
  std::string title;  // drawn in a corner: the program's name
  std::string subtitle;  // a line under it: the bar, the tools and the cycle time
  std::optional<ToolPicture> tool{};  // drawn where it stands, if given
  PartView view = PartView::Iso;
  std::optional<BarOutline> bar{};      // the ghost; with it the picture frames the bar, not the toolpath
  std::optional<ChuckPicture> chuck{};
  std::optional<TailstockPicture> tailstock{};  // drawn in steel green when the setup has one
  PartDimensions dimensions{};          // drawn as dimension lines
  int dimensionDecimals = 1;            // their figures' decimals
  std::optional<SampledSection> section{};  // the part's section: the cut face of the Section view
  std::string caption{};                // a line under the title
  /// Frame this box only (with the view Front: the profile true on the silhouette), without
  /// the toolpath, the tool and the legend.
  std::optional<CloseUp> closeUp{};
  /// Collisions, each a red disc where it happened and a label, over everything else.
  std::vector<CrashMark> crashes{};
};

/// Renders off-screen to a PNG: the shaded part; the bar as a faint amber ghost; the chuck's
/// jaws in dark blue steel; the toolpath over it (rapids dashed red, feeds solid blue, thread
/// moves solid green), cut at the picture's edge where a move leaves it, with an arrow and
/// where it goes; the tool, if given, as gold insert and grey holder slabs in the meridian
/// plane (or an arrow to it when it stands outside the picture); dimension lines in purple;
/// the title, legend and (front and section views) a scale bar.
/// The picture frames the bar and the front ends of the jaws (without a bar, the part and the
/// whole jaws; without a part, the toolpath) with a margin, and the tool with its holder when
/// it stands near them; the rest of the chuck runs out of the picture. A tool not drawn whole
/// inside the picture is said so in the title block ("the tool is off the picture, at …",
/// "… runs off the picture"). Every position a label prints is in the program's own words
/// (its work coordinates, without the tool offset). A close-up frames its box instead.
/// Works with no display: an Xvfb server is started for the process if none is reachable.
/// Throws std::runtime_error if the image cannot be made or written.
void writePartImagePng(const TriangleMesh& part, const interp::Toolpath& toolpath,
                       const PartImageOptions& options, const std::filesystem::path& png);
/// Where that picture puts things: its frame, as it frames the bar, the jaws and the tool
/// (or, without a bar, `part`), so that a point's pixel can be found (picture_frame.hpp).
PictureFrame partPictureFrame(const PartImageOptions& options, const interp::Toolpath& toolpath, const TriangleMesh& part);
/// A label as the picture placed it: its text and its box in pixels from the lower-left corner.
struct PictureLabel {
  std::string text;
  double left = 0, bottom = 0, right = 0, top = 0;
};
/// Where the picture partImage draws puts its labels, its dimension and extension lines
/// (which no label crosses), and the leader lines that join a moved label to its place (which
/// cross no other label, no dimension line and no other leader), found without drawing it.
struct PictureLayout {
  std::vector<PictureLabel> labels;
  std::vector<std::array<Eigen::Vector2d, 2>> dimensionLines;
  std::vector<std::array<Eigen::Vector2d, 2>> leaders;
};
PictureLayout partImageLayout(const TriangleMesh& part, const interp::Toolpath& toolpath, const PartImageOptions& options);
/// The same picture's pixels in memory: to draw it in one thread and write it in another, and
/// to shrink it into a thumbnail without reading the PNG back.
RgbImage partImage(const TriangleMesh& part, const interp::Toolpath& toolpath, const PartImageOptions& options);

}  // namespace lathesim::render
