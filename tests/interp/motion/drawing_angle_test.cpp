// Direct drawing dimensions, format 1: a line by one end and its angle from +Z (counter-
// clockwise, Z to the right and X up). The tool stands at X20 Z0 = (r 10, Z0) before each line.

#include "interp/motion/drawing_angle.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "../test_support.hpp"
#include "interp/control/control_preset.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;
using test::expectMoves;
using test::kFeed;
using test::kRapid;

InterpretResult runUnder(std::string_view preset, std::string_view line) {
  InterpreterOptions options = test::defaultOptions();
  options.control = controlPreset(preset)->parameters;
  options.control.rapidPath = RapidPath::Linear;
  return interpret("G99 G00 X20. Z0.\nG01 " + std::string(line) + " F0.2\n", "t.nc", options);
}

TEST(DrawingAngle, GskQGivesTheLinesAngleInThousandthsOfADegree) {
  // Q135000 = 135°: tan 135° = −1, so from r 10 to X30 (r 15) the line goes Δr 5, ΔZ 5/−1 = −5:
  // a 5 × 45° chamfer toward the chuck.
  const auto result = runUnder("gsk980tdi", "X30 Q135000");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 10, 0, 0, 0}, {kFeed, 10, 0, 15, -5, 0.2, 0}});
  // Z given: Q150000 = 150°, tan 150° = −1/√3: to Z-10 the radius grows 10/√3 = 5.7735.
  const auto byZ = runUnder("gsk980tdi", "Z-10 Q150000");
  ASSERT_TRUE(byZ.ok());
  EXPECT_NEAR(byZ.toolpath.moves[1].to.x(), 10 + 10 / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(byZ.toolpath.moves[1].to.y(), -10, 1e-12);
}

TEST(DrawingAngle, FanucAIsTheSameLineAndCountsIncrementsWithoutAPoint) {
  // and Q135000 describe one line (only the slope matters).
  const auto result = runUnder("fanuc-0i-t", "X30. A-45.");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 10, 0, 0, 0}, {kFeed, 10, 0, 15, -5, 0.2, 0}});
  // Under DPI = 0, A45 is 0.045°: a line within 1° of the Z axis never reaches X30.
  expectError(runUnder("fanuc-0i-t", "X30. A45"), 2, 10,
              "A45 is a line along Z: it never reaches another X; give Z instead, or an angle at least 1° off "
              "the Z axis");
}

TEST(DrawingAngle, TheCommaFormIsTheControlsWhenItSaysSo) {
  InterpreterOptions options = test::defaultOptions();
  options.control.drawingAngleWord = DrawingAngleWord::CommaA;
  const auto result = interpret("G00 X20. Z0.\nG01 X30. ,A135. F0.2\n", "t.nc", options);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves({result.toolpath.moves.begin() + 1, result.toolpath.moves.end()}, {{kFeed, 10, 0, 15, -5, 0.2, 0}});
  // Under the GSK, A is no angle: the word is left over, and the control that reads it is named;
  // ,A is read by no preset, only by the parameter.
  expectError(runUnder("gsk980tdi", "X30. A135."), 2, 10,
              "A135. is a line's angle where the control reads its angle in A (drawing_angle_word), which this "
              "control does not (its angle word is Q): run with --control fanuc-0i-t");
  expectError(runUnder("fanuc-0i-t", "X30. ,A135."), 2, 10,
              ",A135. is a line's angle where the control reads its angle in ,A (drawing_angle_word), which this "
              "control does not (its angle word is A): set drawing_angle_word = \",A\" in the setup's [control]");
  EXPECT_TRUE(runUnder("fanuc-0i-t", "X30. A135.").ok());
}

// A sweep of angles all round, X or Z given: the line ends on the given X (Z) and runs along the
// angle, its direction (ΔZ, Δr) parallel to (cos a, sin a): ΔZ·sin a − Δr·cos a = 0. From
// (r 10, Z0) to X30 (r 15) or to Z-10.
TEST(DrawingAngle, ASweepOfAnglesEndsOnTheGivenAxisAlongTheAngle) {
  for (const int degrees : {-170, -135, -100, -60, -30, -5, 3, 20, 45, 70, 88, 92, 110, 135, 160, 177, 200, 250, 300, 340}) {
    const double a = degrees * std::acos(-1.0) / 180.0;
    for (const bool givesX : {true, false}) {
      SCOPED_TRACE(testing::Message() << degrees << "°, " << (givesX ? "X" : "Z") << " given");
      const double offZ = std::abs(std::remainder(degrees, 180.0));  // from the Z axis
      const double offX = std::abs(std::remainder(degrees - 90.0, 180.0));
      if ((givesX ? offZ : offX) < 1.0) continue;  // the alarm, tested below
      if (!givesX && std::tan(a) > 1.0) continue;    // Z-10 would take it through the axis
      const auto result =
          runUnder("gsk980tdi", std::string(givesX ? "X30" : "Z-10") + " Q" + std::to_string(degrees * 1000));
      ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
      const Move& line = result.toolpath.moves.at(1);
      EXPECT_EQ(line.from, RZ(10, 0));
      EXPECT_EQ(givesX ? line.to.x() : line.to.y(), givesX ? 15 : -10);
      const RZ d = line.to - line.from;
      EXPECT_NEAR(d.y() * std::sin(a) - d.x() * std::cos(a), 0, 1e-9 * (1 + d.norm()));
    }
  }
}

TEST(DrawingAngle, LinesAlongAnAxisAloneOrWithBothEndsAreNamed) {
  expectError(runUnder("gsk980tdi", "Z-10 Q90000"), 2, 10,
              "Q90000 is a line along X: it never reaches another Z; give X instead");
  expectError(runUnder("gsk980tdi", "Q135000"), 2, 5,
              "Q135000 alone starts a drawing dimension of two lines (their intersection found by the control), "
              "which lathesim does not read yet");
  // X and Z given: the end point is known, the angle ignored with a warning (GSK §3.13).
  const auto both = runUnder("gsk980tdi", "X30. Z-8. Q135000");
  ASSERT_TRUE(both.ok());
  EXPECT_EQ(both.toolpath.moves[1].to, RZ(15, -8));
  ASSERT_EQ(both.diagnostics.size(), 1u);
  EXPECT_EQ(both.diagnostics[0].message, "Q135000 is ignored: X and Z give the end point (GSK980TDi §3.13)");
}

}  // namespace
}  // namespace lathesim::interp
