// Overtravel: a move beyond a stated travel stops the program at its block, as the control's
// stored stroke limits do; beyond a derived one it is a warning. The travel here is X-10..X200, Z-100..Z200 (diameters).

#include "interp/motion/travel_limits.hpp"

#include <gtest/gtest.h>

#include "../test_support.hpp"
#include "interp/control/control_preset.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;

InterpreterOptions withTravel(bool derived = false) {
  InterpreterOptions options = test::defaultOptions();
  options.machine.travel = TravelLimits{-10, 200, -100, 200, derived, derived};
  return options;
}

TEST(TravelLimits, MovesWithinTheTravelRun) {
  EXPECT_TRUE(interpret("G00 X200 Z200\nG00 X-10 Z-100\nG28 U0 W0\n", "t.nc", withTravel()).ok());
}

TEST(TravelLimits, AMoveBeyondIsAnOvertravelAtItsBlock) {
  expectError(interpret("G00 X40 Z2\nG00 X250\n", "t.nc", withTravel()), 2, 1,
              "overtravel: this block moves the tool to X250 Z2 (in the setup's frame), beyond the machine's X "
              "travel, X-10 to X200 ([machine] travel_x)");
  expectError(interpret("G00 X40 Z2\nG01 Z-120 F0.2\n", "t.nc", withTravel()), 2, 1,
              "beyond the machine's Z travel, Z-100 to Z200 ([machine] travel_z)");
}

TEST(TravelLimits, AnArcBulgingBeyondIsCaughtAtItsHighestPoint) {
  // G03 from X100 Z0 to X100 Z-40 by R20: a half circle about (r 50, Z-20) over the top
  // (counter-clockwise with Z to the right and X up, from Z0 to Z-40), its top at r 70 =
  // X140. With the X travel to X130 (the tool starting at X100) it overtravels there although
  // both ends are inside.
  InterpreterOptions options = withTravel();
  options.machine.travel->xMaxDiameterMm = 130;
  options.startPosition = RZ(50, 200);
  expectError(interpret("G00 X100 Z0\nG03 X100 Z-40 R20 F0.2\n", "t.nc", options), 2, 1,
              "overtravel: this block moves the tool to X140 Z-20 (in the setup's frame)");
}

TEST(TravelLimits, ADerivedTravelWarnsAtTheBlockAndRuns) {
  // A travel nobody stated is an assumption: the program runs, and the first block beyond it
  // is warned of at its line, naming where the limit came from. G20 X20 is 508 mm of diameter.
  const auto result = interpret("G20 G00 X20. Z.1\nG00 X30.\n", "t.nc", withTravel(true));
  ASSERT_TRUE(result.ok()) << test::messageOf(result);
  const auto warnings = test::warningsOf(result);
  ASSERT_EQ(warnings.size(), 1u) << warnings.back().message;  // once per axis: the second block is beyond too
  EXPECT_EQ(warnings[0].line, 1);
  EXPECT_EQ(warnings[0].column, 1);
  EXPECT_EQ(warnings[0].message,
            "overtravel: this block moves the tool to X508 Z2.54 (in the setup's frame), beyond the machine's X "
            "travel, X-10 to X200, derived from [machine] reference and start and the bar, as no setup states it: "
            "an assumption, not checked further on this axis; give [machine] travel_x to have it checked");
  EXPECT_EQ(result.toolpath.moves.back().to.x(), 381.0);  // X30 in inch, as a radius: 15 × 25.4
}

TEST(TravelLimits, ARearToolPostBelowTheAxisWarnsUnderDerivedTravelAndStopsUnderStated) {
  // A rear tool post works at negative X: is below the derived X-10 (minus the bar).
  // Derived: a warning at line 2, one per axis even when both axes leave (line 3's Z-150).
  const std::string program = "G00 X40. Z2.\nG00 X-25.5\nG00 Z-150.\n";
  const auto derived = interpret(program, "t.nc", withTravel(true));
  ASSERT_TRUE(derived.ok()) << test::messageOf(derived);
  const auto warnings = test::warningsOf(derived);
  ASSERT_EQ(warnings.size(), 2u) << warnings.back().message;
  EXPECT_EQ(warnings[0].line, 2);
  EXPECT_NE(warnings[0].message.find("beyond the machine's X travel, X-10 to X200, derived"), std::string::npos);
  EXPECT_EQ(warnings[1].line, 3);
  EXPECT_NE(warnings[1].message.find("beyond the machine's Z travel, Z-100 to Z200, derived"), std::string::npos);
  // Stated: the same block stops the program.
  expectError(interpret(program, "t.nc", withTravel(false)), 2, 1,
              "overtravel: this block moves the tool to X-25.5 Z2 (in the setup's frame), beyond the machine's X "
              "travel, X-10 to X200 ([machine] travel_x)");
}

TEST(TravelLimits, OnlyTheStatedAxisStops) {
  // X stated, Z derived: the Z overtravel at line 2 warns, the X one at line 3 stops.
  InterpreterOptions options = withTravel(false);
  options.machine.travel->zDerived = true;
  const auto result = interpret("G00 X40 Z2\nG00 Z-150\nG00 X250\n", "t.nc", options);
  expectError(result, 3, 1, "beyond the machine's X travel, X-10 to X200 ([machine] travel_x)");
  const auto zOnly = interpret("G00 X40 Z2\nG00 Z-150\n", "t.nc", options);
  ASSERT_TRUE(zOnly.ok());
  ASSERT_EQ(test::warningsOf(zOnly).size(), 1u);
  EXPECT_EQ(test::warningsOf(zOnly)[0].line, 2);
}

TEST(TravelLimits, TheToolOffsetAndG50AreInTheSetupsFrame) {
  // G50 X400 Z200 calls the tool's X200 X400: the program's X0 is at setup X-200. G00 X390 =
  // setup X190: inside. Without the G50 the same X390 overtravels.
  EXPECT_TRUE(interpret("G50 X400 Z200\nG00 X390\n", "t.nc", withTravel()).ok());
  EXPECT_FALSE(interpret("G00 X390\n", "t.nc", withTravel()).ok());
}

TEST(TravelLimits, G28UnderAToolOffsetReachesTheReferenceNotBeyondIt) {
  // The travel ends at the reference X200 Z200 (where derived travel puts it). Offset 1 shifts
  // the tip by X+0.4 and Z+0.6: G00 X40 Z2 ends at X40.4 Z2.6; G28 U0 W0 returns both axes to the
  // reference itself, X200 Z200, not X200.4 Z200.6 beyond the travel.
  InterpreterOptions options = withTravel(true);
  options.offsets[1] = ToolOffset{0.4, 0.6, 0, 0, 0, 0};
  const auto result = interpret("T0101\nG00 X40 Z2\nG28 U0 W0\n", "t.nc", options);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  EXPECT_EQ(result.toolpath.moves.back().to, RZ(100, 200));
}

}  // namespace
}  // namespace lathesim::interp
