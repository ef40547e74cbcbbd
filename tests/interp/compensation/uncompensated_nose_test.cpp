// A contour cut under G40 with a nose radius: one warning for the run, naming the worst
// deviation from the drawing, each figure worked out by hand (uncompensated_nose.hpp).
// Tip 3 (s = (−1, −1)): the nose centre runs R·(1, 1) from the drawn path, so a line with unit
// normal n = (nr, nz) is missed by R·(|nr + nz| − 1): 0 on diameters and faces, R(√2 − 1) on a
// 45° chamfer, R(cos 30° + sin 30° − 1) on a 30° taper.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

InterpreterOptions withOffset(double radiusMm, int tip) {
  InterpreterOptions options = test::defaultOptions();
  options.offsets[1] = ToolOffset{0, 0, radiusMm, tip, 0, 0};
  return options;
}

// Shaft Φ14 → 45° chamfer to Φ20 (line 4) → Φ20 → away.
constexpr std::string_view kChamfer =
    "T0101 G99 M03 S800\n"
    "G00 X14 Z2\n"
    "G01 Z0 F0.1\n"
    "X20 Z-3\n"
    "Z-10\n"
    "G00 X40\n"
    "M30\n";

TEST(UncompensatedNose, A45DegreeChamferIsMissedByRTimesRoot2MinusOne) {
  for (const double r : {0.2, 0.4, 0.8, 1.2, 1.6}) {
    SCOPED_TRACE(testing::Message() << "R" << r);
    const auto result = test::run(kChamfer, withOffset(r, 3));
    ASSERT_TRUE(result.ok()) << test::messageOf(result);
    const auto warnings = test::noseWarnings(result);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].line, 4);
    const double hand = r * (std::sqrt(2.0) - 1);  // R0.8: 0.331
    EXPECT_NE(warnings[0].message.find(fmt::format("up to {:.3f} mm", hand)), std::string::npos)
        << warnings[0].message;
    EXPECT_NE(warnings[0].message.find("material left on this block's 45° line"), std::string::npos)
        << warnings[0].message;
    EXPECT_NE(warnings[0].message.find(fmt::format("R{:g} of offset 1 (tip 3)", r)), std::string::npos);
  }
}

TEST(UncompensatedNose, The0Point33OfTheIssueAtR0Point8) {
  const auto result = test::run(kChamfer, withOffset(0.8, 3));
  const auto warnings = test::noseWarnings(result);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].message.find("up to 0.331 mm"), std::string::npos) << warnings[0].message;
}

TEST(UncompensatedNose, EveryTipNumberOnTheChamfer) {
  // The chamfer's normal n = (1, 1)/√2 up to its sign; the deviation R(|s·n| − 1):
  //   tips 1, 3: |±2/√2| = √2 → R(√2 − 1) left; tips 2, 4: s·n = 0 → the side cannot be told,
  //   no word from the chamfer (the diameter and face are R(1 − 1) = 0 for them too): none;
  //   tips 5–8: |s·n| = 1/√2 → R(1/√2 − 1) = −0.2929R, cut into the part; tips 0, 9: −R.
  const double r = 0.8;
  const double k = std::sqrt(2.0);
  const struct {
    int tip;
    double hand;  // 0: no warning
  } cases[] = {{0, -r},          {1, r * (k - 1)},     {2, 0},           {3, r * (k - 1)},
               {4, 0},           {5, r * (1 / k - 1)}, {6, r * (1 / k - 1)}, {7, r * (1 / k - 1)},
               {8, r * (1 / k - 1)}, {9, -r}};
  for (const auto& c : cases) {
    SCOPED_TRACE(testing::Message() << "tip " << c.tip);
    const auto result = test::run(kChamfer, withOffset(r, c.tip));
    ASSERT_TRUE(result.ok()) << test::messageOf(result);
    const auto warnings = test::noseWarnings(result);
    if (c.hand == 0) {
      EXPECT_TRUE(warnings.empty()) << warnings[0].message;
      continue;
    }
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].message.find(fmt::format("up to {:.3f} mm normal to the surface, {}", std::abs(c.hand),
                                                   c.hand > 0 ? "material left" : "cut into the part")),
              std::string::npos)
        << warnings[0].message;
  }
}

