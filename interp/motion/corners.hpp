#pragma once
// Chamfers and corner radii between two straight cuts (GSK980TDi §3.11: L and D in G01; Fanuc
// ,C and ,R). A move that asks for one (Move::cornerAfter) and the move after it meet at the
// corner P; u1 points from P back along the first, u2 from P along the second, φ the angle
// between them:
//   chamfer   A = P + d·u1, B = P + d·u2, with d the size from the corner (Fanuc ,C; GSK L under
//             No.181#0 = 1), or d = L / |u1 − u2| when L is the chamfer's own length (GSK type I)
//   radius    tangent points at d = R / tan(φ/2); the arc about P + R / sin(φ/2) · (u1 + u2)/|u1 + u2|,
//             turning the way the path turns
// The first move then ends at A, the second starts at B, and the chamfer (a feed) or the arc
// joins them, carrying the first move's block. Errors at the asking block: no next move, a next
// move that is not a straight cut (a rapid, an arc: next to arcs it is not simulated yet), or a
// size that does not fit either line (GSK §3.11.3). Two lines in line need no corner: none is
// made (GSK: the function does nothing).

#include <vector>

#include "interp/base/move.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp {

/// Inserts every corner `moves` ask for. Warnings go to `warnings`.
Status insertCorners(std::vector<Move>& moves, std::vector<Error>& warnings);

}  // namespace lathesim::interp
