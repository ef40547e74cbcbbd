// Warnings the interpreter gives: they are Diagnostics of Severity::Warning located at the
// block, and the program still runs.

#include <gtest/gtest.h>

#include <string_view>

#include "interp/motion/feed_warnings.hpp"
#include "test_support.hpp"

namespace lathesim::interp {
namespace {

using test::run;
using test::warningsOf;

void expectOneWarning(const InterpretResult& result, int line, int column, std::string_view part) {
  EXPECT_TRUE(result.ok());
  const auto warnings = warningsOf(result);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].line, line) << warnings[0].message;
  EXPECT_EQ(warnings[0].column, column) << warnings[0].message;
  EXPECT_NE(warnings[0].message.find(part), std::string::npos) << warnings[0].message;
}

TEST(FeedWarnings, LargeFeedUnderG99) {
  // G99 is the power-on feed mode. Seed 000's own program does this.
  expectOneWarning(run("M03 S500\nG00 X130 Z5\nG94 X0 Z0 F200\n"), 3, 1,
                   "F200 under G99 is 200 mm per revolution; did you mean G98");
}

TEST(FeedWarnings, SmallFeedUnderG98) {
  expectOneWarning(run("G98 M03 S500\nG00 X60 Z2\n  G01 X40 F0.2\n"), 3, 3,
                   "F0.2 under G98 is 0.2 mm per minute; did you mean G99");
}

TEST(FeedWarnings, TinyFeedUnderG99) {
  // 0.005 mm/rev: a decimal point or an inch feed gone wrong more likely than a real feed.
  expectOneWarning(run("M03 S500\nG00 X60 Z2\nG01 X40 F0.005\n"), 3, 1,
                   "F0.005 under G99 is 0.005 mm per revolution, finer than a cutting edge takes (below 0.01 mm); "
                   "check the decimal point and the unit");
  EXPECT_TRUE(warningsOf(run("M03 S500\nG01 X60 F0.01\n")).empty());
  EXPECT_EQ(kMinPlausibleFeedMmPerRev, 0.01);
}

TEST(FeedWarnings, QuoteTheFeedAsWrittenInItsUnit) {
  // G20: F.2 is 0.2 inch = 5.08 mm per revolution, over 5.
  expectOneWarning(run("G20 M03 S500\nG00 X2. Z.1\nG01 X1. F.2\n"), 3, 1,
                   "F.2 under G99 is 0.2 inch (5.08 mm) per revolution; did you mean G98 (inch per minute)?");
}

TEST(FeedWarnings, OnceUntilTheFeedOrModeChanges) {
  // Lines 3 and 4 repeat the cycle with F200 (one warning); F300 on line 5 warns again.
  const auto result = run("M03 S500\nG00 X130 Z5\nG94 X0 Z0 F200\nZ-1\nZ-2 F300\n");
  const auto warnings = warningsOf(result);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0].line, 3);
  EXPECT_EQ(warnings[1].line, 5);
  EXPECT_NE(warnings[1].message.find("F300 under G99"), std::string::npos);
}

TEST(FeedWarnings, BoundariesArePlausible) {
  // Exactly 5 mm/rev and exactly 1 mm/min are still plausible.
  EXPECT_TRUE(warningsOf(run("M03 S500\nG01 X60 F5\n")).empty());
  EXPECT_TRUE(warningsOf(run("G98 M03 S500\nG01 X60 F1\n")).empty());
  EXPECT_EQ(kMaxPlausibleFeedMmPerRev, 5.0);
  EXPECT_EQ(kMinPlausibleFeedMmPerMin, 1.0);
}

TEST(FeedWarnings, RapidsDoNotCount) {
  EXPECT_TRUE(warningsOf(run("F200\nG00 X60 Z2\n")).empty());
}

TEST(SurfaceSpeedWarning, G96WithoutG50SBeforeItsFirstMove) {
  const auto result = run("M03\nG00 X60 Z2\n G96 S200\nG01 X40 F0.2\n");
  expectOneWarning(result, 3, 2, "G96 with no G50 S before its first move");
  EXPECT_NE(warningsOf(result)[0].message.find("max_rpm (3000 rpm)"), std::string::npos);
}

TEST(SurfaceSpeedWarning, G50SAfterG96ButBeforeTheMoveIsInTime) {
  EXPECT_TRUE(warningsOf(run("M03\nG96 S200\nG50 S2000\nG01 X40 F0.2\n")).empty());
  EXPECT_TRUE(warningsOf(run("G50 S2000\nM03 G96 S200\nG01 X40 F0.2\n")).empty());
}

TEST(SurfaceSpeedWarning, OncePerG96) {
  // G96 stays in force over several moves: one warning. After G97, a new G96 warns again.
  const auto result = run("M03 G96 S200\nG01 X40 F0.2\nG01 X30\nG97 S500\nG96\nG01 X20\n");
  const auto warnings = warningsOf(result);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0].line, 1);
  EXPECT_EQ(warnings[1].line, 5);
}

TEST(Warnings, AreShownWithTheirLineAndCaret) {
  const auto result = run("M03 S500\nG94 X0 Z0 F200\n");
  const auto warnings = warningsOf(result);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(format(warnings[0]),
            "test.nc:2:1: warning: F200 under G99 is 200 mm per revolution; did you mean G98 (mm per "
            "minute)?\nG94 X0 Z0 F200\n^");
}

TEST(Warnings, AProgramThatStopsReportsItsErrorAlone) {
  // F200 under G99 on line 2 would warn; the error on line 3 is all that is reported.
  test::expectError(run("M03 S500\nG94 X0 Z0 F200\nG05\n"), 3, 1, "unknown G code G05");
}

TEST(CycleStarts, EachCycleBlockRecordsItsStartPoint) {
  const auto result = run("G00 X60 Z2\nG94 X50 Z-5 F0.2\nZ-10\nG00 X70\nG90 X60 Z-20\n");
  ASSERT_TRUE(result.ok());
  const auto& starts = result.toolpath.cycleStarts;
  ASSERT_EQ(starts.size(), 3u);
  EXPECT_EQ(starts[0].code, "G94");
  EXPECT_EQ(starts[0].line, 2);
  EXPECT_EQ(starts[0].block, 1);
  EXPECT_EQ(starts[0].point, RZ(30, 2));
  EXPECT_EQ(starts[1].line, 3);
  EXPECT_EQ(starts[1].point, RZ(30, 2));
  EXPECT_EQ(starts[2].code, "G90");
  EXPECT_EQ(starts[2].point, RZ(35, 2));
}

}  // namespace
}  // namespace lathesim::interp
