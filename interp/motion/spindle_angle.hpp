#pragma once
// Where the spindle stands when each move starts (Move::spindleAngleDeg), so that a cut made
// with the spindle stopped lands at the angle the spindle stopped at, and every thread pass
// at its own start angle. The angle is measured from the one-revolution signal about +Z:
// M03 turns the spindle toward +θ (with the tool feeding toward the chuck it cuts a
// right-hand thread), M04 toward −θ. The program starts at 0°.
//   - a thread move starts where its ThreadMotion says (the control waits for that angle in
//     the direction it turns), and turns |Δ lead axis| / lead revolutions;
//   - any other move turns the spindle by its revolutions over the move's time: a G99 feed
//     exactly length / F; otherwise rpm × time, under G96 the rpm integrated along the move
//     (held at the end point's value during a rapid, lathe-cycles.md §7); none while stopped.

#include "interp/control/machine_limits.hpp"
#include "interp/base/move.hpp"

namespace lathesim::interp {

/// The spindle's revolutions during `move` (≥ 0; its timeS must be set).
double spindleRevolutions(const Move& move, const MachineLimits& machine);

/// Where the spindle stands, move after move in program order (times must be assigned).
class SpindleAngleClock {
 public:
  /// Sets `move.spindleAngleDeg` and turns the spindle through the move.
  void place(Move& move, const MachineLimits& machine);

 private:
  double angleDeg_ = 0.0;  // about +Z; the program starts at 0°
};

}  // namespace lathesim::interp
