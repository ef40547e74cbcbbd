#pragma once
// The setup file's [machine] tailstock: a live centre supporting the bar's right-hand end.
//   [machine]
//   tailstock = { z = 0.0, diameter = 30.0 }
//     z         the centre's point (mm): where it enters the bar's centre hole, usually its face
//     diameter  the quill's diameter (mm); the centre is a 60° cone from its point out to it
// The tool and its holder are checked against it (sim/holder_check.hpp, "into_tailstock") and
// it is drawn in the pictures, the 3D view and the video, its quill kQuillLengthPerDiameter
// diameters long: a tool that far behind the centre meets the tailstock itself.

#include <optional>
#include <vector>

#include <toml++/toml.h>

#include "geometry/convex_polygon.hpp"
#include "setup/offset_setup.hpp"  // ReportProblem

namespace lathesim::setup {

struct Tailstock {
  double pointZMm = 0;      // the centre's point, on the axis
  double quillDiameterMm = 0;
};

/// The included angle of a lathe centre's point.
inline constexpr double kCentrePointAngleDeg = 60.0;
/// The quill's length, checked and drawn, in diameters.
inline constexpr double kQuillLengthPerDiameter = 3.0;

/// Where the cone meets the quill: the point's Z plus the quill's radius over tan 30°.
double coneEndZMm(const Tailstock& tailstock);

/// The centre (a triangle) and the quill (a rectangle) in the meridian plane, r ≥ 0.
std::vector<ConvexPolygon> tailstockRegions(const Tailstock& tailstock);

/// Reads `tailstock`'s value (an inline table of z and diameter); nullopt, with each problem
/// reported at its key, when it is not one.
std::optional<Tailstock> readTailstock(const toml::node& node, const ReportProblem& report);

}  // namespace lathesim::setup
