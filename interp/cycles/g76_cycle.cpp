// G76 multiple threading cycle (lathe-cycles.md §6; GSK980TDi 3.24.12, figures 3-94/3-95):
//   G76 P(m)(r)(a) Q(Δdmin) R(d);  G76 X(U) Z(W) R(i) P(k) Q(Δd) F(L);
// A is the tool position before the second block, D = (X, Z) the thread's root at its end,
// C = (X_D + 2i, Z_A) its root at its start, E = (X_A, Z_D). σ is the direction from D
// toward A in X (+1 for an OD thread), ζ the direction of cutting in Z (from A toward D).
// Each pass at cumulative depth D_n below the crest cuts along the root line C→D moved
// σ·(k − D_n) out; with a ≠ 0 its start moves ζ·D_n·tan(a/2) along Z, so the tool goes in
// along one flank and only its leading flank cuts. Depths: D_n = Δd·√n for the rough passes
// until a pass would add less than Δdmin, Δdmin a pass after that, the last rough pass at
// exactly k − d; then m finishing passes at k (the first removes d, the others are spring
// passes). For each pass:
//   step 1  rapid   A → B_n   B_n on the pass's line at Z_A + ζ·D_n·tan(a/2), both axes at once
//   step 2  thread  B_n → the pass's end at Z_D, with the run-out as in G92 (thread_cut.cpp)
//   step 3  rapid   → E′ = (X_A, Z of the run-out's end): X back to A's X
//   step 4  rapid   E′ → A   Z back to A
// Every pass starts at the same spindle angle (0 on Fanuc/GSK, HNC's P); the cycle ends at A.

#include "interp/cycles/g76_cycle.hpp"

#include <cmath>
#include <numbers>

#include "interp/cycles/thread_cut.hpp"

namespace lathesim::interp {

std::optional<std::vector<double>> roughPassDepths(double firstDepthMm, double minDepthStepMm, double finalDepthMm,
                                                   int maxPasses) {
  std::vector<double> depths;
  bool clamped = false;  // once Δdmin has decided a pass, it decides every later one (GSK)
  for (int n = 1; n <= maxPasses; ++n) {
    double depth = firstDepthMm * std::sqrt(static_cast<double>(n));
    if (n > 1) {
      const double previous = depths.back();
      if (clamped || depth - previous < minDepthStepMm) {
        clamped = true;
        depth = previous + minDepthStepMm;
      }
    }
    if (depth >= finalDepthMm) {  // the last rough pass: exactly k − d
      depths.push_back(finalDepthMm);
      return depths;
    }
    depths.push_back(depth);
  }
  return std::nullopt;
}

std::vector<CycleLeg> multipleThreadingLegs(const RZ& start, const RZ& end, const MultipleThreadingParams& params,
                                            const std::vector<double>& roughDepths) {
  const double sigma = start.x() >= end.x() ? 1.0 : -1.0;
  const double zeta = end.y() >= start.y() ? 1.0 : -1.0;
  const double k = params.heightMm;
  const double flank = std::tan(params.toolAngleDeg / 2.0 * std::numbers::pi / 180.0);
  const RZ rootStart(end.x() + params.taperMm, start.y());  // C
  // The root line's radius at Z = z (C→D extended).
  const auto rootRadiusAt = [&](double z) {
    if (end.y() == start.y()) return end.x();
    return end.x() + (rootStart.x() - end.x()) * (z - end.y()) / (start.y() - end.y());
  };

  std::vector<double> depths = roughDepths;
  for (int m = 0; m < params.finishingPasses; ++m) depths.push_back(k);

  std::vector<CycleLeg> legs;
  const auto add = [&legs](const CycleLeg& leg) {
    if (leg.from != leg.to) legs.push_back(leg);
  };
  for (const double depth : depths) {
    const double out = sigma * (k - depth);
    const double zStart = start.y() + zeta * depth * flank;
    const RZ b(rootRadiusAt(zStart) + out, zStart);
    const RZ passEnd(end.x() + out, end.y());
    // The run-out pulls out toward A along the short axis (as in G92).
    const bool alongZ = zIsLongAxis(b, passEnd);
    const double across = (alongZ ? sigma : -zeta) * params.runoutAcrossMm;
    ThreadMotion motion;
    motion.leadMm = params.leadMm;
    motion.startAngleDeg = params.startAngleDeg;
    add({MoveKind::Rapid, start, b, 1});
    const std::vector<CycleLeg> cut = threadCutLegs(b, passEnd, {params.runoutAlongMm, across}, motion, 2);
    for (const CycleLeg& leg : cut) add(leg);
    const RZ finish = cut.back().to;
    const RZ e(start.x(), finish.y());
    add({MoveKind::Rapid, finish, e, 3});
    add({MoveKind::Rapid, e, start, 4});
  }
  return legs;
}

}  // namespace lathesim::interp
