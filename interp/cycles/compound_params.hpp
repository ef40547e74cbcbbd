#pragma once
// The first-block values of the compound cycles (G71 U R, G72 W R, G73 U W R, G74/G75 R):
// modal, kept until a first block changes them. Before any is given the control uses its
// parameters (control_parameters.hpp: GSK No.51–56, Fanuc 5132–5139). Lengths in mm.

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

  /// The values the control's parameters give before a program sets them.
  static CompoundCycleParams of(const ControlParameters& control) {
    return {control.roughingDepthMm, control.roughingRetractMm, control.patternReliefXMm,
            control.patternReliefZMm, control.patternPasses,    control.peckRetractMm, false, false};
  }
};

}  // namespace lathesim::interp
