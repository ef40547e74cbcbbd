#pragma once
// The first-block values of the compound cycles (G71 U R, G72 W R, G73 U W R, G74/G75 R,
// G76 P Q R):
// modal, kept until a first block changes them. Before any is given the control uses its
// parameters (control_parameters.hpp: GSK No.19, No.51–60, Fanuc 5130, 5132–5143). Lengths in mm.

#include <optional>

#include "interp/control/control_parameters.hpp"

namespace lathesim::interp {

struct CompoundCycleParams {
  double roughingDepthMm = 0;    // G71 U / G72 W, first block
  double roughingRetractMm = 0;  // G71/G72 R, first block
  double patternReliefXMm = 0;   // G73 U (Δi), radius, signed
  double patternReliefZMm = 0;   // G73 W (Δk), signed
  int patternPasses = 1;         // G73 R (d)
  double peckRetractMm = 0;      // G74/G75 R (e)
  bool roughingGiven = false;    // a G71/G72 first block was read (or its absence warned)
  bool patternGiven = false;     // a G73 first block was read (or its absence warned)
  // G76 P(m)(r)(a) Q(Δdmin) R(d) [J K] (first block)
  int threadFinishingPasses = 1;
  std::optional<double> threadRunoutLeads;  // r/10: the run-out in leads; unset: the control's
  double threadToolAngleDeg = 60;
  double threadMinDepthMm = 0;
  double threadAllowanceMm = 0;
  std::optional<double> threadRunoutAcrossMm;  // GSK J, K: for the next second block only
  std::optional<double> threadRunoutAlongMm;

  /// The values the control's parameters give before a program sets them.
  static CompoundCycleParams of(const ControlParameters& control) {
    CompoundCycleParams params;
    params.roughingDepthMm = control.roughingDepthMm;
    params.roughingRetractMm = control.roughingRetractMm;
    params.patternReliefXMm = control.patternReliefXMm;
    params.patternReliefZMm = control.patternReliefZMm;
    params.patternPasses = control.patternPasses;
    params.peckRetractMm = control.peckRetractMm;
    params.threadFinishingPasses = control.threadFinishingPasses;
    params.threadToolAngleDeg = control.threadToolAngleDeg;
    params.threadMinDepthMm = control.threadMinDepthMm;
    params.threadAllowanceMm = control.threadAllowanceMm;
    return params;
  }
};

}  // namespace lathesim::interp
