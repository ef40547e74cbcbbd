#pragma once
// Helpers for the G71/G72 tests: contours written segment by segment, and leg lists compared
// with hand-worked ones to 1e-9 mm (the expansions compute positions, so exact equality of
// doubles is not expected).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string_view>
#include <vector>

#include "interp/contour/contour.hpp"
#include "interp/contour/cycle_leg.hpp"
#include "interp/cycles/roughing_cycle.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp::test {

/// Δd, e and the finishing allowance (X a radius, Z) of a G71/G72, the rest as defaulted.
inline RoughingParams params(double depthMm, double retractMm, double allowanceXMm, double allowanceZMm) {
  RoughingParams p;
  p.depthMm = depthMm;
  p.retractMm = retractMm;
  p.allowanceXMm = allowanceXMm;
  p.allowanceZMm = allowanceZMm;
  return p;
}

/// A straight contour segment (r, z in mm, radius) made by the block on `line`, column 1.
inline ContourSegment segment(MoveKind kind, double r0, double z0, double r1, double z1,
                              int line) {
  return {kind, RZ(r0, z0), RZ(r1, z1), RZ(0, 0), line, 1};
}

/// An arc contour segment about (rc, zc).
inline ContourSegment arcSegment(MoveKind kind, double r0, double z0, double r1, double z1,
                                 double rc, double zc, int line) {
  return {kind, RZ(r0, z0), RZ(r1, z1), RZ(rc, zc), line, 1};
}

/// A leg as worked out by hand: positions are (radius, Z) in mm; the centre only for arcs.
struct HandLeg {
  MoveKind kind;
  double r0, z0, r1, z1;
  int step;
  double rc = 0, zc = 0;
};

inline void expectLegsNear(const std::vector<CycleLeg>& legs,
                           const std::vector<HandLeg>& expected) {
  ASSERT_EQ(legs.size(), expected.size());
  for (std::size_t i = 0; i < legs.size(); ++i) {
    SCOPED_TRACE(testing::Message() << "leg " << i);
    const HandLeg& e = expected[i];
    EXPECT_EQ(legs[i].kind, e.kind);
    EXPECT_NEAR(legs[i].from.x(), e.r0, 1e-9);
    EXPECT_NEAR(legs[i].from.y(), e.z0, 1e-9);
    EXPECT_NEAR(legs[i].to.x(), e.r1, 1e-9);
    EXPECT_NEAR(legs[i].to.y(), e.z1, 1e-9);
    EXPECT_EQ(legs[i].step, e.step);
    if (isArc(e.kind)) {
      EXPECT_NEAR(legs[i].center.x(), e.rc, 1e-9);
      EXPECT_NEAR(legs[i].center.y(), e.zc, 1e-9);
    }
  }
}

/// The expansion failed at line:column with a message containing `part`.
inline void expectRoughingError(const Result<std::vector<CycleLeg>>& result, int line,
                                int column, std::string_view part) {
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().line, line) << result.error().message;
  EXPECT_EQ(result.error().column, column) << result.error().message;
  EXPECT_NE(result.error().message.find(part), std::string::npos)
      << "message: " << result.error().message;
}

/// How far an arc turns from its start to direction `angle` (atan2(ΔX, ΔZ), counter-clockwise
/// in the drawing view), in [0, 2π).
inline double turnFromStart(MoveKind kind, const RZ& center, const RZ& start, double angle) {
  const double a0 = std::atan2(start.x() - center.x(), start.y() - center.y());
  const double turn = kind == MoveKind::ArcCCW ? angle - a0 : a0 - angle;
  const double twoPi = 2 * std::numbers::pi;
  return std::fmod(std::fmod(turn, twoPi) + twoPi, twoPi);
}

/// Where the rough contour (the blocks after ns) crosses Z = z: every candidate X (both ends
/// of a face lying at that Z).
inline std::vector<double> contourXsAt(const Contour& contour, double z) {
  std::vector<double> xs;
  for (std::size_t i = 1; i < contour.size(); ++i) {
    const ContourSegment& s = contour[i];
    if (!isArc(s.kind)) {
      const double zLo = std::min(s.from.y(), s.to.y());
      const double zHi = std::max(s.from.y(), s.to.y());
      if (z < zLo - 1e-9 || z > zHi + 1e-9) continue;
      if (std::abs(s.to.y() - s.from.y()) < 1e-12) {
        xs.push_back(s.from.x());
        xs.push_back(s.to.x());
      } else {
        const double t = (z - s.from.y()) / (s.to.y() - s.from.y());
        xs.push_back(s.from.x() + t * (s.to.x() - s.from.x()));
      }
      continue;
    }
    // Of the circle's two X at this Z, those whose direction lies within the arc's turn.
    const double r = (s.from - s.center).norm();
    const double dz = z - s.center.y();
    if (std::abs(dz) > r + 1e-9) continue;
    const double h = std::sqrt(std::max(0.0, r * r - dz * dz));
    const double endAngle = std::atan2(s.to.x() - s.center.x(), s.to.y() - s.center.y());
    const double sweep = turnFromStart(s.kind, s.center, s.from, endAngle);
    for (const double x : {s.center.x() + h, s.center.x() - h}) {
      const double turn = turnFromStart(s.kind, s.center, s.from, std::atan2(x - s.center.x(), dz));
      if (turn <= sweep + 1e-9 || turn >= 2 * std::numbers::pi - 1e-9) xs.push_back(x);
    }
  }
  return xs;
}

/// The point a leg passes at fraction t of its way (arcs by angle).
inline RZ legPoint(const CycleLeg& leg, double t) {
  if (!isArc(leg.kind)) return leg.from + (leg.to - leg.from) * t;
  const double r = (leg.from - leg.center).norm();
  const double a0 = std::atan2(leg.from.x() - leg.center.x(), leg.from.y() - leg.center.y());
  const double a1 = std::atan2(leg.to.x() - leg.center.x(), leg.to.y() - leg.center.y());
  const double sweep = turnFromStart(leg.kind, leg.center, leg.from, a1);
  const double a = a0 + (leg.kind == MoveKind::ArcCCW ? 1 : -1) * sweep * t;
  return leg.center + RZ(r * std::sin(a), r * std::cos(a));
}

/// In G71's axes: every point of every roughing cut (steps 3, 4, 6 at feed or along arcs)
/// lies on A's side of the rough contour, (X − X_contour(Z))·stepDir ≤ 0 where the contour
/// has that Z, taking on a face the most lenient of its X. One failure per offending leg. The semi-finishing pass (step 7)
/// runs on the contour and is not checked.
inline void expectNoGouge(const std::vector<CycleLeg>& legs, const Contour& rough,
                          double stepDir) {
  for (const CycleLeg& leg : legs) {
    if (leg.kind == MoveKind::Rapid || (leg.step != 3 && leg.step != 4 && leg.step != 6)) {
      continue;
    }
    for (int i = 0; i <= 50; ++i) {
      const RZ p = legPoint(leg, i / 50.0);
      const std::vector<double> xs = contourXsAt(rough, p.y());
      if (xs.empty()) continue;
      double lenient = -std::numeric_limits<double>::infinity();
      for (const double x : xs) lenient = std::max(lenient, stepDir * x);
      if (stepDir * p.x() - lenient > 1e-9) {
        ADD_FAILURE() << "leg step " << leg.step << " from (" << leg.from.x() << ", "
                      << leg.from.y() << ") to (" << leg.to.x() << ", " << leg.to.y()
                      << ") crosses the rough contour at (" << p.x() << ", " << p.y() << ")";
        break;
      }
    }
  }
}

}  // namespace lathesim::interp::test
