// Move times by hand, one rule at a time (interp/motion/cycle_time.hpp). The machine is the
// default one: rapids X 6000 and Z 8000 mm/min, max_rpm 3000.

#include "interp/motion/cycle_time.hpp"
#include "interp/motion/spindle_speed.hpp"
#include "../test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lathesim::interp {
namespace {

const MachineLimits kMachine{};

Move straight(MoveKind kind, RZ from, RZ to) {
  Move m;
  m.kind = kind;
  m.from = from;
  m.to = to;
  m.spindleOn = true;
  return m;
}

Move feed(RZ from, RZ to, double f, FeedMode mode) {
  Move m = straight(MoveKind::Feed, from, to);
  m.feed = f;
  m.feedMode = mode;
  return m;
}

Move underG97(Move m, double rpm) {
  m.spindleMode = SpindleMode::Rpm;
  m.spindleS = rpm;
  return m;
}

Move underG96(Move m, double metresPerMin, std::optional<double> limitRpm) {
  m.spindleMode = SpindleMode::SurfaceSpeed;
  m.spindleS = metresPerMin;
  m.spindleLimitRpm = limitRpm;
  return m;
}

double timeOf(const Move& m, const MachineLimits& machine = kMachine) { return moveTimeS(m, machine).value(); }

TEST(SpindleSpeed, SurfaceSpeedRpmByHand) {
  // V 200 at r 20: 200000 / (40π) = 5000/π ≈ 1591.5 rpm, under every clamp.
  EXPECT_NEAR(surfaceSpeedRpm(200, 20, std::nullopt, kMachine), 5000 / M_PI, 1e-9);
  EXPECT_NEAR(surfaceSpeedRpm(200, -20, std::nullopt, kMachine), 5000 / M_PI, 1e-9);
  EXPECT_EQ(surfaceSpeedRpm(200, 20, 1000.0, kMachine), 1000.0);  // the G50 S limit
  EXPECT_EQ(surfaceSpeedRpm(200, 0, std::nullopt, kMachine), 3000.0);  // max_rpm at the axis
  EXPECT_EQ(surfaceSpeedRpm(200, 0, 5000.0, kMachine), 3000.0);  // a limit above max_rpm
  EXPECT_EQ(surfaceSpeedRpm(0, 0, std::nullopt, kMachine), 0.0);
  EXPECT_EQ(constantRpm(5000, kMachine), 3000.0);
}

TEST(CycleTime, RapidLimitedByX) {
  // Δr 60 at 6000 mm/min = 0.01 min; ΔZ 40 at 8000 = 0.005 min: X decides, 0.6 s.
  EXPECT_NEAR(timeOf(straight(MoveKind::Rapid, {70, 0}, {10, 40})), 0.6, 1e-12);
}

TEST(CycleTime, RapidLimitedByZ) {
  // Δr 10 → 0.1 s; ΔZ 160 at 8000 mm/min = 0.02 min = 1.2 s: Z decides.
  EXPECT_NEAR(timeOf(straight(MoveKind::Rapid, {20, 150}, {30, -10})), 1.2, 1e-12);
}

TEST(CycleTime, RapidRatesComeFromTheMachine) {
  // Rapid X 3000: Δr 60 → 0.02 min = 1.2 s.
  MachineLimits slowX;
  slowX.rapidXMmPerMin = 3000.0;
  EXPECT_NEAR(timeOf(straight(MoveKind::Rapid, {70, 0}, {10, 40}), slowX), 1.2, 1e-12);
}

TEST(CycleTime, FeedPerMinuteIsLengthOverF) {
  // G98 F150: a 3-4-5 line 50 mm long → 50/150 min = 20 s, whatever the spindle does.
  Move m = feed({20, 0}, {50, -40}, 150, FeedMode::PerMinute);
  m.spindleOn = false;
  EXPECT_NEAR(timeOf(m), 20.0, 1e-12);
}

TEST(CycleTime, FeedPerRevolutionUnderG97) {
  // G99 F0.2 at S1000: 200 mm/min; 30 mm → 0.15 min = 9 s.
  EXPECT_NEAR(timeOf(underG97(feed({20, 0}, {20, -30}, 0.2, FeedMode::PerRevolution), 1000)), 9.0, 1e-12);
  // S5000 is capped at max_rpm 3000: 600 mm/min → 3 s.
  EXPECT_NEAR(timeOf(underG97(feed({20, 0}, {20, -30}, 0.2, FeedMode::PerRevolution), 5000)), 3.0, 1e-12);
}

TEST(CycleTime, G50LimitDoesNotApplyUnderG97) {
  Move m = underG97(feed({20, 0}, {20, -30}, 0.2, FeedMode::PerRevolution), 1000);
  m.spindleLimitRpm = 500;  // inactive under G97: still 1000 rpm, 9 s
  EXPECT_NEAR(timeOf(m), 9.0, 1e-12);
}

// Facing Φ100 → Φ0 at G96 V = 200 m/min, f = 0.25 mm/rev, G50 S2000 (below max_rpm 3000).
// rpm(r) = 1000·200 / (2π r) = 100000/(π r) until it reaches 2000 at
// r_c = 100000 / (2000 π) = 50/π ≈ 15.92 mm, then 2000.
// time = 60/f · ∫ dr / rpm(r)
//      = 240 · [ ∫_0^{r_c} dr/2000 + ∫_{r_c}^{50} π r/100000 dr ]
//      = 240 · [ (50/π)/2000 + π (2500 − 2500/π²) / 200000 ]
//      = 240 · [ 1/(40π) + (π − 1/π)/80 ] = 6/π + 3π − 3/π = 3π + 3/π ≈ 10.3797 s.
TEST(CycleTime, G96FaceCutToTheAxisWithAG50Clamp) {
  const Move m = underG96(feed({50, 0}, {0, 0}, 0.25, FeedMode::PerRevolution), 200, 2000);
  EXPECT_NEAR(timeOf(m), 3 * M_PI + 3 / M_PI, 1e-9);
  // The same cut outwards takes as long.
  const Move back = underG96(feed({0, 0}, {50, 0}, 0.25, FeedMode::PerRevolution), 200, 2000);
  EXPECT_NEAR(timeOf(back), 3 * M_PI + 3 / M_PI, 1e-9);
}

// With no G50 S, max_rpm 3000 clamps: r_c = 100000/(3000π) = 100/(3π).
// time = 240 · [ (100/(3π))/3000 + π (2500 − 10000/(9π²)) / 200000 ]
//      = 240 · [ 1/(90π) + π/80 − 1/(180π) ] = 240 · [ 1/(180π) + π/80 ] = 4/(3π) + 3π.
TEST(CycleTime, G96WithoutG50IsClampedByMaxRpm) {
  const Move m = underG96(feed({50, 0}, {0, 0}, 0.25, FeedMode::PerRevolution), 200, std::nullopt);
  EXPECT_NEAR(timeOf(m), 4 / (3 * M_PI) + 3 * M_PI, 1e-9);
  // A G50 S above max_rpm changes nothing: max_rpm still caps it.
  EXPECT_NEAR(timeOf(underG96(m, 200, 5000)), 4 / (3 * M_PI) + 3 * M_PI, 1e-9);
}

TEST(CycleTime, G96TurningAtOneRadiusIsConstantRpm) {
  // r 40, V 200: 100000/(40π) = 795.8 rpm; 0.2 mm/rev over 30 mm:
  // 30 / (0.2 · 2500/π) min = 0.06π min = 3.6π s.
  const Move m = underG96(feed({40, 0}, {40, -30}, 0.2, FeedMode::PerRevolution), 200, 2000);
  EXPECT_NEAR(timeOf(m), 3.6 * M_PI, 1e-9);
}

// A quarter arc about the axis point (0, 0), radius 20, from (r 20, Z0) to (r 0, Z20). In
// the drawing view (Z right, r up) that runs from the top to the right: clockwise.
Move quarterArc(MoveKind kind) {
  Move m = straight(kind, {20, 0}, {0, 20});
  m.center = RZ(0, 0);
  return m;
}

TEST(CycleTime, ArcLengthFollowsTheDirection) {
  // G98 F100. CW: a quarter, 10π mm → 6π s. CCW: the other three quarters, 30π mm → 18π s.
  for (auto [kind, seconds] : {std::pair{MoveKind::ArcCW, 6 * M_PI}, std::pair{MoveKind::ArcCCW, 18 * M_PI}}) {
    Move m = quarterArc(kind);
    m.feed = 100;
    m.feedMode = FeedMode::PerMinute;
    EXPECT_NEAR(timeOf(m), seconds, 1e-9);
  }
}

// The CW quarter under G96 V 200, f 0.2, no G50 (max_rpm 3000). r = 20 sin ψ, ψ from 0 at
// the end (r 0) to π/2 at the start (r 20), ds = 20 dψ. 1/rpm = max(k r, c) with
// k = 2π/200000 = π/100000 min/(rev·mm), c = 1/3000; the clamp lets go at
// r_c = c/k = 100/(3π) ≈ 10.61, i.e. at ψ_c = asin(r_c/20) = asin(5/(3π)).
// ∫ = 20 · [ c ψ_c + k · 20 · (cos ψ_c − cos(π/2)) ] = 20 c ψ_c + 400 k cos ψ_c,
// time = 60/0.2 · ∫ = 300 · (ψ_c/150 + 0.004π · cos ψ_c).
TEST(CycleTime, G96ArcIsIntegratedAlongTheArc) {
  Move m = underG96(quarterArc(MoveKind::ArcCW), 200, std::nullopt);
  m.feed = 0.2;
  m.feedMode = FeedMode::PerRevolution;
  const double psiC = std::asin(5.0 / (3.0 * M_PI));
  EXPECT_NEAR(timeOf(m), 300.0 * (psiC / 150.0 + 0.004 * M_PI * std::cos(psiC)), 1e-9);
}

TEST(CycleTime, G96AboveTheClampRadiusFollowsTheRadiusAlone) {
  // V 200, f 0.25, G50 S2000: r_c = 50/π ≈ 15.9, so r 50 → 30 never clamps:
  // 240 · ∫_30^50 π r/100000 dr = 240 · π (2500 − 900) / 200000 = 1.92π s.
  const Move m = underG96(feed({50, 0}, {30, -5}, 0.25, FeedMode::PerRevolution), 200, 2000);
  // The taper is longer than its radial travel by L/|Δr| = √(20² + 5²)/20.
  EXPECT_NEAR(timeOf(m), 1.92 * M_PI * std::sqrt(425.0) / 20.0, 1e-9);
}

// An arc that is neither centred on the axis nor a quarter, crossing the clamp radius twice:
// checked against Simpson's rule on t = 60/(f·rpm(r(ψ)))·R over the swept angle, computed
// here from the definition with no piecewise split (the kinks cost Simpson accuracy, so
// 400000 panels for 1e-7 relative).
TEST(CycleTime, G96ArcAgreesWithNumericIntegration) {
  // Centre (r 12, Z −10), radius 8: r runs from 12 + 8 sin ψ; CCW from ψ = −2.5 to 2.0 rad
  // passes r 4 .. 20; V 120, G50 S1800: r_c = 120000/(2π·1800) ≈ 10.6.
  const RZ center(12, -10);
  const double R = 8, psi0 = -2.5, psi1 = 2.0;
  Move m = straight(MoveKind::ArcCCW, center + R * RZ(std::sin(psi0), std::cos(psi0)),
                    center + R * RZ(std::sin(psi1), std::cos(psi1)));
  m.center = center;
  m = underG96(m, 120, 1800);
  m.feed = 0.15;
  m.feedMode = FeedMode::PerRevolution;
  auto integrand = [&](double psi) {
    const double r = center.x() + R * std::sin(psi);
    const double rpm = std::min(120000.0 / (2 * M_PI * r), 1800.0);
    return 60.0 / (0.15 * rpm) * R;
  };
  const int n = 400000;
  const double h = (psi1 - psi0) / n;
  double sum = integrand(psi0) + integrand(psi1);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * integrand(psi0 + i * h);
  const double simpson = sum * h / 3;
  EXPECT_NEAR(timeOf(m), simpson, 1e-7 * simpson);
}

TEST(CycleTime, DwellIsItsOwnTime) {
  Move m = straight(MoveKind::Dwell, {20, 0}, {20, 0});
  m.dwellS = 1.5;
  EXPECT_DOUBLE_EQ(timeOf(m), 1.5);
}

TEST(CycleTime, AssignFillsEveryMoveAndTheSumIsTheCycleTime) {
  Toolpath path;
  path.moves.push_back(straight(MoveKind::Rapid, {70, 0}, {10, 40}));                              // 0.6 s
  path.moves.push_back(underG97(feed({20, 0}, {20, -30}, 0.2, FeedMode::PerRevolution), 1000));   // 9 s
  EXPECT_TRUE(assignMoveTimes(path, kMachine).empty());
  EXPECT_NEAR(path.moves[0].timeS, 0.6, 1e-12);
  EXPECT_NEAR(path.moves[1].timeS, 9.0, 1e-12);
  EXPECT_NEAR(cycleTimeS(path), 9.6, 1e-12);
}

TEST(CycleTime, FeedPerRevolutionWithTheSpindleStoppedCountsZeroAndWarnsOncePerBlock) {
  Toolpath path;
  for (int i = 0; i < 2; ++i) {
    Move m = underG97(feed({20, 0}, {20, -30}, 0.2, FeedMode::PerRevolution), 1000);
    m.spindleOn = false;
    m.block = 4;
    m.line = 5;
    m.column = 3;
    path.moves.push_back(m);
  }
  const std::vector<Error> warnings = assignMoveTimes(path, kMachine);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].line, 5);
  EXPECT_EQ(warnings[0].column, 3);
  EXPECT_NE(warnings[0].message.find("a feed in mm per revolution (G99) with the spindle stopped"),
            std::string::npos)
      << warnings[0].message;
  EXPECT_NE(warnings[0].message.find("counted as 0 s"), std::string::npos);
  EXPECT_EQ(path.moves[0].timeS, 0.0);
  EXPECT_EQ(path.moves[1].timeS, 0.0);
}

