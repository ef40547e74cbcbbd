#pragma once
// G76, the multiple threading cycle in its two-block Fanuc/GSK form, expanded into primitive
// moves. See g76_cycle.cpp for the moves.

#include <optional>
#include <vector>

#include "geometry/rz.hpp"
#include "interp/contour/cycle_leg.hpp"

namespace lathesim::interp {

/// What the two G76 blocks give, lengths in mm (X ones as radii).
struct MultipleThreadingParams {
  int finishingPasses = 1;       // m: passes at the full depth k; the first removes d
  double toolAngleDeg = 60;      // a: the included angle; the infeed follows one flank (a/2)
  double minDepthStepMm = 0;     // Δdmin: the smallest depth a rough pass adds
  double finishAllowanceMm = 0;  // d: what the first finishing pass removes
  double taperMm = 0;            // i: the thread's radius at its start minus at its end
  double heightMm = 0;           // k: the thread's height, crest to root (> d)
  double firstDepthMm = 0;       // Δd: the first rough pass's depth (> 0)
  double leadMm = 0;
  double runoutAlongMm = 0;      // the run-out, as in G92 (r·L/10 when J/K are not given)
  double runoutAcrossMm = 0;
  double startAngleDeg = 0;      // the spindle angle every pass starts at (HNC P; Fanuc: 0)
};

/// The cumulative depths of the rough passes (lathe-cycles.md §6, GSK 3.24.12): Δd·√n
/// until a pass would add less than Δdmin, then Δdmin a pass; the last is exactly
/// `finalDepthMm` = k − d. nullopt when that takes more than `maxPasses` passes.
/// `firstDepthMm` must be > 0.
std::optional<std::vector<double>> roughPassDepths(double firstDepthMm, double minDepthStepMm, double finalDepthMm,
                                                   int maxPasses);

/// The legs from A = `start` to the thread's end D = `end` (its root, at the end Z), the
/// rough passes at `roughDepths` (from roughPassDepths), then the finishing passes.
std::vector<CycleLeg> multipleThreadingLegs(const RZ& start, const RZ& end, const MultipleThreadingParams& params,
                                            const std::vector<double>& roughDepths);

}  // namespace lathesim::interp
