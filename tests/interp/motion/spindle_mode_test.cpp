// G96 / G97 / G50 S (lathe-cycles.md §7): what each move is stamped with.

#include <gtest/gtest.h>

#include <cmath>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::run;

TEST(SpindleMode, G97IsThePowerOnStateAndSIsRpm) {
  const auto result = run("M03 S800\nG00 X40 Z10\n");
  ASSERT_TRUE(result.ok());
  const Move& m = result.toolpath.moves[0];
  EXPECT_EQ(m.spindleMode, SpindleMode::Rpm);
  EXPECT_EQ(m.spindleS, 800.0);
  EXPECT_TRUE(m.spindleOn);
  EXPECT_FALSE(m.spindleLimitRpm.has_value());
}

TEST(SpindleMode, G96SIsASurfaceSpeedWithTheG50Limit) {
  const auto result = run("G50 S2000\nG96 S200 M03\nG00 X40 Z10\n");
  ASSERT_TRUE(result.ok());
  const Move& m = result.toolpath.moves[0];
  EXPECT_EQ(m.spindleMode, SpindleMode::SurfaceSpeed);
  EXPECT_EQ(m.spindleS, 200.0);
  EXPECT_EQ(m.spindleLimitRpm, 2000.0);
}

TEST(SpindleMode, G96UnderG20IsFeetPerMinute) {
  const auto result = run("G20 G50 S2000\nG96 S100 M03\nG00 X4 Z1\n");
  ASSERT_TRUE(result.ok());
  EXPECT_NEAR(result.toolpath.moves[0].spindleS, 30.48, 1e-12);  // 100 ft = 30.48 m
}

TEST(SpindleMode, G50LimitIsNotStampedUnderG97) {
  const auto result = run("G50 S2000\nG97 S500 M03\nG00 X40 Z10\n");
  ASSERT_TRUE(result.ok());
  EXPECT_FALSE(result.toolpath.moves[0].spindleLimitRpm.has_value());
}

// G96 S200 at X40 (r 20): 1000·200 / (2π·20) = 5000/π ≈ 1591.5 rpm, under the G50 S2000
// limit. G97 with no S keeps it.
TEST(SpindleMode, G97WithoutSKeepsTheRpmG96LeftAtTheLastPoint) {
  const auto result = run("G50 S2000\nG96 S200 M03\nG00 X40 Z10\nG97\nG01 Z0 F0.2\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const Move& m = result.toolpath.moves[1];
  EXPECT_EQ(m.spindleMode, SpindleMode::Rpm);
  EXPECT_NEAR(m.spindleS, 5000.0 / M_PI, 1e-9);
}

// At X10 (r 5): 1000·200/(2π·5) ≈ 6366 rpm, held at the G50 S2000 limit: G97 keeps 2000.
TEST(SpindleMode, G97KeepsTheClampedRpm) {
  const auto result = run("G50 S2000\nG96 S200 M03\nG00 X10 Z10\nG97\nG01 Z0 F0.2\n");
  ASSERT_TRUE(result.ok());
  EXPECT_NEAR(result.toolpath.moves[1].spindleS, 2000.0, 1e-9);
}

// With no G50 S, max_rpm caps the kept speed: at X0 the speed is max_rpm itself.
TEST(SpindleMode, G97KeepsAtMostMaxRpm) {
  InterpreterOptions options = test::defaultOptions();
  options.machine.maxRpm = 2500;
  const auto result = interpret("G96 S200 M03\nG00 X0 Z10\nG97\nG01 Z0 F0.2\n", "test.nc", options);
  ASSERT_TRUE(result.ok());
  EXPECT_NEAR(result.toolpath.moves[1].spindleS, 2500.0, 1e-9);
}

TEST(SpindleMode, G97WithSTakesThatS) {
  const auto result = run("G50 S2000\nG96 S200 M03\nG00 X40 Z10\nG97 S700\nG01 Z0 F0.2\n");
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(result.toolpath.moves[1].spindleS, 700.0);
}

TEST(SpindleMode, G96RemembersItsSurfaceSpeedAcrossG97) {
  const auto result = run("G50 S2000\nG96 S180 M03\nG00 X40 Z10\nG97 S700\nG96\nG01 Z0 F0.2\n");
  ASSERT_TRUE(result.ok());
  const Move& m = result.toolpath.moves[1];
  EXPECT_EQ(m.spindleMode, SpindleMode::SurfaceSpeed);
  EXPECT_EQ(m.spindleS, 180.0);
}

TEST(SpindleMode, SInAG50BlockIsTheLimitNotTheSpeed) {
  const auto result = run("G97 S900 M03\nG50 S1500\nG00 X40 Z10\n");
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(result.toolpath.moves[0].spindleS, 900.0);
}

}  // namespace
}  // namespace lathesim::interp
