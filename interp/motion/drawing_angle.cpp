#include "interp/motion/drawing_angle.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace lathesim::interp {
namespace {

constexpr double kAlarmWithinDeg = 1.0;  // GSK §3.13 notes 3–4

// How far `angleDeg` lies from the nearest of `axisDeg` and `axisDeg` + 180°, in degrees.
double offAxisDeg(double angleDeg, double axisDeg) {
  const double folded = std::fmod(std::abs(angleDeg - axisDeg), 180.0);
  return std::min(folded, 180.0 - folded);
}

}  // namespace

Result<RZ> lineEndByAngle(const RZ& start, std::optional<double> endRadiusMm, std::optional<double> endZMm,
                          double angleDeg, const Word& angle, int line) {
  const double radians = angleDeg * std::numbers::pi / 180.0;
  if (endRadiusMm) {
    if (offAxisDeg(angleDeg, 0.0) < kAlarmWithinDeg) {
      return Error{line, angle.column,
                   fmt::format("{} is a line along Z: it never reaches another X; give Z instead, or an angle "
                               "at least {}° off the Z axis",
                               angle.text(), kAlarmWithinDeg)};
    }
    return RZ(*endRadiusMm, start.y() + (*endRadiusMm - start.x()) / std::tan(radians));
  }
  if (offAxisDeg(angleDeg, 90.0) < kAlarmWithinDeg) {
    return Error{line, angle.column,
                 fmt::format("{} is a line along X: it never reaches another Z; give X instead, or an angle at "
                             "least {}° off the X axis",
                             angle.text(), kAlarmWithinDeg)};
  }
  return RZ(start.x() + (*endZMm - start.y()) * std::tan(radians), *endZMm);
}

}  // namespace lathesim::interp
