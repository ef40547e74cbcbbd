#pragma once
// Tool nose radius compensation G40/G41/G42 (lathe-cycles.md §8), a stage after the moves are
// made: the interpreter makes every move as programmed, each carrying the compensation in
// force (Move::noseComp); this stage replaces each compensated chain by the path of the
// imaginary tip P = C + R·s, where C is the nose centre on the programmed path offset by R to
// the G41 (left) or G42 (right) side, looking along the travel with Z to the right and X up,
// and s the tip number's direction (geometry/imaginary_tip.hpp; tip 0/9: P = C).
//
// A chain is: a start-up move (the first move under G41/G42; G00/G01, else an error, Fanuc
// PS0034), the compensated moves after it, and the cancel move (the first move after them
// without compensation: G40 in a G00/G01 block, or a cycle's first leg; an arc is an error).
// Dwells inside a chain stay at the corner where the tool stands.
//   start-up (type A): from its programmed start to the centre offset perpendicular to the
//            NEXT move's direction at its start (to its own direction if none follows)
//   offset   lines become parallel lines, arcs concentric arcs of radius ρ ∓ R
//   corners  inner (the path turns toward the tool's side): the offset paths meet at their
//            intersection, both trimmed; outer turning by at most 90° (a corner of 90°–180°
//            on the work side): both extended to their intersection; outer turning by more
//            than 90°: Fanuc's extra vectors E → E + R·t1 → S − R·t2 → S (t1, t2 the unit
//            tangents at the corner, E and S the offset ends), straight moves of the first
//            block. Where an extended arc never meets the other path, the tangents at E and
//            S are extended to their intersection instead (straight moves).
//   cancel   the last compensated move ends with the centre offset perpendicular to it at
//            its end; the cancel move goes from there to its programmed end point.
// Errors: an arc starting or cancelling (PS0034); an offset arc of radius ≤ 0 or an offset
// segment that runs backwards after its corners are trimmed (interference, PS0041); inner
// corner paths that never meet (PS0033); the side, R or tip changing inside a chain.
// With R = 0 nothing moves (the checks still apply).

#include <vector>

#include "interp/contour/contour.hpp"
#include "interp/base/move.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp {

/// Compensates the chains of `moves` in place: corner moves may be added (carrying their
/// block's source), zero-length straight moves left out.
Status compensateNoseRadius(std::vector<Move>& moves);

/// A G70–G73 contour compensated the same way (GSK: G41/G42 in the ns block). The cycle ends
/// the compensation, so a chain still open at the contour's end stops with the centre
/// perpendicular to the last segment at its end; there is no cancel move.
/// `noseComps[i]` is the compensation in force in segment i's block.
Result<Contour> compensatedContour(const Contour& contour, const std::vector<NoseComp>& noseComps);

}  // namespace lathesim::interp
