#pragma once
// G74 (face peck drilling / face grooving) and G75 (OD/ID grooving): one engine, the axes
// exchanged by a table. See peck_cycle.cpp for the moves.

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "geometry/rz.hpp"
#include "interp/contour/cycle_leg.hpp"

namespace lathesim::interp {

/// What sets G74 and G75 apart.
struct PeckCycle {
  std::string_view code;  // "G74" or "G75"
  bool pecksAlongZ;       // G74: pecks along Z, plunges stepped in X; G75: the other way
};

constexpr PeckCycle kFacePeckCycle{"G74", true};
constexpr PeckCycle kGroovePeckCycle{"G75", false};

/// Lengths in mm, X ones as radii, all ≥ 0.
struct PeckParams {
  double peckMm = 0;     // depth of each peck along the peck axis (G74 Δk, G75 Δi/2)
  double shiftMm = 0;    // between plunges along the other axis (G74 Δi/2, G75 Δk)
  double retractMm = 0;  // e: backing off after each peck
  double reliefMm = 0;   // Δd: at the bottom, away from the end point along the other axis
  double reliefDirectionWithoutShift = 1;  // ±1: Δd's way when A and the end share the other axis
};

/// The legs from the cycle start `start` (A) to the end point `end`; the cycle ends at A.
/// The caller checks that `peckMm` > 0 when A and the end differ along the peck axis and
/// `shiftMm` > 0 when they differ along the other (the plunges would never arrive). Nullopt
/// when it would take more than `maxLegs` steps (the move limit): pecks of microns over
/// metres would fill memory first, and a peck below the precision of a far coordinate never
/// arrives.
std::optional<std::vector<CycleLeg>> peckCycleLegs(const PeckCycle& cycle, const RZ& start, const RZ& end,
                                                   const PeckParams& params, std::size_t maxLegs);

}  // namespace lathesim::interp