TEST(CycleTime, FeedPerRevolutionAtS0Warns) {
  Toolpath path;
  path.moves.push_back(underG97(feed({20, 0}, {20, -30}, 0.2, FeedMode::PerRevolution), 0));
  const std::vector<Error> warnings = assignMoveTimes(path, kMachine);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].message.find("(G99) at S0 never moves"), std::string::npos) << warnings[0].message;
}

// A thread move turns one revolution per lead of long-axis travel, whatever its path's length
// and whatever G98/G99 says: Z5 → Z-20 at lead 2 is 12.5 revolutions, at 500 rpm 1.5 s; the
// taper X30 Z-20 → X34 Z-25 (Z the long axis) 2.5 revolutions, 0.3 s.
TEST(CycleTime, ThreadIsRevolutionsOverRpm) {
  const auto result = test::run("G98 M03 S500\nG00 X30 Z5\nG32 Z-20 F2\nG32 X34 Z-25\n");
  ASSERT_TRUE(result.ok());
  Toolpath path = result.toolpath;
  EXPECT_TRUE(assignMoveTimes(path, kMachine).empty());
  EXPECT_NEAR(path.moves[1].timeS, 1.5, 1e-12);
  EXPECT_NEAR(path.moves[2].timeS, 0.3, 1e-12);
}

// Under G96 S100 with G50 S1000 at radius 15: 1000·100/(2π·15) = 1061 rpm, clamped to 1000:
// 12.5 revolutions take 0.75 s.
TEST(CycleTime, ThreadUnderG96FollowsTheClampedRpm) {
  const auto result = test::run("G50 S1000\nG96 S100 M03\nG00 X30 Z5\nG32 Z-20 F2\n");
  ASSERT_TRUE(result.ok());
  Toolpath path = result.toolpath;
  EXPECT_TRUE(assignMoveTimes(path, kMachine).empty());
  EXPECT_NEAR(path.moves[1].timeS, 0.75, 1e-12);
}

TEST(CycleTime, ThreadWithTheSpindleStoppedWarns) {
  const auto result = test::run("G00 X30 Z5\nG32 Z-20 F2\n");
  Toolpath path = result.toolpath;
  const std::vector<Error> warnings = assignMoveTimes(path, kMachine);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].message.find("a thread cut (one lead per revolution) with the spindle stopped"),
            std::string::npos);
}

}  // namespace
}  // namespace lathesim::interp
