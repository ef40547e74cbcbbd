#pragma once
// A section's surface as the pictures need it: the loose segments that marching squares
// gives, joined into polylines and thinned to what a picture of a given scale can show.

#include <vector>

#include "geometry/meridian_profile.hpp"

namespace lathesim {

/// Joins segments that share end points (equal within `weldMm`) into polylines, in no
/// particular order or direction. A chain that comes back to its start is closed: its last
/// point repeats its first. A point met by more than two segments ends the chains there.
std::vector<std::vector<RZ>> chainSegments(const std::vector<Segment>& segments, double weldMm);

/// Douglas–Peucker: the fewest of the polyline's own points such that no dropped point lies
/// farther than `toleranceMm` from the line kept across it. The ends are always kept (a
/// closed polyline keeps its repeated point too).
std::vector<RZ> simplifyPolyline(const std::vector<RZ>& points, double toleranceMm);

/// The section's surface joined and thinned, each polyline directed so that the material lies
/// on its right, r across and z up: along an outer diameter it runs towards −z, along a bore
/// towards +z (revolvedMesh then faces outwards).
std::vector<std::vector<RZ>> profilePolylines(const MeridianProfile& profile, double toleranceMm);

}  // namespace lathesim
