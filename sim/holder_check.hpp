#pragma once
// Collisions of what must never touch: a holder body running into material
// ("holder_into_stock": the holder does not cut, so the material inside its swept region is
// measured, not removed) and any tool or holder entering the chuck ("into_chuck").

#include <map>
#include <span>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "interp/base/move.hpp"
#include "sim/chuck_spec.hpp"
#include "sim/stock.hpp"
#include "sim/stock_spec.hpp"

namespace lathesim::sim {

struct Collision;

struct CollisionChecks {
  std::map<int, ConvexPolygon> cutters;  // tool number → cutter outline (as swept)
  std::map<int, ConvexPolygon> holders;  // tool number → holder body; tools without one are absent
  std::vector<ConvexPolygon> chuck;      // the chuck's regions in (r, z), r ≥ 0
  std::vector<ConvexPolygon> tailstock;  // the tailstock's centre and quill in (r, z), r ≥ 0; none without one
};

/// The chuck's regions for a bar: the jaws (bar radius … jaw radius, Z from face − grip length
/// to face) and the body (axis … jaw radius, 100 mm behind the jaws).
std::vector<ConvexPolygon> chuckRegions(const ChuckSpec& chuck, const StockSpec& stock);

/// Checks `moves` (already cut from `stock`) and appends their collisions; a move that
/// continues a collision of the same line and kind adds its volume to it.
/// holder_into_stock: material deeper than one voxel inside the holder's swept region, more
/// than kCollisionVoxels voxels' worth. into_chuck: the largest revolved volume any piece
/// of the cutter's or the holder's sweep has inside the chuck (any positive volume);
/// into_tailstock: the same inside the tailstock's centre and quill. Arcs are swept as chords
/// of at most 5°.
void checkMoves(const CollisionChecks& checks, std::span<const interp::Move> moves, const Stock& stock,
                std::vector<Collision>& collisions);

}  // namespace lathesim::sim
