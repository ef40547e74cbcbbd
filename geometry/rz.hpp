#pragma once
// A point of the lathe's meridian half-plane, the plane every turned shape lives in.

#include <numbers>

#include <Eigen/Core>

namespace lathesim {

/// (radius mm, Z mm): x() is the distance from the spindle axis — a radius, never a
/// diameter — and y() is the position along the spindle axis, +Z towards the tailstock.
/// Programs speak in diameters; interp halves them once, when a move is made.
using RZ = Eigen::Vector2d;

inline double diameterOf(const RZ& p) { return 2.0 * p.x(); }

/// One turn of the spindle, in radians.
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

}  // namespace lathesim
