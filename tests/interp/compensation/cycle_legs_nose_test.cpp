// G90 and G94 under G40 with a nose radius: the nose-radius warning comes only from a leg that
// has a nose error. Tip 3 (s = (−1, −1)): a straight line with unit normal n = (nr, nz) is
// missed by R·(|nr + nz| − 1) (uncompensated_nose.hpp), 0 on a leg along Z or X, so a
// straight turn or face says nothing. A taper leg at angle a to its axis has n = (cos a,
// ±sin a) up to sign, so R·(cos a + sin a − 1) (material left) where the diameter grows
// towards the cut's end like a chamfer, R·(|cos a − sin a| − 1) (cut into the part) where it
// shrinks. The legs are those of lathe-cycles.md §1: G90 cuts from (X + 2R, Z of the start) to
// (X, Z); G94 from (X of the start, Z + R) to (X, Z).

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

InterpreterOptions nose08Tip3() {
  InterpreterOptions options = test::defaultOptions();
  options.offsets[1] = ToolOffset{0, 0, 0.8, 3, 0, 0};
  return options;
}

/// The cycle's cutting leg: its feed move that changes both X and Z.
const Move& taperLeg(const InterpretResult& result) {
  for (const Move& m : result.toolpath.moves)
    if (m.kind == MoveKind::Feed && m.from.x() != m.to.x() && m.from.y() != m.to.y()) return m;
  throw std::runtime_error("no taper leg");
}

TEST(CycleLegsNose, StraightG90AndG94SayNothing) {
  for (const char* cycle : {"G90 X30. Z-20. F0.2\nX26.\n", "G94 X10. Z-2. F0.2\nZ-4.\n"}) {
    const auto result = test::run(std::string("T0101 G99 M03 S800\nG00 X44. Z2.\n") + cycle + "G00 X60. Z50.\nM30\n",
                                  nose08Tip3());
    ASSERT_TRUE(result.ok()) << test::messageOf(result);
    EXPECT_TRUE(test::noseWarnings(result).empty()) << cycle << test::noseWarnings(result)[0].message;
  }
}

// G90 X30. Z-20. R∓1. from X44. Z2.: the leg runs from radius 15 ± 1 at Z2 to radius 15 at
// Z-20, 1 in radius over 22 in Z: tan a = 1/22, cos a = 22/√485, sin a = 1/√485.
//   R-1 (Φ28 → Φ30, grows like a chamfer): 0.8·(23/√485 − 1) = 0.0355 mm, material left;
//   R+1 (Φ32 → Φ30, a back taper):         0.8·(21/√485 − 1) = −0.0372 mm, cut into the part.
TEST(CycleLegsNose, ATaperedG90NamesItsError) {
  for (const double r : {-1.0, 1.0}) {
    const auto result = test::run(fmt::format("T0101 G99 M03 S800\nG00 X44. Z2.\nG90 X30. Z-20. R{:.1f} F0.2\n"
                                              "G00 X60. Z50.\nM30\n",
                                              r),
                                  nose08Tip3());
    ASSERT_TRUE(result.ok()) << test::messageOf(result);
    const Move& leg = taperLeg(result);
    EXPECT_NEAR(leg.from.x(), 15 + r, 1e-9);
    EXPECT_NEAR(leg.from.y(), 2, 1e-9);
    EXPECT_NEAR(leg.to.x(), 15, 1e-9);
    EXPECT_NEAR(leg.to.y(), -20, 1e-9);
    const double hand = 0.8 * ((r < 0 ? 23 : 21) / std::sqrt(485.0) - 1);
    const auto warnings = test::noseWarnings(result);
    ASSERT_EQ(warnings.size(), 1u) << "R" << r;
    EXPECT_EQ(warnings[0].line, 3);
    EXPECT_NE(warnings[0].message.find(fmt::format("up to {:.3f} mm normal to the surface, {}", std::abs(hand),
                                                   hand > 0 ? "material left" : "cut into the part")),
              std::string::npos)
        << warnings[0].message;
    EXPECT_NE(warnings[0].message.find("2.603° line"), std::string::npos) << warnings[0].message;  // atan(1/22)
  }
}

// G94 X10. Z-2. R-1. from X44. Z2.: the leg runs from radius 22 at Z-3 to radius 5 at Z-2,
// 17 in radius over 1 in Z: n ∝ (1, 17)/√290, |nr + nz| = 18/√290: 0.8·(18/√290 − 1) =
// 0.0456 mm, material left (the face leans like a chamfer towards the axis).
TEST(CycleLegsNose, ATaperedG94NamesItsError) {
  const auto result = test::run("T0101 G99 M03 S800\nG00 X44. Z2.\nG94 X10. Z-2. R-1. F0.2\nG00 X60. Z50.\nM30\n",
                                nose08Tip3());
  ASSERT_TRUE(result.ok()) << test::messageOf(result);
  const Move& leg = taperLeg(result);
  EXPECT_NEAR(leg.from.x(), 22, 1e-9);
  EXPECT_NEAR(leg.from.y(), -3, 1e-9);
  EXPECT_NEAR(leg.to.x(), 5, 1e-9);
  EXPECT_NEAR(leg.to.y(), -2, 1e-9);
  const auto warnings = test::noseWarnings(result);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].line, 3);
  EXPECT_NE(warnings[0].message.find(fmt::format("up to {:.3f} mm normal to the surface, material left",
                                                 0.8 * (18 / std::sqrt(290.0) - 1))),
            std::string::npos)
      << warnings[0].message;
}

// Under G42 the cycle offsets its own legs (cycle_nose_compensation.hpp): no warning for the
// taper, whether the nose is the offset's or only the tool's insert's.
TEST(CycleLegsNose, ACompensatedTaperedG90SaysNothing) {
  InterpreterOptions options = nose08Tip3();
  options.toolNoses[1] = ToolNose{0.8, 3};
  const auto result = test::run("T0101 G99 M03 S800\nG00 G42 X44. Z2.\nG90 X30. Z-20. R-1. F0.2\nG00 G40 X60. Z50.\nM30\n",
                                options);
  ASSERT_TRUE(result.ok()) << test::messageOf(result);
  const auto warnings = test::noseWarnings(result);
  EXPECT_TRUE(warnings.empty()) << warnings[0].message;
}

}  // namespace
}  // namespace lathesim::interp
