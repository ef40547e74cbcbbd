#pragma once
// Convex polygons of the (r, z) half-plane: tool outlines and the regions they sweep.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "geometry/rz.hpp"

namespace lathesim {

/// A convex polygon with its vertices in counter-clockwise order (r to the right, z up),
/// no three consecutive vertices collinear. Built only through the named constructors,
/// so every instance is valid.
class ConvexPolygon {
 public:
  /// The convex hull of any points (at least one). Degenerate hulls (a point, a segment)
  /// are kept as such: their signed distance is the plain distance.
  static ConvexPolygon hullOf(std::span<const RZ> points);

  /// The outline as given, if it is a simple convex polygon with non-zero area (either
  /// orientation); otherwise why not, in words a user can act on.
  struct Checked;
  static Checked fromOutline(std::span<const RZ> outline);

  const std::vector<RZ>& vertices() const { return vertices_; }

  /// Signed Euclidean distance (mm): negative inside, positive outside, exact on both sides.
  double signedDistance(const RZ& p) const;

  /// The region a move from a to b sweeps: conv((P + a) ∪ (P + b)).
  ConvexPolygon sweptAlong(const RZ& a, const RZ& b) const;

  ConvexPolygon translated(const RZ& offset) const;

  double area() const;
  RZ lowerBound() const;  // componentwise minimum of the vertices
  RZ upperBound() const;  // componentwise maximum of the vertices

 private:
  explicit ConvexPolygon(std::vector<RZ> ccwVertices) : vertices_(std::move(ccwVertices)) {}
  std::vector<RZ> vertices_;
};

struct ConvexPolygon::Checked {
  std::optional<ConvexPolygon> polygon;
  std::string problem;  // empty when polygon is set
};

}  // namespace lathesim
