#pragma once
// Inside render only: what the part pictures draw over the scene, in pixels — the toolpath cut
// at the picture's edge with arrows where moves leave it, the bar's outline, dimension lines,
// a scale bar — and the labels that go with them.

#include <optional>
#include <string>
#include <vector>

#include "geometry/part_dimensions.hpp"
#include "interp/motion/toolpath_clock.hpp"
#include "interp/base/move.hpp"
#include "render/overlay_2d.hpp"
#include "render/part_image.hpp"
#include "render/picture_frame.hpp"

namespace lathesim::render {

inline constexpr Rgb kFeedColour{0.05, 0.25, 0.95};
inline constexpr Rgb kRapidColour{0.90, 0.08, 0.08};
inline constexpr Rgb kThreadColour{0.05, 0.55, 0.15};
inline constexpr Rgb kToolMarkColour{0.85, 0.62, 0.05};

enum class Justify { Left, Centre, Right };

struct Label {
  Pixel at{0, 0};  // the text's anchor: its baseline's left end, middle or right end
  std::string text;
  Rgb colour{0, 0, 0};
  Justify justify = Justify::Left;
  bool backed = false;  // on a pale patch, to read over the part
  /// The point it tells about (an arrow at the picture's edge, a dimension line): a label
  /// moved from its place is joined to it by a leader. None: the middle of where it was put.
  std::optional<Pixel> target{};
};

/// The rectangle inside which lines are drawn whole; beyond it they are cut and marked.
struct ClipRectangle {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool contains(const Pixel& p) const { return p.x() >= x0 && p.x() <= x1 && p.y() >= y0 && p.y() <= y1; }
};
ClipRectangle clipRectangleOf(const PictureFrame& frame);

/// A position as a program writes it: "X200 Z-30.5" (X a diameter).
std::string programPoint(const RZ& p);

/// The point in the program's own words where `move` ends: its end in the setup's frame less
/// the work shift (G54–G59, G10 L2, G50) and the tool offset's shift it ends under.
RZ programmedEnd(const interp::Move& move);

/// The toolpath (up to `shown` if given) into `lines` (2 px), cut at `clip`; where a move
/// leaves or enters the rectangle an arrowhead into `marks` and a label saying where it goes
/// or comes from (one per place): the block's programmed end or start in the program's own
/// words (programmedEnd), never a dog-leg's corner (a non-linear rapid's two legs are
/// labelled as the one move they are).
void drawToolpath(const interp::Toolpath& toolpath, const std::optional<interp::ToolpathInstant>& shown,
                  const PictureFrame& frame, const ClipRectangle& clip, Overlay2D& lines, Overlay2D& marks,
                  std::vector<Label>& labels);

/// An arrow at the picture's edge pointing towards a tool standing outside it (the title
/// block says where it is).
void drawToolOutside(const RZ& position, const PictureFrame& frame, const ClipRectangle& clip, Overlay2D& marks);

/// Each crash as a filled disc `radiusPx` wide in kCrashColour at its point (kept inside `clip`
/// when it lies outside), labelled beside it in the same red.
void drawCrashMarks(const std::vector<CrashMark>& crashes, const PictureFrame& frame, const ClipRectangle& clip,
                    double radiusPx, Overlay2D& marks, std::vector<Label>& labels);

/// The bar's outline in the ghost's line colour (iso: its silhouette and end circle; front and
/// section: its rectangle).
void drawBarOutline(const BarOutline& bar, PartView view, const PictureFrame& frame, Overlay2D& lines);

/// Diameters as vertical lines across the part with arrows at its surface; lengths as
/// horizontal lines stacked above `topPx` and below `ceilingPx` (the title block's foot), with
/// extension lines down to the faces. Every line drawn is added to `dimensionLines` too, for
/// the labels to keep clear of.
void drawDimensions(const PartDimensions& dims, int decimals, const PictureFrame& frame, double topPx,
                    double ceilingPx, Overlay2D& lines, Overlay2D& marks, std::vector<Label>& labels,
                    std::vector<PixelSegment>& dimensionLines);

/// A bar of a round length (1, 2 or 5 × 10ⁿ mm) in the lower-right corner, true to scale.
void drawScaleBar(const PictureFrame& frame, Overlay2D& lines, std::vector<Label>& labels);

}  // namespace lathesim::render