TEST(UncompensatedNose, A30DegreeTaper) {
  // (7, 0) → (9, −2√3): 30° to the axis, n = (cos 30°, sin 30°) up to sign: 0.8(0.8660 + 0.5 − 1).
  const auto result = test::run(
      "T0101 G99 M03 S800\n"
      "G00 X14 Z2\n"
      "G01 Z0 F0.1\n"
      "X18 Z-3.46410162\n"
      "G00 X40\n"
      "M30\n",
      withOffset(0.8, 3));
  const auto warnings = test::noseWarnings(result);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].line, 4);
  const double hand = 0.8 * (std::cos(std::numbers::pi / 6) + std::sin(std::numbers::pi / 6) - 1);  // 0.293
  EXPECT_NE(warnings[0].message.find(fmt::format("up to {:.3f} mm", hand)), std::string::npos) << warnings[0].message;
  EXPECT_NE(warnings[0].message.find("30° line"), std::string::npos) << warnings[0].message;
}

TEST(UncompensatedNose, AnArcEndingShortOf45DegreesIsWorstAtItsEnd) {
  // G03 R5 about O = (0, −10) from n at 60° to the axis, (4.3301, −7.5), to n at 90°, (5, −10):
  // convex, the tool outside. The nose centres run on the arc moved by R(1, 1), so the cut is
  // the circle of radius 5 − R about O + R(1, 1); the drawn point at 60°, Q = O + 5(sin 60°,
  // cos 60°), lies inside it by (5 − R) − |Q − O − R(1, 1)| — material left, the most at that
  // end (at 90° it is 0: the diameter).
  const double r = 0.8;
  const double qr = 5 * std::sin(std::numbers::pi / 3) - r, qz = 5 * std::cos(std::numbers::pi / 3) - r;
  const double hand = (5 - r) - std::sqrt(qr * qr + qz * qz);  // 0.282
  const auto result = test::run(
      "T0101 G99 M03 S800\n"
      "G00 X8.66025404 Z-7.5\n"
      "G03 X10 Z-10 R5 F0.1\n"
      "G00 X40\n"
      "M30\n",
      withOffset(r, 3));
  const auto warnings = test::noseWarnings(result);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].line, 3);
  EXPECT_NE(warnings[0].message.find(fmt::format("up to {:.3f} mm normal to the surface, material left on this block's R5 arc", hand)),
            std::string::npos)
      << warnings[0].message;
}

TEST(UncompensatedNose, AnArcThrough45DegreesIsMissedByTheChamfersFigure) {
  // A quarter round R3 from the face to the diameter, G03 about (7, −3) from (7, 0) to
  // (10, −3): convex, through n = (1, 1)/√2, where the nose misses it by R(√2 − 1).
  const auto result = test::run(
      "T0101 G99 M03 S800\n"
      "G00 X0 Z2\n"
      "G01 Z0 F0.1\n"
      "X14\n"
      "G03 X20 Z-3 R3\n"
      "G01 Z-10\n"
      "G00 X40\n"
      "M30\n",
      withOffset(1.2, 3));
  const auto warnings = test::noseWarnings(result);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].line, 5);
  EXPECT_NE(warnings[0].message.find(fmt::format("up to {:.3f} mm", 1.2 * (std::sqrt(2.0) - 1))), std::string::npos)
      << warnings[0].message;
}

