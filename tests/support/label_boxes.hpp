#pragma once
// Label boxes as the pictures place them (render::partImageLayout), for the overprint tests.

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Core>

#include "render/part_image.hpp"

namespace lathesim::test {

/// Whether the segment runs through the label's inside: walked in quarter-pixel steps.
inline bool crosses(const render::PictureLabel& l, const std::array<Eigen::Vector2d, 2>& s) {
  const double length = (s[1] - s[0]).norm();
  const int steps = std::max(1, static_cast<int>(std::ceil(length * 4)));
  for (int k = 0; k <= steps; ++k) {
    const Eigen::Vector2d p = s[0] + (s[1] - s[0]) * (static_cast<double>(k) / steps);
    if (p.x() > l.left && p.x() < l.right && p.y() > l.bottom && p.y() < l.top) return true;
  }
  return false;
}

}  // namespace lathesim::test
