#pragma once
// A crash (a collision the simulation found) marked where it happened: a red disc and a label
// in the part pictures and the video, a red marker in report.html's 3D view.

#include <algorithm>
#include <array>
#include <string>

#include "geometry/rz.hpp"

namespace lathesim::render {

struct CrashMark {
  RZ at{0, 0};        // where the tool stood: (radius, Z) mm in the meridian plane
  std::string label;  // "crash, line 8"
};

/// The marker's colour: pure red, redder than the rapids' dashes (picture_annotations.hpp).
inline constexpr std::array<double, 3> kCrashColour{1.0, 0.0, 0.0};

/// The marker's radius in a picture `heightPx` high.
inline double crashMarkRadiusPx(int heightPx) { return std::max(6.0, heightPx / 80.0); }

}  // namespace lathesim::render
