// G90 axial (OD/ID) cutting cycle, system A (spec lathe-gcode.md, lathe-cycles.md §1).
// With A the tool position before the block, C = (X or X_A+U, Z or Z_A+W) the cut's end,
// and R the taper as a radius difference (R = 0 for a straight cylinder):
//   B = (X_C + 2R, Z_A)  the cut's start (diameters),  D = (X_A, Z_C)
//   step 1  rapid  A → B   along X
//   step 2  feed   B → C   the cut (a cone when R ≠ 0)
//   step 3  feed   C → D   back along X to X_A
//   step 4  rapid  D → A   back along Z; the cycle ends where it began
// Alarm: R and U = X_C − X_A of opposite signs with |R| > |U/2| [GSK][FC HUST]: then B
// lies beyond X_A and the cut B→C crosses the retract D→A.

#include "interp/cycles/g90_cycle.hpp"

#include <cmath>

#include <fmt/format.h>

namespace lathesim::interp {

std::vector<CycleLeg> axialCycleLegs(const RZ& start, const RZ& end, double rMm) {
  const RZ b(end.x() + rMm, start.y());
  const RZ d(start.x(), end.y());
  return keptLegs({
      {MoveKind::Rapid, start, b, 1},
      {MoveKind::Feed, b, end, 2},
      {MoveKind::Feed, end, d, 3},
      {MoveKind::Rapid, d, start, 4},
  });
}

std::optional<std::string> axialCycleTaperProblem(double uDiameterMm, double rMm, std::string_view name) {
  const bool opposite = (rMm > 0 && uDiameterMm < 0) || (rMm < 0 && uDiameterMm > 0);
  if (!opposite || std::abs(rMm) <= std::abs(uDiameterMm) / 2.0) return std::nullopt;
  return fmt::format(
      "R{} and U{} have opposite signs and |R| > |U/2|; {} needs |R| ≤ |U/2| (U is the end X "
      "minus the start X, a diameter; R is a radius)",
      rMm, uDiameterMm, name);
}

}  // namespace lathesim::interp