TEST(UncompensatedNose, DiametersAndFacesWithTip3AreRightAndNoRadiusSaysNothing) {
  constexpr std::string_view kSquare =
      "T0101 G99 M03 S800\n"
      "G00 X14 Z2\n"
      "G01 Z0 F0.1\n"
      "X20\n"
      "Z-10\n"
      "G00 X40\n"
      "M30\n";
  EXPECT_TRUE(test::noseWarnings(test::run(kSquare, withOffset(0.8, 3))).empty());
  EXPECT_TRUE(test::noseWarnings(test::run(kChamfer, withOffset(0.0, 3))).empty());
  // Tip 9 (the centre is the programmed point): every cut surface is R off, into the part.
  const auto centre = test::noseWarnings(test::run(kSquare, withOffset(0.8, 9)));
  ASSERT_EQ(centre.size(), 1u);
  EXPECT_NE(centre[0].message.find("up to 0.800 mm normal to the surface, cut into the part"), std::string::npos) << centre[0].message;
}

TEST(UncompensatedNose, WithoutAnOffsetRadiusTheToolsInsertIsTheNose) {
  // No offset entry (R 0): the insert of tool 1, R0.4 tip 3, still leaves 0.4(√2 − 1) on the
  // chamfer; an offset's R, when there is one, is the one named.
  InterpreterOptions options = test::defaultOptions();
  options.toolNoses[1] = ToolNose{0.4, 3};
  auto warnings = test::noseWarnings(test::run(kChamfer, options));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].message.find(fmt::format("R0.4 of tool 1's insert (its offset gives no R) (tip 3): the "
                                                 "finish is off the drawing by up to {:.3f} mm",
                                                 0.4 * (std::sqrt(2.0) - 1))),
            std::string::npos)
      << warnings[0].message;
  options.offsets[1] = ToolOffset{0, 0, 0.8, 3, 0, 0};
  warnings = test::noseWarnings(test::run(kChamfer, options));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].message.find("R0.8 of offset 1 (tip 3)"), std::string::npos) << warnings[0].message;
}

TEST(UncompensatedNose, OneWarningForTheRunAtItsWorstBlock) {
  // A 30° taper (0.293) on line 4, then a 45° chamfer (0.331) on line 6: one warning, line 6.
  const auto result = test::run(
      "T0101 G99 M03 S800\n"
      "G00 X14 Z2\n"
      "G01 Z0 F0.1\n"
      "X18 Z-3.46410162\n"
      "Z-10\n"
      "X24 Z-13\n"
      "Z-20\n"
      "G00 X40\n"
      "M30\n",
      withOffset(0.8, 3));
  const auto warnings = test::noseWarnings(result);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].line, 6);
}

TEST(UncompensatedNose, CompensatedContoursSayNothing) {
  const auto result = test::run(
      "T0101 G99 M03 S800\n"
      "G00 X14 Z2\n"
      "G42 G01 Z0 F0.1\n"
      "X20 Z-3\n"
      "Z-10\n"
      "G40 G00 X40\n"
      "M30\n",
      withOffset(0.8, 3));
  ASSERT_TRUE(result.ok()) << test::messageOf(result);
  EXPECT_TRUE(test::noseWarnings(result).empty());
}

// G71 roughs a contour and its last pass runs along it: under G40 that pass is as far off the
// drawing as any uncompensated contour, but it makes the surface only when no G70 finishes the
// contour afterwards. The shaft Φ14 → 45° chamfer (line 7) → Φ20, roughed by G71 with no
// allowance; then finished by G70 under G42, under G40, or not at all. Under both presets,
// with R0.8 tip 3 in the offset or, with no R there, R0.4 tip 3 on the tool's insert.
class RoughingUnderG40 : public testing::TestWithParam<const char*> {};

std::string roughedChamfer(const std::string& after) {
  return "T0101 G99 M03 S800\n"
         "G00 X42. Z2.\n"
         "G71 U1. R0.5\n"
         "G71 P10 Q20 U0. W0. F0.2\n"
         "N10 G00 X14.\n"
         "G01 Z0. F0.1\n"
         "X20. Z-3.\n"
         "Z-10.\n"
         "N20 X42.\n" +
         after + "G00 X60. Z5.\nM30\n";
}

