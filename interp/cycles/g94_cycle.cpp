// G94 face cutting cycle, system A (GSK980TDi manual 3.21.2; spec lathe-gcode.md).
// With A the tool position before the block, C = (X or X_A+U, Z or Z_A+W) the cut's end,
// and R the taper (R = 0 for a straight face):
//   B = (X_A, Z_C + R)  the cut's start,  D = (X_C, Z_A)
//   step 1  rapid  A → B   along Z
//   step 2  feed   B → C   the face (a cone when R ≠ 0)
//   step 3  feed   C → D   back along Z to Z_A
//   step 4  rapid  D → A   back along X; the cycle ends where it began
// Alarm: R and W = Z_C − Z_A of opposite signs with |R| > |W|. Seed 003 (the GSK980TDi
// English page) words the sign test against U, but its own figure cases and seed 000's
// (U>0/U<0 with R>0, W<0, each marked |R| ≤ |W|) test R against W, and so does the
// geometry: with opposite signs and |R| > |W| the cut B→C crosses the retract D→A.
// We follow W; parts/seed004-o0006 is a textbook program that alarms under this rule.

#include "interp/cycles/g94_cycle.hpp"

#include <cmath>

#include <fmt/format.h>

namespace lathesim::interp {

std::vector<CycleLeg> faceCycleLegs(const RZ& start, const RZ& end, double rMm) {
  const RZ b(start.x(), end.y() + rMm);
  const RZ d(end.x(), start.y());
  return keptLegs({
      {MoveKind::Rapid, start, b, 1},
      {MoveKind::Feed, b, end, 2},
      {MoveKind::Feed, end, d, 3},
      {MoveKind::Rapid, d, start, 4},
  });
}

std::optional<std::string> faceCycleTaperProblem(double wMm, double rMm) {
  const bool opposite = (rMm > 0 && wMm < 0) || (rMm < 0 && wMm > 0);
  if (!opposite || std::abs(rMm) <= std::abs(wMm)) return std::nullopt;
  return fmt::format(
      "R{} and W{} have opposite signs and |R| > |W|; G94 needs |R| ≤ |W| (W is the end Z "
      "minus the start Z)",
      rMm, wMm);
}

}  // namespace lathesim::interp
