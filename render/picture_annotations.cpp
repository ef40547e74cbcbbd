#include "render/picture_annotations.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/move_points.hpp"
#include "render/scene_actors.hpp"

namespace lathesim::render {
namespace {

constexpr double kArrowPx = 14.0;

std::string number(double value, int decimals) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

/// Shortest text for a coordinate: up to three decimals, no trailing zeros.
std::string coordinate(double value) {
  char text[48];
  std::snprintf(text, sizeof text, "%.3f", std::round(value * 1000.0) / 1000.0);
  std::string s = text;
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

/// A label beside a point on the clip rectangle's edge, moved inside and justified so that
/// it stays in the picture.
Label edgeLabel(const Pixel& at, const ClipRectangle& clip, std::string text, const Rgb& colour) {
  const double inset = 10.0, line = 18.0;
  Label label{at, std::move(text), colour, Justify::Centre, true, at};
  const double toLeft = at.x() - clip.x0, toRight = clip.x1 - at.x(), toBottom = at.y() - clip.y0, toTop = clip.y1 - at.y();
  const double nearest = std::min({toLeft, toRight, toBottom, toTop});
  if (nearest == toRight) label.justify = Justify::Right, label.at += Pixel(-inset - kArrowPx, inset);
  else if (nearest == toLeft) label.justify = Justify::Left, label.at += Pixel(inset + kArrowPx, inset);
  else if (nearest == toTop) label.at += Pixel(0, -line - kArrowPx);
  else label.at += Pixel(0, inset + kArrowPx);
  if (label.at.x() < clip.x0 + 120) label.justify = Justify::Left, label.at.x() = std::max(label.at.x(), clip.x0);
  if (label.at.x() > clip.x1 - 120) label.justify = Justify::Right, label.at.x() = std::min(label.at.x(), clip.x1);
  return label;
}

/// Adds `label` unless one with the same text is there already (where it goes: label_layout.hpp).
void place(std::vector<Label>& labels, Label label) {
  if (std::any_of(labels.begin(), labels.end(), [&](const Label& l) { return l.text == label.text; })) return;
  labels.push_back(std::move(label));
}

/// Whether moves[i] and moves[i + 1] are the two legs of one non-linear rapid, as
/// interp/motion/rapid_path.hpp splits it at its dog-leg corner: rapids of the same block and
/// cycle step, the first (both axes moving) ending where the second (one axis alone, going
/// on the way it went) starts.
bool dogLeg(const std::vector<interp::Move>& moves, std::size_t i) {
  if (i + 1 >= moves.size()) return false;
  const interp::Move& a = moves[i];
  const interp::Move& b = moves[i + 1];
  if (a.kind != interp::MoveKind::Rapid || b.kind != interp::MoveKind::Rapid || a.block != b.block ||
      a.line != b.line || a.cycleStep != b.cycleStep || a.to != b.from)
    return false;
  const RZ first = a.to - a.from, second = b.to - b.from;
  if (first.x() == 0 || first.y() == 0) return false;
  const bool alongX = second.y() == 0 && second.x() != 0, alongZ = second.x() == 0 && second.y() != 0;
  return (alongX && (second.x() > 0) == (first.x() > 0)) || (alongZ && (second.y() > 0) == (first.y() > 0));
}

/// Where the block of `moves[i]` starts and ends, in the program's words: a rapid's dog-leg
/// legs are one block's move, and their corner is no point the program names. A move starts
/// under the tool offset the move before it ended under (interp/compensation/tool_offset.cpp:
/// the new offset takes effect with the move), in its own work coordinates.
RZ blockStart(const std::vector<interp::Move>& moves, std::size_t i) {
  const std::size_t first = i > 0 && dogLeg(moves, i - 1) ? i - 1 : i;
  RZ offsetInForce(0, 0);
  for (std::size_t k = first; k-- > 0;)
    if (moves[k].kind != interp::MoveKind::Dwell) {
      offsetInForce = moves[k].offsetShift;
      break;
    }
  return moves[first].from - moves[first].workShift - offsetInForce;
}
RZ blockEnd(const std::vector<interp::Move>& moves, std::size_t i) {
  return programmedEnd(dogLeg(moves, i) ? moves[i + 1] : moves[i]);
}

void dimensionArrows(const Pixel& a, const Pixel& b, Overlay2D& lines, Overlay2D& marks,
                     std::vector<PixelSegment>& dimensionLines) {
  lines.line(a, b, kDimensionColour);
  dimensionLines.push_back({a, b});
  const Eigen::Vector2d d = b - a;
  if (d.norm() < 2.5 * kArrowPx) return;  // too short for arrows inside
  marks.arrowhead(a, -d, 0.8 * kArrowPx, kDimensionColour);
  marks.arrowhead(b, d, 0.8 * kArrowPx, kDimensionColour);
}

}  // namespace

ClipRectangle clipRectangleOf(const PictureFrame& frame) {
  const double inset = 0.012 * std::min(frame.widthPx, frame.heightPx);
  return {inset, inset, frame.widthPx - inset, frame.heightPx - inset};
}

RZ programmedEnd(const interp::Move& move) { return move.to - move.workShift - move.offsetShift; }

std::string programPoint(const RZ& p) {
  // Appended rather than "X" + …: GCC 12 warns falsely (-Wrestrict) on a literal plus a temporary.
  std::string text = "X";
  text += coordinate(diameterOf(p));
  text += " Z";
  text += coordinate(p.y());
  return text;
}

void drawToolpath(const interp::Toolpath& toolpath, const std::optional<interp::ToolpathInstant>& shown,
                  const PictureFrame& frame, const ClipRectangle& clip, Overlay2D& lines, Overlay2D& marks,
                  std::vector<Label>& labels) {
  const double dashPx = std::max(6.0, 0.008 * frame.widthPx);
  for (std::size_t i = 0; i < toolpath.moves.size(); ++i) {
    interp::Move move = toolpath.moves[i];
    if (shown && i > shown->move) break;
    if (shown && i == shown->move) {
      if (shown->fraction <= 0.0) break;
      move.to = shown->position;  // the move so far (an arc keeps its centre)
    }
    const bool rapid = !interp::isCutting(move.kind);
    const Rgb& colour = rapid ? kRapidColour : move.kind == interp::MoveKind::Thread ? kThreadColour : kFeedColour;
    const std::vector<RZ> points = movePoints(move);
    double phase = 0;
    for (std::size_t k = 1; k < points.size(); ++k) {
      const Pixel a = frame.pixelOf(points[k - 1]), b = frame.pixelOf(points[k]);
      const auto span = clipToRectangle(a, b, clip.x0, clip.y0, clip.x1, clip.y1);
      if (!span) continue;
      const Pixel from = a + span->t0 * (b - a), to = a + span->t1 * (b - a);
      if (rapid) phase = lines.dashed(from, to, colour, dashPx, phase);
      else lines.line(from, to, colour);
      if (span->t0 > 0) {  // comes in from outside
        marks.arrowhead(from + (b - a).normalized() * kArrowPx, b - a, kArrowPx, colour);
        place(labels, edgeLabel(from, clip, "from " + programPoint(blockStart(toolpath.moves, i)), colour));
      }
      if (span->t1 < 1) {  // goes out
        marks.arrowhead(to, b - a, kArrowPx, colour);
        place(labels, edgeLabel(to, clip, "to " + programPoint(blockEnd(toolpath.moves, i)), colour));
      }
    }
  }
}

void drawToolOutside(const RZ& position, const PictureFrame& frame, const ClipRectangle& clip, Overlay2D& marks) {
  const Pixel centre(frame.widthPx / 2.0, frame.heightPx / 2.0), at = frame.pixelOf(position);
  const auto span = clipToRectangle(centre, at, clip.x0, clip.y0, clip.x1, clip.y1);
  if (!span || span->t1 >= 1) return;
  const Pixel edge = centre + span->t1 * (at - centre);
  marks.arrowhead(edge, at - centre, 1.4 * kArrowPx, kToolMarkColour);
}

void drawCrashMarks(const std::vector<CrashMark>& crashes, const PictureFrame& frame, const ClipRectangle& clip,
                    double radiusPx, Overlay2D& marks, std::vector<Label>& labels) {
  constexpr int kCorners = 32;
  for (const CrashMark& crash : crashes) {
    const Pixel at = frame.pixelOf(crash.at);
    const Pixel centre(std::clamp(at.x(), clip.x0, clip.x1), std::clamp(at.y(), clip.y0, clip.y1));
    std::vector<Pixel> disc;
    for (int k = 0; k < kCorners; ++k) {
      const double a = 2 * M_PI * k / kCorners;
      disc.push_back(centre + radiusPx * Pixel(std::cos(a), std::sin(a)));
    }
    marks.polygon(disc, kCrashColour);
    place(labels, {centre + Pixel(1.6 * radiusPx, 0.6 * radiusPx), crash.label, kCrashColour, Justify::Left, true, centre});
  }
}

void drawBarOutline(const BarOutline& bar, PartView view, const PictureFrame& frame, Overlay2D& lines) {
  const double r = bar.radiusMm, bore = bar.boreRadiusMm;
  for (double side : {-1.0, 1.0})
    for (double radius : bore > 0 ? std::vector{r, bore} : std::vector{r})
      lines.line(frame.pixelOf(RZ(side * radius, bar.zLowMm)), frame.pixelOf(RZ(side * radius, bar.zHighMm)),
                 kGhostLineColour);
  if (view != PartView::Iso) {
    for (double z : {bar.zLowMm, bar.zHighMm})
      for (double side : {-1.0, 1.0})  // the end faces, from the axis or the bore out
        lines.line(frame.pixelOf(RZ(side * bore, z)), frame.pixelOf(RZ(side * r, z)), kGhostLineColour);
    return;
  }
  // The right-hand end face's circles, seen at an angle: ellipses.
  constexpr int kSteps = 96;
  for (double radius : bore > 0 ? std::vector{r, bore} : std::vector{r})
    for (int k = 0; k < kSteps; ++k) {
      const double a0 = 2 * M_PI * k / kSteps, a1 = 2 * M_PI * (k + 1) / kSteps;
      lines.line(frame.pixelOf(Eigen::Vector3d(radius * std::cos(a0), radius * std::sin(a0), bar.zHighMm)),
                 frame.pixelOf(Eigen::Vector3d(radius * std::cos(a1), radius * std::sin(a1), bar.zHighMm)),
                 kGhostLineColour);
    }
}

void drawDimensions(const PartDimensions& dims, int decimals, const PictureFrame& frame, double topPx,
                    double ceilingPx, Overlay2D& lines, Overlay2D& marks, std::vector<Label>& labels,
                    std::vector<PixelSegment>& dimensionLines) {
  // Diameters: across the part at the middle of their face, the text beside the middle,
  // staggered so that neighbours do not collide.
  for (std::size_t n = 0; n < dims.diameters.size(); ++n) {
    const DiameterDimension& d = dims.diameters[n];
    const double z = 0.5 * (d.zLowMm + d.zHighMm), r = d.diameterMm / 2;
    const Pixel top = frame.pixelOf(RZ(r, z)), bottom = frame.pixelOf(RZ(-r, z));
    dimensionArrows(bottom, top, lines, marks, dimensionLines);
    const double up = (n % 2 == 0 ? 0.15 : -0.25) * (top.y() - bottom.y());
    // Beside its line rather than on it: a label never crosses a dimension line (label_layout.hpp).
    labels.push_back({0.5 * (top + bottom) + Pixel(6, up), "Ø" + number(d.diameterMm, decimals), kDimensionColour,
                      Justify::Left, true, 0.5 * (top + bottom) + Pixel(0, up)});
  }
  // Lengths: stacked upwards, the shortest lowest; extension lines from each face's outer
  // corner up past the dimension line.
  // The highest line's extension lines reach 6 px over it and stay clear of the title block.
  double spacing = std::max(22.0, 0.045 * frame.heightPx);
  if (!dims.lengths.empty())
    spacing = std::max(14.0, std::min(spacing, (ceilingPx - 8.0 - topPx) / (static_cast<double>(dims.lengths.size()) - 0.2)));
  for (std::size_t n = 0; n < dims.lengths.size(); ++n) {
    const LengthDimension& l = dims.lengths[n];
    const double y = topPx + spacing * (static_cast<double>(n) + 0.8);
    const Pixel low = frame.pixelOf(RZ(l.radiusLowMm, l.zLowMm)), high = frame.pixelOf(RZ(l.radiusHighMm, l.zHighMm));
    for (const Pixel& face : {low, high}) {
      const PixelSegment extension{face + Pixel(0, 4), Pixel(face.x(), y + 6)};
      lines.line(extension[0], extension[1], kDimensionColour);
      dimensionLines.push_back(extension);
    }
    dimensionArrows(Pixel(low.x(), y), Pixel(high.x(), y), lines, marks, dimensionLines);
    labels.push_back({Pixel(0.5 * (low.x() + high.x()), y + 5), number(l.zHighMm - l.zLowMm, decimals),
                      kDimensionColour, Justify::Centre, true, Pixel(0.5 * (low.x() + high.x()), y)});
  }
}

void drawScaleBar(const PictureFrame& frame, Overlay2D& lines, std::vector<Label>& labels) {
  const double mostMm = 0.2 * frame.widthPx / frame.pxPerMm;
  double length = std::pow(10.0, std::floor(std::log10(mostMm)));
  for (double step : {5.0, 2.0})
    if (length * step <= mostMm) {
      length *= step;
      break;
    }
  const double px = length * frame.pxPerMm, margin = 0.03 * frame.widthPx;
  const Pixel right(frame.widthPx - margin, 0.045 * frame.heightPx), left = right - Pixel(px, 0);
  lines.line(left, right, kInkColour);
  for (const Pixel& end : {left, right}) lines.line(end - Pixel(0, 6), end + Pixel(0, 6), kInkColour);
  lines.line(0.5 * (left + right) - Pixel(0, 4), 0.5 * (left + right) + Pixel(0, 4), kInkColour);
  labels.push_back({0.5 * (left + right) + Pixel(0, 10), number(length, length < 1 ? 1 : 0) + " mm", kInkColour,
                    Justify::Centre, false});
}

}  // namespace lathesim::render
