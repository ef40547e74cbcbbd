// Where the spindle stands when each move starts (interp/motion/spindle_angle.hpp), worked by
// hand on the default machine (rapid X 6000, Z 8000 mm/min, 3000 rpm) from X200 Z200.

#include "interp/motion/spindle_angle.hpp"

#include <gtest/gtest.h>

#include "interp/motion/cycle_time.hpp"
#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

std::vector<double> anglesOf(std::string_view program) {
  auto result = test::run(program);
  EXPECT_TRUE(result.ok());
  (void)assignMoveTimes(result.toolpath, MachineLimits{});
  std::vector<double> angles;
  for (const Move& m : result.toolpath.moves) angles.push_back(m.spindleAngleDeg);
  return angles;
}

void expectAngles(const std::vector<double>& actual, const std::vector<double>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(actual[i], expected[i], 1e-9) << "move " << i;
}

// The rapid to X50 Z5 takes 195/8000 min (Z decides) at 600 rpm: 14.625 turns → 225°. The G99
// feed of 5.05 mm at 0.2 mm/rev is 25.25 turns → 315°. After M05 the spindle stands: the next
// feed starts at 315° and so does the one after it. With M04 the angles run backwards.
TEST(SpindleAngle, FollowsTheRevolutionsOfEveryMove) {
  expectAngles(anglesOf("M03 S600\nG00 X50 Z5\nG99 G01 Z-0.05 F0.2 M05\nG01 X40\nX30\n"), {0, 225, 315, 315});
  expectAngles(anglesOf("M04 S600\nG00 X50 Z5\nG99 G01 Z-0.05 F0.2 M05\nG01 X40\nX30\n"), {0, 135, 45, 45});
}

// Before M03 the spindle has never turned: 0°. A thread move starts at its Q whatever came
// before; the move after it starts where the thread left the spindle: 12.5 turns after 90°.
TEST(SpindleAngle, ThreadMovesResetItToTheirStartAngle) {
  expectAngles(anglesOf("G00 X50 Z5\nG01 X40 F0.2\nM03 S600\nG00 X30\nG32 Z-20 F2 Q90000\nG00 X40\n"),
               {0, 0, 0, 90, 270});
  // M04: the thread starts at 90° in the direction the spindle turns, i.e. at −90° ≡ 270° about +Z.
  expectAngles(anglesOf("M04 S600\nG00 X30 Z5\nG32 Z-20 F2 Q90000\nG00 X40\n"), {0, 270, 90});
}

// A dwell of 0.125 s at 600 rpm turns the spindle 1.25 revolutions: 90°.
TEST(SpindleAngle, DwellTurnsTheSpindle) {
  expectAngles(anglesOf("M03 S600\nG04 X0.125\nG04 X1\n"), {0, 450.0 - 360.0});
}

}  // namespace
}  // namespace lathesim::interp
