#pragma once
// The path a rapid takes (control parameter rapid_positioning; GSK980TDi §3.2, Fanuc LRP).
// Non-linear positioning, the default on both presets: the axes start together, each at its
// own rapid rate, so the one with less time to go arrives first and the other goes on alone:
//   tX = |Δr| / rapid X,  tZ = |ΔZ| / rapid Z,  t1 = min(tX, tZ)
//   leg 1  from → corner = from + t1·(±rapid X, ±rapid Z)   both axes (a diagonal)
//   leg 2  corner → to                                      the slower axis alone
// Each leg takes the time the rapid's own rule gives it (cycle_time.hpp): t1 and
// max(tX, tZ) − t1, so the rapid takes max(tX, tZ) as before. A rapid along one axis, or
// whose axes arrive together, stays one move; so does every rapid under linear positioning,
// which moves in a straight line in the same time.

#include <vector>

#include "interp/control/machine_limits.hpp"
#include "interp/base/move.hpp"

namespace lathesim::interp {

/// Replaces each rapid of `moves` that moves both axes by its two legs (kind Rapid, the same
/// block, line and cycle step), the diagonal first.
void splitRapidsIntoAxisLegs(std::vector<Move>& moves, const MachineLimits& machine);

}  // namespace lathesim::interp
