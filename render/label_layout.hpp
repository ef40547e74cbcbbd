#pragma once
// Inside render only: where the part pictures' labels go, so that none overprints another
// label or crosses a dimension line. Each label is measured as VTK will draw it, kept where it
// was put when that place is free, else moved to the nearest free place around it (a leader
// line then joins it to where it was meant to be; the leader too crosses no other label, no
// dimension line and no other leader).

#include <array>
#include <cstddef>
#include <vector>

#include "render/overlay_2d.hpp"
#include "render/picture_annotations.hpp"

namespace lathesim::render {

/// A rectangle in pixels from the picture's lower-left corner.
struct LabelBox {
  double left = 0, bottom = 0, right = 0, top = 0;
  bool overlaps(const LabelBox& other) const {
    return left < other.right && other.left < right && bottom < other.top && other.bottom < top;
  }
  /// Whether the segment a–b passes through the box's inside.
  bool crossedBy(const Pixel& a, const Pixel& b) const;
};

/// Whether the segments a and b cross or touch (collinear overlaps included).
bool segmentsMeet(const PixelSegment& a, const PixelSegment& b);

/// The box `label`'s text takes drawn `fontPx` high at its anchor (with its justification).
LabelBox labelBox(const Label& label, int fontPx);

struct PlacedLabel {
  Label label;  // its anchor where it was placed
  int fontPx = 12;
  LabelBox box;
};

/// A line from where a label was meant to be to where it went, in the label's colour.
struct LeaderLine {
  PixelSegment segment;
  Rgb colour{0, 0, 0};
};

struct LabelPlacement {
  std::vector<PlacedLabel> labels;
  std::vector<LeaderLine> leaders;
};

/// Places `labels` (each drawn `fontPx[i]` high) in their order, which is their priority: the
/// first `fixedCount` stay where they are (the title, the legend); each other keeps its place
/// when it overlaps no label placed before, is crossed by no leader and crosses none of
/// `keepClear`, and lies inside `bounds`; else it takes the nearest place around it that does
/// and whose leader (from where it was meant to be) crosses no label placed before, none of
/// `keepClear` and no other leader. A label with no free place within reach stays where it
/// was put.
LabelPlacement placeLabels(const std::vector<Label>& labels, const std::vector<int>& fontPx, std::size_t fixedCount,
                           const std::vector<PixelSegment>& keepClear, const ClipRectangle& bounds);

}  // namespace lathesim::render
