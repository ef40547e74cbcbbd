#pragma once
// One spindle-synchronised cut, with its run-out: what G32 makes, and step 2 of G92 and G76.
// See thread_cut.cpp for the moves.

#include <vector>

#include "geometry/rz.hpp"
#include "interp/contour/cycle_leg.hpp"

namespace lathesim::interp {

/// The run-out at the end of a thread cut (GSK J/K, Fanuc's chamfer, HNC R/E): over the last
/// `alongMm` of the long axis the tool also moves `acrossMm` along the short axis (X as a
/// radius), so the groove runs out of the part instead of ending in a wall. Zero `acrossMm`
/// is no run-out.
struct ThreadRunout {
  double alongMm = 0;   // ≥ 0
  double acrossMm = 0;  // signed: + is toward +X (+Z for a face thread's short axis)
};

/// Whether Z is the long axis of a cut from `from` to `to`: it moves at least as far as X
/// (counted as a radius). The lead is measured along the long axis (lathe-cycles.md §2).
bool zIsLongAxis(const RZ& from, const RZ& to);

/// The thread legs (kind Thread, cycle step `step`) from `from` to `to` with `runout`: one
/// leg, or two when the run-out has length. `motion` gives the lead and the spindle angle
/// the cut starts at (its lead axis is set here from the cut's long axis); the second leg
/// starts where the first ended. The legs end at `to` moved across by the run-out.
std::vector<CycleLeg> threadCutLegs(const RZ& from, const RZ& to, const ThreadRunout& runout, ThreadMotion motion,
                                    int step);

/// The angle (degrees in [0, 360)) the spindle reaches after `revolutions` from `startDeg`.
double angleAfter(double startDeg, double revolutions);

}  // namespace lathesim::interp
