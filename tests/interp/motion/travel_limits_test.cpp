// Overtravel: a move beyond the machine's travel stops the program at its block, as the
// control's stored stroke limits do. The travel here is X-10..X200, Z-100..Z200 (diameters).

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

TEST(TravelLimits, AnInchProgramReadAsMillimetresGoesNowhere) {
  // The travel derived from a setup names where it came from. G20 X20 is 508 mm of diameter.
  expectError(interpret("G20 G00 X20 Z.1\n", "t.nc", withTravel(true)), 1, 1,
              "overtravel: this block moves the tool to X508 Z2.54 (in the setup's frame), beyond the machine's X "
              "travel, X-10 to X200, derived from [machine] reference and start and the bar; give [machine] "
              "travel_x if the machine reaches further");
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