TEST_P(RoughingUnderG40, WarnsOnlyWhenNoCompensatedG70FinishesTheContour) {
  struct Nose {
    InterpreterOptions options;
    double radiusMm;
  };
  InterpreterOptions ofOffset = test::under(GetParam());
  ofOffset.offsets[1] = ToolOffset{0, 0, 0.8, 3, 0, 0};
  InterpreterOptions ofInsert = test::under(GetParam());
  ofInsert.toolNoses[1] = ToolNose{0.4, 3};
  for (const Nose& nose : {Nose{ofOffset, 0.8}, Nose{ofInsert, 0.4}}) {
    SCOPED_TRACE(testing::Message() << "R" << nose.radiusMm);
    const std::string said = fmt::format("off the drawing by up to {:.3f} mm", nose.radiusMm * (std::sqrt(2.0) - 1));
    // G71 alone: its last pass made the chamfer, at line 7's block.
    auto result = test::run(roughedChamfer(""), nose.options);
    ASSERT_TRUE(result.ok()) << test::messageOf(result);
    auto warnings = test::noseWarnings(result);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].line, 7);
    EXPECT_NE(warnings[0].message.find(said), std::string::npos) << warnings[0].message;
    // Away, back under G42 and G70 finishes it compensated: the roughing made no surface, nothing to say.
    result = test::run(roughedChamfer("G00 X60. Z20.\nG42 G00 X42. Z2.\nG70 P10 Q20\nG40 "), nose.options);
    ASSERT_TRUE(result.ok()) << test::messageOf(result);
    EXPECT_TRUE(test::noseWarnings(result).empty()) << test::noseWarnings(result)[0].message;
    // G70 under G40: the finish itself is off, at the same block.
    result = test::run(roughedChamfer("G70 P10 Q20\n"), nose.options);
    ASSERT_TRUE(result.ok()) << test::messageOf(result);
    warnings = test::noseWarnings(result);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].line, 7);
    EXPECT_NE(warnings[0].message.find(said), std::string::npos) << warnings[0].message;
  }
}

// A G70 finishes the contour it names, not another: the chamfered contour roughed by G71 and
// left, a plain contour N30–N40 (diameters only, exact under tip 3) roughed and finished by G70
// under G42. The first contour's last pass still made its surface: warned at line 7.
TEST_P(RoughingUnderG40, AG70OfAnotherContourLeavesTheRoughingWarned) {
  InterpreterOptions options = test::under(GetParam());
  options.offsets[1] = ToolOffset{0, 0, 0.8, 3, 0, 0};
  const auto result = test::run(roughedChamfer("G71 P30 Q40 U0. W0. F0.2\n"
                                               "N30 G00 X10.\n"
                                               "G01 Z-20. F0.1\n"
                                               "N40 X42.\n"
                                               "G00 X60. Z20.\n"
                                               "G42 G00 X42. Z2.\n"
                                               "G70 P30 Q40\n"
                                               "G40 "),
                                options);
  ASSERT_TRUE(result.ok()) << test::messageOf(result);
  const auto warnings = test::noseWarnings(result);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].line, 7);
}

// G42 in the ns block: G71 roughs against the compensated contour, its last pass is the
// compensated path, and nothing is said even with no G70 after it (the tool's insert known too).
TEST_P(RoughingUnderG40, ACompensatedContourRoughedAloneSaysNothing) {
  InterpreterOptions options = test::under(GetParam());
  options.offsets[1] = ToolOffset{0, 0, 0.8, 3, 0, 0};
  options.toolNoses[1] = ToolNose{0.8, 3};
  std::string program = roughedChamfer("");
  program.replace(program.find("N10 G00 X14."), 12, "N10 G00 G42 X14.");
  const auto result = test::run(program, options);
  ASSERT_TRUE(result.ok()) << test::messageOf(result);
  EXPECT_TRUE(test::noseWarnings(result).empty()) << test::noseWarnings(result)[0].message;
}

INSTANTIATE_TEST_SUITE_P(Presets, RoughingUnderG40, testing::Values("gsk980tdi", "fanuc-0i-t"));

}  // namespace
}  // namespace lathesim::interp
