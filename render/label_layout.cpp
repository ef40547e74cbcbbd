#include "render/label_layout.hpp"

#include <algorithm>
#include <cmath>

#include <vtkNew.h>
#include <vtkStdString.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

namespace lathesim::render {
namespace {

constexpr double kGapPx = 3.0;        // kept free around a label
constexpr int kRingsTried = 14;       // candidate places out to this many steps each way
constexpr double kLeaderFromPx = 6.0; // a label moved further than this from its place gets a leader

bool inside(const LabelBox& box, const ClipRectangle& bounds) {
  return box.left >= bounds.x0 && box.right <= bounds.x1 && box.bottom >= bounds.y0 && box.top <= bounds.y1;
}

LabelBox grown(const LabelBox& box, double by) {
  return {box.left - by, box.bottom - by, box.right + by, box.top + by};
}

LabelBox shifted(const LabelBox& box, const Pixel& by) {
  return {box.left + by.x(), box.bottom + by.y(), box.right + by.x(), box.top + by.y()};
}

/// The point of `box` nearest `p`.
Pixel nearestPoint(const LabelBox& box, const Pixel& p) {
  return {std::clamp(p.x(), box.left, box.right), std::clamp(p.y(), box.bottom, box.top)};
}

/// Offsets around a label's place, nearest first: steps of a third of its width across and of
/// its height (and the gap) up and down.
std::vector<Pixel> candidateOffsets(const LabelBox& box) {
  const double stepX = std::max(4.0, (box.right - box.left) / 3.0), stepY = box.top - box.bottom + kGapPx;
  std::vector<Pixel> offsets;
  for (int i = -3 * kRingsTried; i <= 3 * kRingsTried; ++i)
    for (int j = -kRingsTried; j <= kRingsTried; ++j) offsets.emplace_back(i * stepX, j * stepY);
  std::stable_sort(offsets.begin(), offsets.end(),
                   [](const Pixel& a, const Pixel& b) { return a.squaredNorm() < b.squaredNorm(); });
  return offsets;
}

}  // namespace

bool LabelBox::crossedBy(const Pixel& a, const Pixel& b) const {
  if (right <= left || top <= bottom) return false;
  const auto span = clipToRectangle(a, b, left, bottom, right, top);
  if (!span) return false;
  // Touching an edge only (a zero-length piece, or running along the border) is no crossing.
  const Pixel p0 = a + span->t0 * (b - a), p1 = a + span->t1 * (b - a);
  const Pixel middle = 0.5 * (p0 + p1);
  return middle.x() > left && middle.x() < right && middle.y() > bottom && middle.y() < top;
}

LabelBox labelBox(const Label& label, int fontPx) {
  vtkNew<vtkTextProperty> p;  // as part_picture.cpp's textActor sets it
  p->SetFontSize(fontPx);
  p->SetFontFamilyToArial();
  if (label.justify == Justify::Centre) p->SetJustificationToCentered();
  if (label.justify == Justify::Right) p->SetJustificationToRight();
  int bbox[4] = {0, 0, 0, 0};
  vtkTextRenderer* renderer = vtkTextRenderer::GetInstance();
  if (!renderer || !renderer->GetBoundingBox(p.GetPointer(), vtkStdString(label.text), bbox, 72))
    return {label.at.x(), label.at.y(), label.at.x(), label.at.y()};
  // bbox: {xmin, xmax, ymin, ymax} from the anchor, its last pixel included.
  return {label.at.x() + bbox[0], label.at.y() + bbox[2], label.at.x() + bbox[1] + 1, label.at.y() + bbox[3] + 1};
}

std::vector<PlacedLabel> placeLabels(const std::vector<Label>& labels, const std::vector<int>& fontPx,
                                     std::size_t fixedCount, const std::vector<PixelSegment>& keepClear,
                                     const ClipRectangle& bounds, Overlay2D& leaders) {
  std::vector<PlacedLabel> placed;
  const auto free = [&](const LabelBox& box) {
    const LabelBox clear = grown(box, kGapPx);
    return inside(box, bounds) &&
           std::none_of(placed.begin(), placed.end(), [&](const PlacedLabel& p) { return p.box.overlaps(clear); }) &&
           std::none_of(keepClear.begin(), keepClear.end(), [&](const PixelSegment& s) { return clear.crossedBy(s[0], s[1]); });
  };
  for (std::size_t n = 0; n < labels.size(); ++n) {
    const Label& label = labels[n];
    const LabelBox box = labelBox(label, fontPx[n]);
    if (n < fixedCount || free(box)) {
      placed.push_back({label, fontPx[n], box});
      continue;
    }
    Pixel chosen(0, 0);
    bool found = false;
    for (const Pixel& offset : candidateOffsets(box))
      if (free(shifted(box, offset))) {
        chosen = offset;
        found = true;
        break;
      }
    Label moved = label;
    moved.at += chosen;
    const LabelBox movedBox = shifted(box, chosen);
    placed.push_back({moved, fontPx[n], movedBox});
    if (found && chosen.norm() > kLeaderFromPx) {
      // From the middle of where it was meant to be (a dimension line's middle, an arrow's
      // side) to the nearest point of where it went.
      const Pixel from(0.5 * (box.left + box.right), 0.5 * (box.bottom + box.top));
      leaders.line(from, nearestPoint(movedBox, from), label.colour);
    }
  }
  return placed;
}

}  // namespace lathesim::render
