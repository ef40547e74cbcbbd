// G74 and G75 (lathe-cycles.md §5, GSK980TDi 3.23.5–3.23.6), written in "peck axis" p (Z for
// G74, X for G75) and "step axis" s (the other). From A = (p_A, s_A) to E = (p_E, s_E), the
// plunges stand at s_1 = s_A, s_(j+1) = s_j + shift toward s_E, the last clamped onto s_E.
// For each plunge j:
//   step 1  feed   one peck toward p_E (the first from p_A, each later one peck + e from
//                  where the tool backed off), the last clamped onto p_E
//   step 2  rapid  back e along p after every peck but the last
//   step 3  rapid  relief Δd along s, away from s_E; when A and E share s, toward + (GSK §3.23.5:
//                  X(U) and P omitted) or the way Δd's sign says (Fanuc ⚠), as the control reads it
//   step 4  rapid  back along p to p_A
//   step 5  rapid  along s to the next plunge s_(j+1)
//   step 6  rapid  to A after the last plunge
// Zero-length legs are left out.

#include "interp/cycles/peck_cycle.hpp"

#include <algorithm>
#include <cmath>

#include "interp/base/tolerance.hpp"

namespace lathesim::interp {
namespace {

double signOf(double value) { return value > kTolMm ? 1.0 : value < -kTolMm ? -1.0 : 0.0; }

}  // namespace

std::optional<std::vector<CycleLeg>> peckCycleLegs(const PeckCycle& cycle, const RZ& start, const RZ& end,
                                                   const PeckParams& params, std::size_t maxLegs) {
  // (p, s) → (radius, Z)
  const auto at = [&cycle](double p, double s) {
    return cycle.pecksAlongZ ? RZ(s, p) : RZ(p, s);
  };
  const double pA = cycle.pecksAlongZ ? start.y() : start.x();
  const double sA = cycle.pecksAlongZ ? start.x() : start.y();
  const double pE = cycle.pecksAlongZ ? end.y() : end.x();
  const double sE = cycle.pecksAlongZ ? end.x() : end.y();
  const double pDir = signOf(pE - pA);
  const double sDir = signOf(sE - sA);

  std::vector<CycleLeg> legs;
  const auto add = [&legs](MoveKind kind, const RZ& from, const RZ& to, int step) {
    if (from != to) legs.push_back({kind, from, to, step, RZ(0, 0)});
  };
  double s = sA;
  RZ here = start;
  std::size_t steps = 0;  // pecks and plunges, each one leg at least unless it does not move
  for (;;) {
    // Pecks down to p_E.
    double p = pA;
    for (;;) {
      if (++steps > maxLegs) return std::nullopt;
      const bool last = std::abs(pE - p) <= params.peckMm + kTolMm;
      const double bottom = last ? pE : p + pDir * params.peckMm;
      add(MoveKind::Feed, here, at(bottom, s), 1);
      here = at(bottom, s);
      if (last) break;
      p = bottom;
      add(MoveKind::Rapid, here, at(p - pDir * params.retractMm, s), 2);
      here = at(p - pDir * params.retractMm, s);
    }
    const double reliefDir = sDir != 0 ? -sDir : params.reliefDirectionWithoutShift;
    const double relieved = s + reliefDir * params.reliefMm;
    add(MoveKind::Rapid, here, at(pE, relieved), 3);
    add(MoveKind::Rapid, at(pE, relieved), at(pA, relieved), 4);
    here = at(pA, relieved);
    if (std::abs(sE - s) <= kTolMm) break;
    if (++steps > maxLegs) return std::nullopt;
    s = std::abs(sE - s) <= params.shiftMm + kTolMm ? sE : s + sDir * params.shiftMm;
    add(MoveKind::Rapid, here, at(pA, s), 5);
    here = at(pA, s);
  }
  add(MoveKind::Rapid, here, start, 6);
  return legs;
}

}  // namespace lathesim::interp
