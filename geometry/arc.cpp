#include "geometry/arc.hpp"

#include <algorithm>
#include <cmath>

namespace lathesim {
namespace {

}  // namespace

Arc::Arc(const RZ& start, const RZ& end, const RZ& center, bool clockwise)
    : start_(start), end_(end), center_(center), clockwise_(clockwise) {}

double Arc::angleOf(const RZ& p) const {
  // Drawing view: Z is the horizontal axis, the radius the vertical one, so a
  // counter-clockwise turn increases atan2(Δr, Δz).
  return std::atan2(p.x() - center_.x(), p.y() - center_.y());
}

double Arc::sweepRad() const {
  if (start_ == end_) return kTwoPi;
  const double turn = clockwise_ ? angleOf(start_) - angleOf(end_) : angleOf(end_) - angleOf(start_);
  double sweep = std::fmod(turn, kTwoPi);
  if (sweep < 0) sweep += kTwoPi;
  // End on the start's ray but at a slightly different radius: a whole turn.
  return sweep > 0 ? sweep : kTwoPi;
}

double Arc::lengthMm() const { return sweepRad() * 0.5 * (startRadiusMm() + endRadiusMm()); }

RZ Arc::pointAt(double t) const {
  if (t <= 0) return start_;
  if (t >= 1) return end_;
  const double direction = clockwise_ ? -1.0 : 1.0;
  const double angle = angleOf(start_) + direction * t * sweepRad();
  const double radius = startRadiusMm() + t * (endRadiusMm() - startRadiusMm());
  return RZ(center_.x() + radius * std::sin(angle), center_.y() + radius * std::cos(angle));
}

double Arc::sagittaMm() const {
  return std::max(startRadiusMm(), endRadiusMm()) * (1.0 - std::cos(0.5 * sweepRad()));
}

std::vector<Arc> Arc::split(double maxSagittaMm) const {
  // A sub-arc of radius R sweeping φ deviates from its chord by R(1 − cos(φ/2)), so
  // φ ≤ 2·acos(1 − s/R) keeps that within s; never more than half a turn per piece.
  const double radius = std::max(startRadiusMm(), endRadiusMm());
  const double maxStepRad =
      maxSagittaMm >= radius ? M_PI : std::min(M_PI, 2.0 * std::acos(1.0 - maxSagittaMm / radius));
  const int count = std::max(1, static_cast<int>(std::ceil(sweepRad() / maxStepRad)));
  std::vector<Arc> pieces;
  pieces.reserve(count);
  RZ from = start_;
  for (int k = 1; k <= count; ++k) {
    const RZ to = pointAt(static_cast<double>(k) / count);
    pieces.emplace_back(from, to, center_, clockwise_);
    from = to;
  }
  return pieces;
}

}  // namespace lathesim
