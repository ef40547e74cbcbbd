#pragma once
// G90/G94 under G41/G42 (lathe-cycles.md §8: single cycles "are offset using the tip number";
// on Fanuc the side then comes from the tip, not from G41/G42). The cycle's cut B → C is
// moved so that the nose circle touches the programmed cut line from the start point A's
// side: the tip's line is the cut line moved by R·n + R·s, n the line's unit normal toward A,
// s the tip direction (tool_offset.hpp). The cut keeps its extent along the cycle's own axis
// (Z for G90, X for G94), so its new ends B′ and C′ stay on the lines of steps 1 and 3:
//   step 1  rapid  A → B′,  step 2  feed  B′ → C′,  step 3  feed  C′ → D,  step 4  rapid  D → A
// A straight cycle with tip 1–4 is unchanged (the nose touches off on both axes); with R 0,
// no G41/G42, or A on the cut's line, nothing changes. The legs stay uncompensated moves:
// they are not part of a G41/G42 chain.

#include <vector>

#include "interp/contour/cycle_leg.hpp"
#include "interp/base/move.hpp"

namespace lathesim::interp {

/// `legs` of a G90 (`axial`) or G94 cycle started at `start`, compensated with `comp`.
std::vector<CycleLeg> noseCompensatedCycle(const std::vector<CycleLeg>& legs, const RZ& start,
                                           bool axial, const NoseComp& comp);

}  // namespace lathesim::interp
