#pragma once
// The region a group of cuts removes while the spindle turns: a union of convex polygons
// of the (r, z) plane, revolved about the Z axis.
//
// For a 3D point at distance ρ from the axis, the signed distance to the revolved solid is
// the 2D signed distance of (ρ, z) to the region (the nearest point of a surface of
// revolution lies in the point's own meridian half-plane). A polygon reaching across the
// axis (r < 0) revolves together with its mirror image, so (−ρ, z) is measured as well.
// Outside the union the value is the exact distance; inside it is a lower bound of the
// depth, which is all a max-based removal needs.

#include <vector>

#include "geometry/convex_polygon.hpp"

namespace lathesim {

class RevolvedRegion {
 public:
  explicit RevolvedRegion(const std::vector<ConvexPolygon>& polygons);

  /// Signed distance (mm) of the point (ρ ≥ 0, z). Values beyond `cap` in magnitude are
  /// returned as ±cap or further: callers that clamp at a narrow band pass the band as cap
  /// and skip the exact edge search far from the boundary.
  double signedDistance(double rho, double z, double cap) const;

  /// Signed distances at the kColumn points (ρ, z0 + k·dz), k = 0…kColumn−1, with the same
  /// meaning and cap as signedDistance. A leaf's voxels share ρ along Z, and evaluating
  /// them together lets the compiler vectorise the edge loops.
  static constexpr int kColumn = 8;
  void signedDistanceColumn(double rho, double z0, double dz, double cap, double (&out)[kColumn]) const;

  /// The points (ρ, z0 + k·dz), k = 0…kColumn−1, made ready for every ρ in [ρLow, ρHigh]
  /// (voxel columns of many radii can share one place): per convex piece and point, the one
  /// edge whose line lies farthest out. Where an edge is so at both ends, by a margin, it is so
  /// throughout — the farthest of the lines is convex in ρ and meets that edge's line at both
  /// ends — and it alone gives the piece's distance there, inside or out.
  ///
  /// Where a piece's farthest edge at some point changes between ρLow and ρHigh, the range is
  /// split in halves (a few times at most) and each span planned on its own.
  class ColumnPlan {
   public:
    /// How many pieces are read one edge a point over some span of the range (the others are
    /// searched whole).
    int plannedPieces() const;

   private:
    friend class RevolvedRegion;
    static constexpr int kWhole = -1;  // the piece is searched whole at every point
    // A planned piece's edge at each point, its numbers laid out by point so that the points
    // are read as vectors.
    struct EdgesByPoint {
      double ax[kColumn], az[kColumn], nx[kColumn], nz[kColumn], length[kColumn];
    };
    // A piece's plan over a span of ρ that ends at rhoHigh (and starts where the piece's
    // previous span ends, or at the plan's ρLow): its entry in edges_, or kWhole.
    struct Span {
      double rhoHigh;
      int edges;
    };
    double z0_ = 0.0, dz_ = 0.0;
    std::vector<int> firstSpan_;  // per piece, then one past the last: its spans are spans_[firstSpan_[p], firstSpan_[p + 1])
    std::vector<Span> spans_;     // in ascending ρ
    std::vector<EdgesByPoint> edges_;
  };
  void planColumn(double rhoLow, double rhoHigh, double z0, double dz, ColumnPlan& plan) const;
  /// signedDistanceColumn(ρ, plan's z0 and dz, cap, out) for ρ within the plan's range, to the
  /// last bit: the planned pieces read one edge a point, computed as the whole search does.
  void signedDistanceColumn(const ColumnPlan& plan, double rho, double cap, double (&out)[kColumn]) const;

  /// The plain 2D signed distance of (r, z) to the union of the polygons, r any sign: no
  /// revolution, no mirror image (for regions that are not revolved: a thread's tool outline,
  /// a cut with the spindle stopped). Same meaning of cap as signedDistance.
  double planarDistance(double r, double z, double cap) const;
  /// The same at (r, z0 + k·dz), k = 0…kColumn−1, each lowered into out[k] (out is not reset).
  void planarDistanceColumnMin(double r, double z0, double dz, double cap, double (&out)[kColumn]) const;

  /// The part of this region that matters within `radius` of (ρ, z): the pieces that come
  /// that close, and of each only the edges that can be nearest there. Evaluating it there
  /// gives the same values as the whole region wherever they are ≤ radius minus the
  /// distance to (ρ, z); a leaf's voxels are evaluated with it.
  RevolvedRegion near(double rho, double z, double radius) const;
  /// The same as near(), written into `out`, whose memory is reused: for hot loops that
  /// take a subset per leaf.
  void nearInto(double rho, double z, double radius, RevolvedRegion& out) const;
  RevolvedRegion() = default;  // empty: a place for nearInto to write

  RZ lowerBound() const { return lower_; }  // bounds of the polygons (r may be negative)
  RZ upperBound() const { return upper_; }
  bool empty() const { return pieces_.empty(); }
  std::size_t pieceCount() const { return pieces_.size(); }

  /// The largest distance from the axis of any point of the revolved solid.
  double maxRadius() const;

 private:
  struct Edge {
    double ax, az;      // start vertex
    double dx, dz;      // edge vector
    double nx, nz;      // outward unit normal
    double inverseLengthSquared;
    double length;
  };
  struct Piece {
    int firstEdge;     // its edges are edges_[firstEdge, firstEdge + edgeCount)
    int edgeCount;
    bool isArea;       // a polygon with area (else a point or segment: plain distance)
    bool crossesAxis;  // its mirror image across the axis counts as well
  };
  static double pieceDistance(const Edge* edges, const Piece& piece, double r, double z, double cap);
  static void pieceDistanceColumn(const Edge* edges, const Piece& piece, double r, double z0, double dz, double cap,
                                  double (&out)[kColumn]);

  // The edge whose line lies farthest out at each point (ρ, z0 + k·dz) of a column; false
  // where at some point another's lies within rounding of it (then neither can be planned).
  bool farthestEdges(const Piece& piece, double rho, double z0, double dz, int (&edgeOf)[kColumn]) const;
  // Plans `piece` over ρ in [low, high], whose farthest edges are given, in spans split at most
  // `splits` times deep.
  void planSpans(const Piece& piece, double low, const int (&lowEdges)[kColumn], bool lowClear, double high,
                 const int (&highEdges)[kColumn], bool highClear, int splits, ColumnPlan& plan) const;

  void appendNear(const Piece& piece, double rho, double z, double radius, RevolvedRegion& subset) const;
  static constexpr int kMaxOrderedPieces = 16;

  std::vector<Edge> edges_;  // every piece's edges, piece after piece (flat, so that nearInto reuses memory)
  std::vector<Piece> pieces_;
  RZ lower_{0, 0};
  RZ upper_{0, 0};
};

}  // namespace lathesim
