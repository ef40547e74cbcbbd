// G92 threading cycle, system A (lathe-cycles.md §1; GSK980TDi 3.24.9, figures 3-88 to
// 3-90). With A the tool position before the block, C = (X or X_A+U, Z or Z_A+W) the cut's
// end and R the taper as a radius difference (as in G90), B = (X_C + 2R, Z_A) the cut's start:
//   step 1  rapid   A → B   along X
//   step 2  thread  B → C   at the lead F per revolution along the long axis, with the
//                           run-out (thread_cut.cpp): its last `runoutAlongMm` of long-axis
//                           travel also pull `runoutAcrossMm` out along the short axis, away
//                           from the cut toward A's side, so the cut ends at C′ = C moved out
//   step 3  rapid   C′ → D  D = (X_A, Z_C): back along X (the short axis) to A's X
//   step 4  rapid   D → A   back along Z; the cycle ends where it began
// A multi-start thread (GSK L, HNC C: n starts) repeats steps 1–4 for each start k = 0…n−1,
// each waiting for the spindle at firstStartDeg + 360k/n, so the grooves lie a turn/n apart;
// firstStartDeg is Fanuc's Q (0.001°, not modal) or HNC's P (°, kept).
// The taper alarm is G90's (R and U of opposite signs with |R| > |U/2|), checked by the caller.

#include "interp/cycles/g92_cycle.hpp"

namespace lathesim::interp {
namespace {

double signTowards(double from, double to) { return to > from ? 1.0 : -1.0; }

}  // namespace

std::vector<CycleLeg> threadCycleLegs(const RZ& start, const RZ& end, double rMm, const ThreadCycleParams& params) {
  const RZ b(end.x() + rMm, start.y());
  // The run-out pulls out along the short axis toward A: in X for the usual cut (Z the long
  // axis), in Z for a steep taper whose long axis is X.
  const bool alongZ = zIsLongAxis(b, end);
  const double outward = alongZ ? signTowards(end.x(), start.x()) : signTowards(end.y(), start.y());
  const ThreadRunout runout{params.runoutAlongMm, outward * params.runoutAcrossMm};
  std::vector<CycleLeg> legs;
  for (int k = 0; k < params.starts; ++k) {
    ThreadMotion motion;
    motion.leadMm = params.leadMm;
    motion.starts = params.starts;
    motion.startAngleDeg = angleAfter(params.firstStartDeg, static_cast<double>(k) / params.starts);
    const std::vector<CycleLeg> cut = threadCutLegs(b, end, runout, motion, 2);
    const RZ out = cut.back().to;
    const RZ d(start.x(), out.y());
    std::vector<CycleLeg> pass{{MoveKind::Rapid, start, b, 1}};
    pass.insert(pass.end(), cut.begin(), cut.end());
    pass.push_back({MoveKind::Rapid, out, d, 3});
    pass.push_back({MoveKind::Rapid, d, start, 4});
    for (const CycleLeg& leg : pass)
      if (leg.from != leg.to) legs.push_back(leg);
  }
  return legs;
}

}  // namespace lathesim::interp
