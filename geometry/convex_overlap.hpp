#pragma once
// Where two convex polygons of the (r, z) half-plane overlap, and the volume that overlap
// sweeps when revolved about the Z axis (Pappus).

#include <vector>

#include "geometry/convex_polygon.hpp"

namespace lathesim {

struct Overlap {
  double areaMm2 = 0.0;
  RZ centroid{0, 0};
};

/// The common part of a and b (Sutherland–Hodgman: b's edges clip a). Zero area when they
/// are disjoint or only touch.
Overlap overlapOf(const ConvexPolygon& a, const ConvexPolygon& b);

/// Convex pieces whose union is the closure of a \ b (b's edges cut a, one piece outside each
/// edge that a reaches past): empty when b covers a. Pieces of no area (where the two only
/// share a boundary) are left out.
std::vector<ConvexPolygon> differenceOf(const ConvexPolygon& a, const ConvexPolygon& b);

/// The volume (mm³) of the overlap revolved about Z: area · 2π · centroid radius. For regions
/// at r ≥ 0.
double revolvedVolumeMm3(const Overlap& overlap);

}  // namespace lathesim
