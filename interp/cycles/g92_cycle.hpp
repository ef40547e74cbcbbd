#pragma once
// G92, the single threading cycle of system A (fanuc-b writes it G78, hnc G82), expanded
// into primitive moves. See g92_cycle.cpp for the moves.

#include <vector>

#include "geometry/rz.hpp"
#include "interp/contour/cycle_leg.hpp"
#include "interp/cycles/thread_cut.hpp"

namespace lathesim::interp {

/// How one G92 block threads: the lead, the run-out, and its starts.
struct ThreadCycleParams {
  double leadMm = 0;
  double runoutAlongMm = 0;   // the run-out's length along the long axis (≥ 0)
  double runoutAcrossMm = 0;  // how far it pulls out along the short axis, toward A (≥ 0)
  int starts = 1;             // G92 L / HNC C: one pass per start, each a turn/starts later
  double firstStartDeg = 0;   // the first start's spindle angle (HNC P)
};

/// The legs of one G92 block from A = `start` to the cut's end C = `end` with `rMm` the taper
/// (a radius: the cut's start minus its end, as in G90), zero-length legs left out.
std::vector<CycleLeg> threadCycleLegs(const RZ& start, const RZ& end, double rMm, const ThreadCycleParams& params);

}  // namespace lathesim::interp
