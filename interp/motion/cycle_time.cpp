#include "interp/motion/cycle_time.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "interp/motion/spindle_angle.hpp"
#include "interp/motion/spindle_speed.hpp"

namespace lathesim::interp {
namespace {

constexpr double kSecondsPerMinute = 60.0;

// Arcs are parametrised in the drawing view (Z to the right, radius up), where CCW is
// positive: (r, z) = centre + R·(sin ψ, cos ψ).
double angleOf(const RZ& point, const RZ& center) {
  return std::atan2(point.x() - center.x(), point.y() - center.y());
}

struct ArcSpan {
  double radiusMm;
  double psiBegin;  // ψ at the lower end of the span (not necessarily the move's start)
  double psiEnd;    // ψBegin + the swept angle, > ψBegin
};

ArcSpan arcSpan(const Move& move) {
  const double radius = (move.from - move.center).norm();
  const double psiFrom = angleOf(move.from, move.center);
  const double psiTo = angleOf(move.to, move.center);
  // The swept angle in (0, 2π]: start == end is a full circle.
  double sweep = move.kind == MoveKind::ArcCCW ? psiTo - psiFrom : psiFrom - psiTo;
  sweep = std::fmod(sweep, kTwoPi);
  if (sweep <= 0.0) sweep += kTwoPi;
  const double begin = move.kind == MoveKind::ArcCCW ? psiFrom : psiTo;
  return {radius, begin, begin + sweep};
}

double pathLengthMm(const Move& move) {
  if (!isArc(move.kind)) return (move.to - move.from).norm();
  const ArcSpan arc = arcSpan(move);
  return arc.radiusMm * (arc.psiEnd - arc.psiBegin);
}

// Under G96 the minutes per revolution are 1/rpm(r) = max(k·|r|, c): k = 2π / (1000·V)
// while the speed follows the radius, c = 1 / clamp once the clamp holds it.
struct InverseRpm {
  double k;  // min per (rev · mm of radius)
  double c;  // min per rev
  double at(double radiusMm) const { return std::max(k * std::abs(radiusMm), c); }
};

// An antiderivative of max(k·|r|, c) in r: odd, and c·r up to the radius rc = c/k where
// the clamp lets go, then c·rc + k·(r² − rc²)/2.
double antiderivative(const InverseRpm& f, double r) {
  const double a = std::abs(r);
  const double rc = f.c / f.k;
  const double g = a <= rc ? f.c * a : f.c * rc + f.k * (a * a - rc * rc) / 2.0;
  return r < 0.0 ? -g : g;
}

// ∫ max(k·|r|, c) ds along a straight move: r is linear in s.
double lineIntegral(const InverseRpm& f, const Move& move) {
  const double length = (move.to - move.from).norm();
  const double dr = move.to.x() - move.from.x();
  if (std::abs(dr) <= 1e-12 * std::max(1.0, length)) return length * f.at(move.from.x());
  return length / dr * (antiderivative(f, move.to.x()) - antiderivative(f, move.from.x()));
}

// ∫ max(k·|r|, c) ds along an arc, r(ψ) = rC + R·sin ψ, ds = R dψ. The integrand is c, k·r
// or −k·r between the angles where r crosses rc, 0 or −rc; each piece has a closed form
// (∫ r dψ = rC·ψ − R·cos ψ).
double arcIntegral(const InverseRpm& f, const Move& move) {
  const ArcSpan arc = arcSpan(move);
  const double rC = move.center.x();
  const double R = arc.radiusMm;
  const double rc = f.c / f.k;
  std::vector<double> cuts{arc.psiBegin, arc.psiEnd};
  for (const double level : {rc, 0.0, -rc}) {
    const double s = (level - rC) / R;
    if (std::abs(s) > 1.0) continue;
    for (const double root : {std::asin(s), M_PI - std::asin(s)}) {
      double psi = root + kTwoPi * std::ceil((arc.psiBegin - root) / kTwoPi);
      for (; psi < arc.psiEnd; psi += kTwoPi)
        if (psi > arc.psiBegin) cuts.push_back(psi);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double a = cuts[i], b = cuts[i + 1];
    const double rMid = rC + R * std::sin((a + b) / 2.0);
    if (f.k * std::abs(rMid) <= f.c) {
      sum += f.c * (b - a);
    } else {
      const double integralOfR = rC * (b - a) - R * (std::cos(b) - std::cos(a));
      sum += (rMid < 0.0 ? -f.k : f.k) * integralOfR;
    }
  }
  return R * sum;
}

std::optional<double> perRevolutionTimeS(const Move& move, const MachineLimits& machine) {
  if (!move.spindleOn || move.spindleS <= 0.0) return std::nullopt;
  if (move.spindleMode == SpindleMode::Rpm) {
    const double rpm = constantRpm(move.spindleS, machine);
    return pathLengthMm(move) / (move.feed * rpm) * kSecondsPerMinute;
  }
  constexpr double kMmPerM = 1000.0;
  const double clampRpm = surfaceSpeedClampRpm(move.spindleLimitRpm, machine);
  const InverseRpm f{kTwoPi / (kMmPerM * move.spindleS), 1.0 / clampRpm};
  // The control turns the spindle for the X of its own coordinates, which G50 may have moved
  // away from the setup's.
  Move programmed = move;
  programmed.from -= move.workShift;
  programmed.to -= move.workShift;
  programmed.center -= move.workShift;
  const double minutesTimesFeed = isArc(move.kind) ? arcIntegral(f, programmed) : lineIntegral(f, programmed);
  return minutesTimesFeed / move.feed * kSecondsPerMinute;
}

}  // namespace

std::optional<double> moveTimeS(const Move& move, const MachineLimits& machine) {
  switch (move.kind) {
    case MoveKind::Dwell: return move.dwellS;
    case MoveKind::Rapid: {
      const RZ d = (move.to - move.from).cwiseAbs();
      return std::max(d.x() / machine.rapidXMmPerMin, d.y() / machine.rapidZMmPerMin) * kSecondsPerMinute;
    }
    case MoveKind::Thread: {
      // One revolution per lead of long-axis travel: the per-revolution time of a feed
      // whose feed along the path is the lead scaled by path length / long-axis travel.
      const double revolutions = move.thread.revolutions(move.from, move.to);
      if (revolutions == 0.0) return 0.0;
      Move alongPath = move;
      alongPath.feed = pathLengthMm(move) / revolutions;
      return perRevolutionTimeS(alongPath, machine);
    }
    case MoveKind::Feed:
    case MoveKind::ArcCW:
    case MoveKind::ArcCCW: break;
  }
  if (move.feedMode == FeedMode::PerMinute) return pathLengthMm(move) / move.feed * kSecondsPerMinute;
  return perRevolutionTimeS(move, machine);
}

void MoveTimer::time(Move& move) {
  const std::optional<double> time = moveTimeS(move, machine_);
  move.timeS = time.value_or(0.0);
  spindle_.place(move, machine_);
  if (time || move.block == lastWarnedBlock_) return;
  lastWarnedBlock_ = move.block;
  const char* why = move.spindleOn ? (move.spindleMode == SpindleMode::Rpm ? "at S0" : "at G96 S0")
                                   : "with the spindle stopped (M05, or no M03/M04 yet)";
  const char* what = move.kind == MoveKind::Thread ? "a thread cut (one lead per revolution) "
                                                   : "a feed in mm per revolution (G99) ";
  warnings_.push_back({move.line, move.column,
                       std::string(what) + why + " never moves on a machine; its time is counted as 0 s"});
}

std::vector<Error> assignMoveTimes(Toolpath& toolpath, const MachineLimits& machine) {
  MoveTimer timer(machine);
  for (Move& move : toolpath.moves) timer.time(move);
  return timer.warnings();
}

double cycleTimeS(const Toolpath& toolpath) {
  double sum = 0.0;
  for (const Move& move : toolpath.moves) sum += move.timeS;
  return sum;
}

}  // namespace lathesim::interp
