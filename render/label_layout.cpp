#include "render/label_layout.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <vtkNew.h>
#include <vtkStdString.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

namespace lathesim::render {
namespace {

constexpr double kGapPx = 3.0;        // kept free around a label
constexpr int kRingsTried = 14;       // candidate places out to this many steps each way
constexpr double kLeaderFromPx = 6.0; // a label moved further than this from its place gets a leader
constexpr double kLeaderGapPx = 4.0;  // left between a leader's start and the point it tells about

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

bool segmentsMeet(const PixelSegment& a, const PixelSegment& b) {
  const auto cross = [](const Pixel& u, const Pixel& v) { return u.x() * v.y() - u.y() * v.x(); };
  const Pixel r = a[1] - a[0], q = b[1] - b[0], w = b[0] - a[0];
  const double denominator = cross(r, q);
  if (denominator == 0) {  // parallel: they meet only if collinear and overlapping
    if (cross(w, r) != 0) return false;
    const double length2 = r.squaredNorm();
    if (length2 == 0) return (a[0] - b[0]).norm() == 0 || (q.squaredNorm() > 0 && cross(w, q) == 0);
    const double t0 = w.dot(r) / length2, t1 = (b[1] - a[0]).dot(r) / length2;
    return std::max(t0, t1) >= 0 && std::min(t0, t1) <= 1;
  }
  const double t = cross(w, q) / denominator, u = cross(w, r) / denominator;
  return t >= 0 && t <= 1 && u >= 0 && u <= 1;
}

LabelPlacement placeLabels(const std::vector<Label>& labels, const std::vector<int>& fontPx, std::size_t fixedCount,
                           const std::vector<PixelSegment>& keepClear, const ClipRectangle& bounds) {
  LabelPlacement result;
  std::vector<PlacedLabel>& placed = result.labels;
  const auto free = [&](const LabelBox& box) {
    const LabelBox clear = grown(box, kGapPx);
    return inside(box, bounds) &&
           std::none_of(placed.begin(), placed.end(), [&](const PlacedLabel& p) { return p.box.overlaps(clear); }) &&
           std::none_of(keepClear.begin(), keepClear.end(), [&](const PixelSegment& s) { return clear.crossedBy(s[0], s[1]); }) &&
           std::none_of(result.leaders.begin(), result.leaders.end(),
                        [&](const LeaderLine& l) { return clear.crossedBy(l.segment[0], l.segment[1]); });
  };
  // A leader's way is clear when it passes by every label placed (with the gap kept free around
  // it), meets no line kept clear and no other leader.
  const auto clearWay = [&](const PixelSegment& leader) {
    return std::none_of(placed.begin(), placed.end(),
                        [&](const PlacedLabel& p) { return grown(p.box, 1.0).crossedBy(leader[0], leader[1]); }) &&
           std::none_of(keepClear.begin(), keepClear.end(), [&](const PixelSegment& s) { return segmentsMeet(leader, s); }) &&
           std::none_of(result.leaders.begin(), result.leaders.end(),
                        [&](const LeaderLine& l) { return segmentsMeet(leader, l.segment); });
  };
  for (std::size_t n = 0; n < labels.size(); ++n) {
    const Label& label = labels[n];
    const LabelBox box = labelBox(label, fontPx[n]);
    if (n < fixedCount || free(box)) {
      placed.push_back({label, fontPx[n], box});
      continue;
    }
    // From the point the label tells about (or the middle of where it was meant to be), a few
    // pixels off it, to the nearest point of where it went.
    const Pixel target = label.target.value_or(Pixel(0.5 * (box.left + box.right), 0.5 * (box.bottom + box.top)));
    const auto leaderTo = [&](const LabelBox& moved) -> PixelSegment {
      const Pixel end = nearestPoint(moved, target);
      const Pixel along = end - target;
      const double length = along.norm();
      return {length > kLeaderGapPx ? Pixel(target + along * (kLeaderGapPx / length)) : end, end};
    };
    // The nearest free place whose leader's way is clear; failing that, the nearest free place
    // (without a leader: one that crosses a label would mislead more than none).
    std::optional<Pixel> chosen, chosenWithoutLeader;
    for (const Pixel& offset : candidateOffsets(box)) {
      const LabelBox moved = shifted(box, offset);
      if (!free(moved)) continue;
      if (!chosenWithoutLeader) chosenWithoutLeader = offset;
      if (offset.norm() <= kLeaderFromPx || clearWay(leaderTo(moved))) {
        chosen = offset;
        break;
      }
    }
    const bool withLeader = chosen.has_value();
    const Pixel offset = chosen.value_or(chosenWithoutLeader.value_or(Pixel(0, 0)));
    Label moved = label;
    moved.at += offset;
    const LabelBox movedBox = shifted(box, offset);
    if (withLeader && offset.norm() > kLeaderFromPx) result.leaders.push_back({leaderTo(movedBox), label.colour});
    placed.push_back({moved, fontPx[n], movedBox});
  }
  return result;
}

}  // namespace lathesim::render
