#pragma once
// How long each move takes on the machine (Move::timeS), from its kind, feed and the spindle
// state stamped on it:
// - rapid: the axes move independently at their own rates, so the slower axis decides:
//   max(|Δr| / rapid X, |ΔZ| / rapid Z);
// - feed (straight or arc) under G98: path length / F;
// - feed under G99 and G97: length / (F · rpm), rpm = min(S, max_rpm);
// - feed under G99 and G96: ∫ ds / (F · rpm(r)), rpm(r) = min(1000·V / (2π·r), G50 S,
//   max_rpm) varying along the move; integrated exactly (piecewise closed form) over lines
//   and arcs alike;
// - thread (G32, G92, G76): one revolution per lead of long-axis travel, at the rpm above
//   (G97: revolutions / rpm; under G96 the same integral as a G99 feed);
// - dwell: its own time.
// A G99 feed with the spindle stopped (M05, no M03, or S0) would wait forever on a machine;
// it is counted as 0 s and reported as a warning.

#include <optional>
#include <vector>

#include "interp/control/machine_limits.hpp"
#include "interp/motion/spindle_angle.hpp"
#include "interp/base/move.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp {

/// The time of one move, in seconds; nullopt for a G99 feed that never moves (spindle stopped).
std::optional<double> moveTimeS(const Move& move, const MachineLimits& machine);

/// Times moves one after another in program order, as they stream from the interpreter:
/// each move's timeS, and then its spindleAngleDeg (spindle_angle.hpp), which follows from
/// the times of the moves before it.
class MoveTimer {
 public:
  explicit MoveTimer(const MachineLimits& machine) : machine_(machine) {}
  void time(Move& move);
  /// A warning per block whose G99 feeds or thread cuts stand still for want of spindle
  /// revolutions (those moves get timeS = 0), in the order met.
  const std::vector<Error>& warnings() const { return warnings_; }

 private:
  MachineLimits machine_;
  SpindleAngleClock spindle_;
  std::vector<Error> warnings_;
  int lastWarnedBlock_ = -1;
};

/// Times every move of `toolpath` (MoveTimer); returns its warnings.
std::vector<Error> assignMoveTimes(Toolpath& toolpath, const MachineLimits& machine);

/// The sum of the moves' times (s).
double cycleTimeS(const Toolpath& toolpath);

}  // namespace lathesim::interp
