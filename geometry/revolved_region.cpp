#include "geometry/revolved_region.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>

namespace lathesim {

namespace {

// Four points of a column in GCC vector types: one AVX2 register each in the AVX2 clones, two
// SSE2 registers elsewhere. Masks hold lanes −1 (true) or 0.
using Double4 = double __attribute__((vector_size(32)));
using Mask4 = std::int64_t __attribute__((vector_size(32)));

// The helpers below are always inlined into their callers (each compiled for its own
// processor), so their vector results never cross a call: GCC's note on the AVX call ABI
// does not apply.
#pragma GCC diagnostic ignored "-Wpsabi"

[[gnu::always_inline]] inline bool anyOf(const Mask4& m) { return (m[0] | m[1] | m[2] | m[3]) != 0; }

// A column's four values read and written as one vector. The column write reads the distances
// so: a vector read of values stored a lane at a time cannot take them from the stores in
// flight and waits until they reach the cache.
// (Vectors are handed back through a reference, not returned: clang refuses a function returning
// a 256-bit vector in code compiled without AVX, inlined or not.)
[[gnu::always_inline]] inline void loadFour(const double* values, Double4& v) { std::memcpy(&v, values, sizeof v); }
[[gnu::always_inline]] inline void storeFour(double* values, const Double4& v) { std::memcpy(values, &v, sizeof v); }

// An edge's line distance n·(p − a) at p = (r, z), and p's position along the edge u·(p − a),
// u = (−nz, nx): each the part in r, to which the part in z (nz·z, nx·z) is added. Every search
// of the edges computes them so, term by term (a plan's reading gives the whole search's values
// to the last bit); E is an edge, or four points' edges in vectors.
template <class E, class R, class V>
[[gnu::always_inline]] inline void radialLine(const E& e, R r, V& line) {
  line = e.nx * (r - e.ax) - e.nz * e.az;
}
template <class E, class R, class V>
[[gnu::always_inline]] inline void radialAlong(const E& e, R r, V& along) {
  along = -e.nz * (r - e.ax) - e.nx * e.az;
}

bool isSymmetricAboutAxis(const ConvexPolygon& polygon) {
  std::vector<RZ> mirrored = polygon.vertices();
  for (RZ& v : mirrored) v.x() = -v.x();
  const ConvexPolygon image = ConvexPolygon::hullOf(mirrored);
  if (image.vertices().size() != polygon.vertices().size()) return false;
  for (const RZ& v : image.vertices()) {
    bool found = false;
    for (const RZ& w : polygon.vertices()) found |= (v - w).norm() <= 1e-12 * (1.0 + w.norm());
    if (!found) return false;
  }
  return true;
}

}  // namespace

RevolvedRegion::RevolvedRegion(const std::vector<ConvexPolygon>& polygons) {
  for (const ConvexPolygon& polygon : polygons) {
    const auto& v = polygon.vertices();
    Piece piece{static_cast<int>(edges_.size()), 0, v.size() >= 3, false};
    // Across the axis the mirror image counts too, unless it is the polygon itself (a
    // bar's section): then measuring it again would only repeat the same numbers.
    piece.crossesAxis = polygon.lowerBound().x() < 0.0 && !isSymmetricAboutAxis(polygon);
    for (std::size_t i = 0; i < v.size(); ++i) {
      const RZ& a = v[i];
      const RZ& b = v[(i + 1) % v.size()];
      const RZ d = b - a;
      const double length = d.norm();
      if (length == 0.0) continue;
      // Counter-clockwise vertices: the outward normal is the edge turned clockwise.
      edges_.push_back({a.x(), a.y(), d.x(), d.y(), d.y() / length, -d.x() / length, 1.0 / (length * length), length});
    }
    if (v.size() == 1) edges_.push_back({v[0].x(), v[0].y(), 0, 0, 0, 0, 0, 0});
    piece.edgeCount = static_cast<int>(edges_.size()) - piece.firstEdge;
    if (pieces_.empty()) {
      lower_ = polygon.lowerBound();
      upper_ = polygon.upperBound();
    } else {
      lower_ = lower_.cwiseMin(polygon.lowerBound());
      upper_ = upper_.cwiseMax(polygon.upperBound());
    }
    pieces_.push_back(piece);
  }
}

double RevolvedRegion::pieceDistance(const Edge* edges, const Piece& piece, double r, double z, double cap) {
  const Edge* const begin = edges + piece.firstEdge;
  const Edge* const end = begin + piece.edgeCount;
  const bool isArea = piece.isArea;
  if (isArea) {
    double maxLine = -std::numeric_limits<double>::infinity();
    for (const Edge* e = begin; e != end; ++e) maxLine = std::max(maxLine, e->nx * (r - e->ax) + e->nz * (z - e->az));
    // Inside: exact. Outside but farther than cap from a supporting line: farther than cap
    // from the polygon too, so the exact search can be skipped.
    if (maxLine <= 0.0 || maxLine >= cap) return maxLine;
  }
  double best = std::numeric_limits<double>::infinity();
  for (const Edge* edge = begin; edge != end; ++edge) {
    const Edge& e = *edge;
    const double px = r - e.ax, pz = z - e.az;
    const double t = std::clamp((px * e.dx + pz * e.dz) * e.inverseLengthSquared, 0.0, 1.0);
    const double qx = px - t * e.dx, qz = pz - t * e.dz;
    best = std::min(best, qx * qx + qz * qz);
  }
  return std::sqrt(best);
}

double RevolvedRegion::signedDistance(double rho, double z, double cap) const {
  double d = std::numeric_limits<double>::infinity();
  for (const Piece& piece : pieces_) {
    d = std::min(d, pieceDistance(edges_.data(), piece, rho, z, cap));
    if (piece.crossesAxis) d = std::min(d, pieceDistance(edges_.data(), piece, -rho, z, cap));
  }
  return d;
}

// The hottest loop of a simulation: cloned for AVX2 where the processor has it (chosen at
// load time), plain SSE2 elsewhere. Written with plain ternaries over fixed-size arrays so
// that each k-loop becomes a few vector instructions.
//
// Outside a convex polygon the nearest point lies on the edge whose line is farthest out
// (the normals of a convex polygon turn monotonically, so no other edge's line can beat
// those of the feature the nearest point lies on). So where points lie outside and near,
// a second pass over the edges finds, per point, that edge and the point's position along
// it; the distance is its line distance, or past either end of the edge the distance to
// that vertex: √(line² + past²).
__attribute__((target_clones("avx2", "default"))) void RevolvedRegion::pieceDistanceColumn(
    const Edge* edges, const Piece& piece, double r, double z0, double dz, double cap, double (&out)[kColumn]) {
  // Two groups of four points.
  static_assert(kColumn == 8);
  const Edge* const begin = edges + piece.firstEdge;
  const Edge* const end = begin + piece.edgeCount;
  const Double4 z[2] = {Double4{0, 1, 2, 3} * dz + z0, Double4{4, 5, 6, 7} * dz + z0};
  const Double4 infinity = Double4{} + std::numeric_limits<double>::infinity();
  Double4 result[2];
  if (!piece.isArea) {  // a point or a segment: the plain distance to its edges
    Double4 best[2] = {infinity, infinity};
    for (const Edge* edge = begin; edge != end; ++edge) {
      const Edge& e = *edge;
      const double px = r - e.ax;
      const double radialDot = px * e.dx;
      for (int g = 0; g < 2; ++g) {
        const Double4 pz = z[g] - e.az;
        Double4 t = (radialDot + pz * e.dz) * e.inverseLengthSquared;
        t = t < 0.0 ? Double4{} : t;
        t = t > 1.0 ? Double4{} + 1.0 : t;
        const Double4 qx = px - t * e.dx, qz = pz - t * e.dz;
        const Double4 d2 = qx * qx + qz * qz;
        best[g] = d2 < best[g] ? d2 : best[g];
      }
    }
    for (int g = 0; g < 2; ++g)
      for (int k = 0; k < 4; ++k) result[g][k] = std::sqrt(best[g][k]);
  } else {
    Double4 line[2] = {-infinity, -infinity};
    for (const Edge* edge = begin; edge != end; ++edge) {
      const Edge& e = *edge;
      double radial;
      radialLine(e, r, radial);
      for (int g = 0; g < 2; ++g) {
        const Double4 d = radial + e.nz * z[g];
        line[g] = d > line[g] ? d : line[g];
      }
    }
    // Inside, or farther than cap from a supporting line: the line distance is the answer
    // (see signedDistance). Only points outside and near need the edges themselves.
    const Mask4 outsideNear[2] = {(line[0] > 0.0) & (line[0] < cap), (line[1] > 0.0) & (line[1] < cap)};
    if (anyOf(outsideNear[0] | outsideNear[1])) {
      Double4 farthest[2] = {-infinity, -infinity}, along[2] = {}, length[2] = {};
      for (const Edge* edge = begin; edge != end; ++edge) {
        const Edge& e = *edge;
        // Line distance n·(p − a) and position along the edge u·(p − a), u = (−nz, nx).
        double radial, radialPosition;
        radialLine(e, r, radial);
        radialAlong(e, r, radialPosition);
        for (int g = 0; g < 2; ++g) {
          const Double4 d = radial + e.nz * z[g];
          const Double4 a = radialPosition + e.nx * z[g];
          const Mask4 farther = d > farthest[g];
          farthest[g] = farther ? d : farthest[g];
          along[g] = farther ? a : along[g];
          length[g] = farther ? Double4{} + e.length : length[g];
        }
      }
      for (int g = 0; g < 2; ++g) {
        Double4 past = -along[g];
        const Double4 beyond = along[g] - length[g];
        past = beyond > past ? beyond : past;
        past = past > 0.0 ? past : Double4{};
        const Double4 d2 = farthest[g] * farthest[g] + past * past;
        Double4 d;
        for (int k = 0; k < 4; ++k) d[k] = std::sqrt(d2[k]);
        line[g] = outsideNear[g] ? d : line[g];
      }
    }
    result[0] = line[0];
    result[1] = line[1];
  }
  for (int g = 0; g < 2; ++g) {
    Double4 before;
    loadFour(out + 4 * g, before);
    storeFour(out + 4 * g, result[g] < before ? result[g] : before);
  }
}

void RevolvedRegion::signedDistanceColumn(double rho, double z0, double dz, double cap, double (&out)[kColumn]) const {
  for (double& v : out) v = std::numeric_limits<double>::infinity();
  for (const Piece& piece : pieces_) {
    pieceDistanceColumn(edges_.data(), piece, rho, z0, dz, cap, out);
    if (piece.crossesAxis) pieceDistanceColumn(edges_.data(), piece, -rho, z0, dz, cap, out);
  }
}

int RevolvedRegion::ColumnPlan::plannedPieces() const {
  int planned = 0;
  for (std::size_t p = 0; p + 1 < firstSpan_.size(); ++p)
    planned += std::any_of(spans_.begin() + firstSpan_[p], spans_.begin() + firstSpan_[p + 1],
                           [](const Span& span) { return span.edges != kWhole; });
  return planned;
}

bool RevolvedRegion::farthestEdges(const Piece& piece, double rho, double z0, double dz, int (&edgeOf)[kColumn]) const {
  // An edge must lead the next one by more than rounding can take back anywhere between.
  constexpr double kMargin = 1e-9;
  for (int k = 0; k < kColumn; ++k) {
    const double z = static_cast<double>(k) * dz + z0;
    double first = -std::numeric_limits<double>::infinity(), second = first;
    for (int i = piece.firstEdge; i < piece.firstEdge + piece.edgeCount; ++i) {
      const Edge& e = edges_[i];
      double d;
      radialLine(e, rho, d);
      d += e.nz * z;
      if (d > first) {
        second = first;
        first = d;
        edgeOf[k] = i;
      } else {
        second = std::max(second, d);
      }
    }
    if (!(first - second > kMargin)) return false;
  }
  return true;
}

void RevolvedRegion::planSpans(const Piece& piece, double low, const int (&lowEdges)[kColumn], bool lowClear,
                               double high, const int (&highEdges)[kColumn], bool highClear, int splits,
                               ColumnPlan& plan) const {
  const bool same = lowClear && highClear && std::equal(lowEdges, lowEdges + kColumn, highEdges);
  // Where an end is within rounding of a tie, halving cannot help: that end stays.
  if (!same && lowClear && highClear && splits > 0) {
    const double middle = 0.5 * (low + high);
    int middleEdges[kColumn];
    const bool middleClear = farthestEdges(piece, middle, plan.z0_, plan.dz_, middleEdges);
    planSpans(piece, low, lowEdges, lowClear, middle, middleEdges, middleClear, splits - 1, plan);
    planSpans(piece, middle, middleEdges, middleClear, high, highEdges, highClear, splits - 1, plan);
    return;
  }
  if (!same) {
    plan.spans_.push_back({high, ColumnPlan::kWhole});
    return;
  }
  plan.spans_.push_back({high, static_cast<int>(plan.edges_.size())});
  ColumnPlan::EdgesByPoint& edges = plan.edges_.emplace_back();
  for (int k = 0; k < kColumn; ++k) {
    const Edge& e = edges_[lowEdges[k]];
    edges.ax[k] = e.ax;
    edges.az[k] = e.az;
    edges.nx[k] = e.nx;
    edges.nz[k] = e.nz;
    edges.length[k] = e.length;
  }
}

void RevolvedRegion::planColumn(double rhoLow, double rhoHigh, double z0, double dz, ColumnPlan& plan) const {
  // Halving a bin's range twice at most: a contour's pieces change edge within a voxel-wide bin
  // now and then, rarely more than once.
  constexpr int kSplits = 2;
  plan.z0_ = z0;
  plan.dz_ = dz;
  plan.firstSpan_.clear();
  plan.spans_.clear();
  plan.edges_.clear();
  for (const Piece& piece : pieces_) {
    plan.firstSpan_.push_back(static_cast<int>(plan.spans_.size()));
    if (!piece.isArea || piece.crossesAxis) {
      plan.spans_.push_back({rhoHigh, ColumnPlan::kWhole});
      continue;
    }
    int lowEdges[kColumn], highEdges[kColumn];
    const bool lowClear = farthestEdges(piece, rhoLow, z0, dz, lowEdges);
    const bool highClear = farthestEdges(piece, rhoHigh, z0, dz, highEdges);
    planSpans(piece, rhoLow, lowEdges, lowClear, rhoHigh, highEdges, highClear, kSplits, plan);
  }
  plan.firstSpan_.push_back(static_cast<int>(plan.spans_.size()));
}

namespace {

// Four points' edges, one a point (a plan's EdgesByPoint, from point 4·g on).
struct EdgeLanes {
  Double4 ax, az, nx, nz, length;
};

template <class EdgesByPoint>
[[gnu::always_inline]] inline EdgeLanes lanesOf(const EdgesByPoint& edges, int g) {
  EdgeLanes lanes;
  std::memcpy(&lanes.ax, edges.ax + 4 * g, sizeof lanes.ax);
  std::memcpy(&lanes.az, edges.az + 4 * g, sizeof lanes.az);
  std::memcpy(&lanes.nx, edges.nx + 4 * g, sizeof lanes.nx);
  std::memcpy(&lanes.nz, edges.nz + 4 * g, sizeof lanes.nz);
  std::memcpy(&lanes.length, edges.length + 4 * g, sizeof lanes.length);
  return lanes;
}

}  // namespace

// Cloned as pieceDistanceColumn is. A planned piece is read with pieceDistanceColumn's
// arithmetic for the one edge farthest out at each point, four points at a time.
__attribute__((target_clones("avx2", "default"))) void RevolvedRegion::signedDistanceColumn(
    const ColumnPlan& plan, double rho, double cap, double (&out)[kColumn]) const {
  // The distances so far, in registers (in out only while a piece is searched whole).
  Double4 lowest[2] = {Double4{} + std::numeric_limits<double>::infinity(), Double4{} + std::numeric_limits<double>::infinity()};
  const Double4 z[2] = {Double4{0, 1, 2, 3} * plan.dz_ + plan.z0_, Double4{4, 5, 6, 7} * plan.dz_ + plan.z0_};
  for (std::size_t p = 0; p < pieces_.size(); ++p) {
    const Piece& piece = pieces_[p];
    int span = plan.firstSpan_[p];
    while (span + 1 < plan.firstSpan_[p + 1] && rho > plan.spans_[span].rhoHigh) ++span;
    const int planned = plan.spans_[span].edges;
    if (planned == ColumnPlan::kWhole) {
      storeFour(out, lowest[0]);
      storeFour(out + 4, lowest[1]);
      pieceDistanceColumn(edges_.data(), piece, rho, plan.z0_, plan.dz_, cap, out);
      if (piece.crossesAxis) pieceDistanceColumn(edges_.data(), piece, -rho, plan.z0_, plan.dz_, cap, out);
      loadFour(out, lowest[0]);
      loadFour(out + 4, lowest[1]);
      continue;
    }
    const ColumnPlan::EdgesByPoint& edges = plan.edges_[planned];
    for (int g = 0; g < 2; ++g) {
      const EdgeLanes e = lanesOf(edges, g);
      Double4 line;
      radialLine(e, rho, line);
      line += e.nz * z[g];
      const Mask4 outsideNear = (line > 0.0) & (line < cap);
      Double4 distance = line;
      if (anyOf(outsideNear)) {
        Double4 along;
        radialAlong(e, rho, along);
        along += e.nx * z[g];
        Double4 past = -along;
        const Double4 beyond = along - e.length;
        past = beyond > past ? beyond : past;
        past = past > 0.0 ? past : Double4{};
        const Double4 d2 = line * line + past * past;
        Double4 d{};
        for (int k = 0; k < 4; ++k) d[k] = std::sqrt(d2[k]);
        distance = outsideNear ? d : line;
      }
      lowest[g] = distance < lowest[g] ? distance : lowest[g];
    }
  }
  storeFour(out, lowest[0]);
  storeFour(out + 4, lowest[1]);
}

double RevolvedRegion::planarDistance(double r, double z, double cap) const {
  double d = std::numeric_limits<double>::infinity();
  for (const Piece& piece : pieces_) d = std::min(d, pieceDistance(edges_.data(), piece, r, z, cap));
  return d;
}

void RevolvedRegion::planarDistanceColumnMin(double r, double z0, double dz, double cap, double (&out)[kColumn]) const {
  for (const Piece& piece : pieces_) pieceDistanceColumn(edges_.data(), piece, r, z0, dz, cap, out);
}

RevolvedRegion RevolvedRegion::near(double rho, double z, double radius) const {
  RevolvedRegion subset;
  nearInto(rho, z, radius, subset);
  return subset;
}

void RevolvedRegion::nearInto(double rho, double z, double radius, RevolvedRegion& subset) const {
  subset.edges_.clear();
  subset.pieces_.clear();
  subset.lower_ = lower_;
  subset.upper_ = upper_;
  // Nearest pieces first: a column's later pieces then often cannot lower its values and
  // skip their edge search (see pieceDistanceColumn).
  std::pair<double, int> order[kMaxOrderedPieces];
  int ordered = 0;
  for (int p = 0; p < static_cast<int>(pieces_.size()); ++p) {
    const Piece& piece = pieces_[p];
    double d = pieceDistance(edges_.data(), piece, rho, z, radius + 1.0);
    if (piece.crossesAxis) d = std::min(d, pieceDistance(edges_.data(), piece, -rho, z, radius + 1.0));
    if (d > radius) continue;
    if (ordered < kMaxOrderedPieces) order[ordered++] = {d, p};
    else appendNear(piece, rho, z, radius, subset);  // beyond the sorted few: kept in order
  }
  std::sort(order, order + ordered);
  for (int i = 0; i < ordered; ++i) appendNear(pieces_[order[i].second], rho, z, radius, subset);
}

void RevolvedRegion::appendNear(const Piece& piece, double rho, double z, double radius, RevolvedRegion& subset) const {
  const Edge* const begin = edges_.data() + piece.firstEdge;
  const Edge* const end = begin + piece.edgeCount;
  Piece kept{static_cast<int>(subset.edges_.size()), 0, piece.isArea, piece.crossesAxis};
  if (!piece.isArea || piece.crossesAxis) {
    subset.edges_.insert(subset.edges_.end(), begin, end);
  } else {
    // Inside a convex polygon the distance is set by the edge line farthest out; outside,
    // the nearest point lies on that edge too (or on a vertex it shares). An edge whose line
    // is more than 2·radius behind the farthest one at the centre cannot become the
    // farthest anywhere within radius (each line distance changes by at most radius).
    double farthest = -std::numeric_limits<double>::infinity();
    for (const Edge* e = begin; e != end; ++e) farthest = std::max(farthest, e->nx * (rho - e->ax) + e->nz * (z - e->az));
    for (const Edge* e = begin; e != end; ++e)
      if (e->nx * (rho - e->ax) + e->nz * (z - e->az) >= farthest - 2.0 * radius) subset.edges_.push_back(*e);
  }
  kept.edgeCount = static_cast<int>(subset.edges_.size()) - kept.firstEdge;
  subset.pieces_.push_back(kept);
}

double RevolvedRegion::maxRadius() const { return std::max(std::abs(lower_.x()), std::abs(upper_.x())); }

}  // namespace lathesim
