#pragma once
// G71 (turning) and G72 (facing) stock removal against a finishing contour: the parameters
// both share and the two expansions. See g71_cycle.cpp and g72_cycle.cpp for the moves.

#include <cstddef>
#include <limits>
#include <vector>

#include "interp/contour/contour.hpp"
#include "interp/contour/cycle_leg.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp {

/// The most troughs a Haas roughs in one G71/G72 (its operator's manual, "Troughs").
inline constexpr std::size_t kHaasMaxTroughs = 10;

struct RoughingParams {
  double depthMm = 0;         // Δd: cut depth per pass (G71: radius, in X; G72: in Z), > 0
  double retractMm = 0;       // e: retract after each pass, ≥ 0
  double allowanceXMm = 0;    // Δu/2: finishing allowance in X as a RADIUS, signed
  double allowanceZMm = 0;    // Δw: finishing allowance in Z, signed
  double roughAllowanceXMm = 0;  // Haas I: what the roughing levels leave on top of Δu/2 (a
  double roughAllowanceZMm = 0;  // radius), and K on top of Δw; the closing contour pass does not
  bool retractAtFeed = true;  // GSK makes the 45° retract at cutting feed; Fanuc-style: rapid
  bool typeII = false;        // the ns block programs both axes (G71: X(U) and Z(W), W0
                              // included; G72: Z(W) and X(U)): pockets allowed
  bool haasTroughs = false;   // Haas: a contour with troughs (type I or II) is roughed region by
                              // region, the material above the troughs first, then each trough
                              // along Z (stock_removal.cpp); at most kHaasMaxTroughs of them
  std::size_t maxLegs = std::numeric_limits<std::size_t>::max();  // more: refused at the ns
                                                                    // block (the move limit)
};

/// The moves of G71 from the cycle start `start` (A): roughing passes, the semi-finishing pass
/// along the contour shifted by the allowances, and the rapid back to A. The infeed to each
/// level is rapid when the ns block is G00 (contour.front().kind), at feed when G01. A contour that breaks
/// the cycle's rules is an Error located at the offending contour block.
Result<std::vector<CycleLeg>> turningRoughingLegs(const RZ& start, const Contour& contour,
                                                  const RoughingParams& params);

/// G72: the same with the axes exchanged (passes parallel to X, stepping in Z).
Result<std::vector<CycleLeg>> facingRoughingLegs(const RZ& start, const Contour& contour,
                                                 const RoughingParams& params);

}  // namespace lathesim::interp
