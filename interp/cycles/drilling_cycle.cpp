// G81/G82/G83 on a lathe, the drill on the axis (Haas lathe manual's drilling canned cycles;
// Fanuc 0i-T's G83 front drilling cycle read the same way with the tool at X0 ⚠):
//   step 1  rapid  A → (X_A, R)
//   step 2  feed   to the bottom Z; G83 with Q: a peck of Q at a time, after each but the last
//   step 3  rapid  back to R, then
//   step 4  rapid  down again to the last depth less the clearance, the next peck fed from there
//   (G82/G83 P: the dwell at the bottom, made by the caller between the two lists)
//   step 5  rapid  back to A's Z (the initial point ⚠: where Haas's lathe cycles return is not
//                  checked against the manual)
// G84 (tapping: Fanuc 0i-T's front tapping cycle, Haas's G84 ⚠) feeds to the bottom in one go
// (step 2); there the spindle reverses and the tap feeds back out to R at the same feed
// (step 3, at feed), then the tool rapids back to A's Z (step 5).
// Zero-length legs are left out.

#include "interp/cycles/drilling_cycle.hpp"

#include <cmath>

namespace lathesim::interp {

DrillingLegs drillingLegs(const RZ& start, const DrillingParams& params) {
  DrillingLegs legs;
  const double x = start.x();
  const double direction = params.bottomZ < params.rPlaneZ ? -1.0 : 1.0;  // toward the bottom
  const auto add = [](std::vector<CycleLeg>& to, MoveKind kind, const RZ& from, const RZ& end, int step) {
    if (from != end) to.push_back({kind, from, end, step});
  };
  RZ at = start;
  add(legs.down, MoveKind::Rapid, at, RZ(x, params.rPlaneZ), 1);
  at = RZ(x, params.rPlaneZ);
  const double total = std::abs(params.bottomZ - params.rPlaneZ);
  double depth = params.peckMm > 0 ? std::min(params.peckMm, total) : total;
  for (;;) {
    const RZ reached(x, params.rPlaneZ + direction * depth);
    add(legs.down, MoveKind::Feed, at, reached, 2);
    at = reached;
    if (depth >= total) break;
    add(legs.down, MoveKind::Rapid, at, RZ(x, params.rPlaneZ), 3);
    const double backDown = std::max(depth - params.clearanceMm, 0.0);
    add(legs.down, MoveKind::Rapid, RZ(x, params.rPlaneZ), RZ(x, params.rPlaneZ + direction * backDown), 4);
    at = RZ(x, params.rPlaneZ + direction * backDown);
    depth = std::min(depth + params.peckMm, total);
  }
  if (params.tapping) {
    add(legs.up, MoveKind::Feed, at, RZ(x, params.rPlaneZ), 3);
    at = RZ(x, params.rPlaneZ);
  }
  add(legs.up, MoveKind::Rapid, at, RZ(x, start.y()), 5);
  return legs;
}

}  // namespace lathesim::interp
