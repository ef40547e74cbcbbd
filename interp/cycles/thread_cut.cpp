// A thread cut from S to E (lathe-cycles.md §2; GSK980TDi 3.24.1, figure 3-82), the lead L
// along the long axis (the one that moves more, X counted as a radius):
//   without a run-out   thread  S → E
//   with a run-out      thread  S → P   P on S→E, `alongMm` short of E along the long axis
//                       thread  P → E'  E' = E moved `acrossMm` along the short axis
// Both legs keep the lead along the long axis of S→E, so the spindle keeps turning one
// revolution per L of long-axis travel through the run-out; the second leg starts at the
// angle where the first ended. A run-out longer than the cut starts at S.

#include "interp/cycles/thread_cut.hpp"

#include <algorithm>
#include <cmath>

namespace lathesim::interp {

bool zIsLongAxis(const RZ& from, const RZ& to) {
  return std::abs(to.y() - from.y()) >= std::abs(to.x() - from.x());
}

double angleAfter(double startDeg, double revolutions) {
  const double angle = std::fmod(startDeg + 360.0 * revolutions, 360.0);
  return angle < 0 ? angle + 360.0 : angle;
}

std::vector<CycleLeg> threadCutLegs(const RZ& from, const RZ& to, const ThreadRunout& runout, ThreadMotion motion,
                                    int step) {
  motion.leadAlongZ = zIsLongAxis(from, to);
  const int longAxis = motion.leadAlongZ ? 1 : 0;  // RZ index: x() radius, y() Z
  const double travel = to[longAxis] - from[longAxis];
  std::vector<CycleLeg> legs;
  if (runout.acrossMm == 0.0 || runout.alongMm <= 0.0 || travel == 0.0) {
    RZ end = to;
    end[1 - longAxis] += runout.acrossMm;
    legs.push_back({MoveKind::Thread, from, end, step, RZ(0, 0), motion});
    return legs;
  }
  const double share = std::clamp(1.0 - runout.alongMm / std::abs(travel), 0.0, 1.0);
  const RZ turnOut = from + share * (to - from);
  RZ end = to;
  end[1 - longAxis] += runout.acrossMm;
  if (turnOut != from) legs.push_back({MoveKind::Thread, from, turnOut, step, RZ(0, 0), motion});
  ThreadMotion out = motion;
  out.startAngleDeg = angleAfter(motion.startAngleDeg, motion.revolutions(from, turnOut));
  legs.push_back({MoveKind::Thread, turnOut, end, step, RZ(0, 0), out});
  return legs;
}

}  // namespace lathesim::interp
