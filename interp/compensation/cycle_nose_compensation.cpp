// G90/G94 nose radius compensation by the tip number; see cycle_nose_compensation.hpp.

#include "geometry/imaginary_tip.hpp"
#include "interp/compensation/cycle_nose_compensation.hpp"

#include <cmath>

#include "interp/base/tolerance.hpp"
#include "interp/compensation/tool_offset.hpp"

namespace lathesim::interp {

std::vector<CycleLeg> noseCompensatedCycle(const std::vector<CycleLeg>& legs, const RZ& start,
                                           bool axial, const NoseComp& comp) {
  const CycleLeg* cut = nullptr;
  for (const CycleLeg& leg : legs) {
    if (leg.step == 2) cut = &leg;
  }
  if (comp.side == NoseSide::None || comp.radiusMm <= 0 || cut == nullptr) return legs;
  const RZ b = cut->from;
  const RZ c = cut->to;
  const RZ along = c - b;
  // The cycle's own axis: Z (y) for G90, X (x) for G94; the cut must move along it.
  const int axis = axial ? 1 : 0;
  if (std::abs(along[axis]) < kTolMm) return legs;
  RZ normal = RZ(along.y(), -along.x()).normalized();
  const double side = normal.dot(start - b);
  if (std::abs(side) < kTolMm) return legs;
  if (side < 0) normal = -normal;
  const RZ shift = comp.radiusMm * (normal + imaginaryTipDirection(comp.tip));
  // Slide the moved line back along itself so its ends keep their coordinate on `axis`.
  const RZ moved = shift - (shift[axis] / along[axis]) * along;
  const RZ bMoved = b + moved;
  const RZ cMoved = c + moved;
  const RZ d = axial ? RZ(start.x(), c.y()) : RZ(c.x(), start.y());
  std::vector<CycleLeg> compensated;
  for (const CycleLeg& leg : {CycleLeg{MoveKind::Rapid, start, bMoved, 1, RZ(0, 0)},
                              CycleLeg{MoveKind::Feed, bMoved, cMoved, 2, RZ(0, 0)},
                              CycleLeg{MoveKind::Feed, cMoved, d, 3, RZ(0, 0)},
                              CycleLeg{MoveKind::Rapid, d, start, 4, RZ(0, 0)}}) {
    if ((leg.to - leg.from).norm() > kTolMm) compensated.push_back(leg);
  }
  return compensated;
}

}  // namespace lathesim::interp
