#include "interp/motion/spindle_angle.hpp"

#include <cmath>

#include "geometry/arc.hpp"
#include "interp/motion/spindle_speed.hpp"
#include "interp/motion/toolpath_clock.hpp"

namespace lathesim::interp {
namespace {

constexpr double kSecondsPerMinute = 60.0;

double rpmAt(const Move& move, const RZ& point, const MachineLimits& machine) {
  if (move.spindleMode == SpindleMode::Rpm) return constantRpm(move.spindleS, machine);
  return surfaceSpeedRpm(move.spindleS, point.x(), move.spindleLimitRpm, machine);
}

}  // namespace

double spindleRevolutions(const Move& move, const MachineLimits& machine) {
  if (move.kind == MoveKind::Thread) return move.thread.revolutions(move.from, move.to);
  if (!move.spindleOn || move.spindleS <= 0.0) return 0.0;
  const bool feed = isCutting(move.kind);
  if (feed && move.feedMode == FeedMode::PerRevolution) {
    const double length = isArc(move.kind) ? Arc(move.from, move.to, move.center, move.kind == MoveKind::ArcCW).lengthMm()
                                           : (move.to - move.from).norm();
    return length / move.feed;
  }
  if (move.spindleMode == SpindleMode::Rpm || !feed) {
    // G97, or a rapid or dwell under G96: one speed for the whole move (a rapid's is the
    // end point's).
    return rpmAt(move, move.to, machine) * move.timeS / kSecondsPerMinute;
  }
  // A G98 feed under G96: the rpm follows the radius along the path at the constant speed F,
  // so revolutions = ∫ rpm dt = time × the rpm's mean over the path (Simpson, 64 panels).
  constexpr int kPanels = 64;
  double sum = 0.0;
  for (int i = 0; i <= kPanels; ++i) {
    const double weight = i == 0 || i == kPanels ? 1.0 : i % 2 ? 4.0 : 2.0;
    sum += weight * rpmAt(move, pointAlong(move, static_cast<double>(i) / kPanels), machine);
  }
  const double meanRpm = sum / (3.0 * kPanels);
  return meanRpm * move.timeS / kSecondsPerMinute;
}

void SpindleAngleClock::place(Move& move, const MachineLimits& machine) {
  const double sense = move.spindleDirection == SpindleDirection::Clockwise ? 1.0 : -1.0;
  if (move.kind == MoveKind::Thread) angleDeg_ = sense * move.thread.startAngleDeg;
  angleDeg_ = std::fmod(angleDeg_, 360.0);
  if (angleDeg_ < 0) angleDeg_ += 360.0;
  move.spindleAngleDeg = angleDeg_;
  angleDeg_ += sense * 360.0 * spindleRevolutions(move, machine);
}

}  // namespace lathesim::interp
