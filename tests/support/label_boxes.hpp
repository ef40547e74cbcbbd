#pragma once
// Label boxes as the pictures place them (render::partImageLayout), for the overprint tests:
// what overprints what, worked out here apart from render's own placement.

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "render/part_image.hpp"

namespace lathesim::test {

using LayoutSegment = std::array<Eigen::Vector2d, 2>;

/// Whether the segment runs through the label's inside: walked in quarter-pixel steps.
inline bool crosses(const render::PictureLabel& l, const LayoutSegment& s) {
  const double length = (s[1] - s[0]).norm();
  const int steps = std::max(1, static_cast<int>(std::ceil(length * 4)));
  for (int k = 0; k <= steps; ++k) {
    const Eigen::Vector2d p = s[0] + (s[1] - s[0]) * (static_cast<double>(k) / steps);
    if (p.x() > l.left && p.x() < l.right && p.y() > l.bottom && p.y() < l.top) return true;
  }
  return false;
}

/// Whether two segments have a point in common: the ends of each on either side of (or on)
/// the other's line, or, on one line, overlapping.
inline bool segmentsIntersect(const LayoutSegment& a, const LayoutSegment& b) {
  const auto side = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
    const double c = (q - p).x() * (r - p).y() - (q - p).y() * (r - p).x();
    return c > 0 ? 1 : c < 0 ? -1 : 0;
  };
  const int a0 = side(a[0], a[1], b[0]), a1 = side(a[0], a[1], b[1]);
  const int b0 = side(b[0], b[1], a[0]), b1 = side(b[0], b[1], a[1]);
  if (a0 * a1 < 0 && b0 * b1 < 0) return true;
  const auto within = [](const Eigen::Vector2d& p, const LayoutSegment& s) {
    return p.x() >= std::min(s[0].x(), s[1].x()) && p.x() <= std::max(s[0].x(), s[1].x()) &&
           p.y() >= std::min(s[0].y(), s[1].y()) && p.y() <= std::max(s[0].y(), s[1].y());
  };
  return (a0 == 0 && within(b[0], a)) || (a1 == 0 && within(b[1], a)) || (b0 == 0 && within(a[0], b)) ||
         (b1 == 0 && within(a[1], b));
}

/// Everything in `layout` that overprints: two labels overlapping, a label across a dimension
/// line or a leader, a leader across a dimension line or another leader; one line each.
inline std::vector<std::string> overprints(const render::PictureLayout& layout) {
  std::vector<std::string> found;
  const auto say = [&](const std::string& what) { found.push_back(what); };
  const auto text = [](const LayoutSegment& s) {
    std::ostringstream out;
    out << "(" << s[0].transpose() << ") – (" << s[1].transpose() << ")";
    return out.str();
  };
  for (std::size_t i = 0; i < layout.labels.size(); ++i) {
    const render::PictureLabel& a = layout.labels[i];
    for (std::size_t j = i + 1; j < layout.labels.size(); ++j) {
      const render::PictureLabel& b = layout.labels[j];
      if (a.left < b.right && b.left < a.right && a.bottom < b.top && b.bottom < a.top)
        say("'" + a.text + "' over '" + b.text + "'");
    }
    for (const LayoutSegment& line : layout.dimensionLines)
      if (crosses(a, line)) say("'" + a.text + "' across the dimension line " + text(line));
    for (const LayoutSegment& leader : layout.leaders)
      if (crosses(a, leader)) say("a leader " + text(leader) + " across '" + a.text + "'");
  }
  for (std::size_t i = 0; i < layout.leaders.size(); ++i) {
    for (const LayoutSegment& line : layout.dimensionLines)
      if (segmentsIntersect(layout.leaders[i], line))
        say("a leader " + text(layout.leaders[i]) + " across the dimension line " + text(line));
    for (std::size_t j = i + 1; j < layout.leaders.size(); ++j)
      if (segmentsIntersect(layout.leaders[i], layout.leaders[j]))
        say("the leaders " + text(layout.leaders[i]) + " and " + text(layout.leaders[j]) + " cross");
  }
  return found;
}

}  // namespace lathesim::test
