#pragma once
// The first-block values of the compound cycles (G71 U R, G72 W R, G73 U W R, G74/G75 R,
// G76 P Q R):
// modal, kept until a first block changes them. Before any is given the control uses its
// parameters (control_parameters.hpp: GSK No.51–56, Fanuc 5132–5139). Lengths in mm.

#include <optional>

#include "interp/control/control_parameters.hpp"

namespace lathesim::interp {

// G76's first-block values before a program gives them (GSK No.57–60; Fanuc No.5142, 5143,
// 5140, 5141 ⚠): not yet among the control's parameters; the values are assumed.
constexpr int kDefaultThreadFinishingPasses = 1;     // GSK No.57: m
constexpr double kDefaultThreadToolAngleDeg = 60.0;  // GSK No.58: a
constexpr double kDefaultThreadMinDepthMm = 0.0;     // GSK No.59: Δdmin
constexpr double kDefaultThreadAllowanceMm = 0.0;    // GSK No.60: d

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
  int threadFinishingPasses = kDefaultThreadFinishingPasses;
  std::optional<double> threadRunoutLeads;  // r/10: the run-out in leads; unset: the machine's
  double threadToolAngleDeg = kDefaultThreadToolAngleDeg;
  double threadMinDepthMm = kDefaultThreadMinDepthMm;
  double threadAllowanceMm = kDefaultThreadAllowanceMm;
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
    return params;
  }
};

}  // namespace lathesim::interp
