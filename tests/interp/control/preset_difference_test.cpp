// Where the two presets read one program differently (lathe-cycles.md §10), each case worked
// by hand under both: the feed mode at power-on, G72's retract and its first-block W in an inch
// program, G73 with d = 1, and G74's X-axis words. Rapids are straight here (one move per
// rapid); the dog-leg has its own tests (motion/rapid_path_test.cpp).

#include <gtest/gtest.h>

#include "../test_support.hpp"
#include "interp/control/control_preset.hpp"
#include "interp/motion/cycle_time.hpp"

namespace lathesim::interp {
namespace {

using test::expectMoves;
using test::kFeed;
using test::kRapid;
using test::under;

TEST(PresetDifference, TheFeedModeAtPowerOn) {
  // No G98/G99 in the program: F0.2 is 0.2 mm/min on the GSK (G98 at power-on, §3.26), 0.2 mm/rev
  // on the Fanuc (G99, 3402#4 FPM = 0 ⚠). The 12 mm cut from Z2 to Z-10 at S500: 12 / 0.2 = 60 min
  // = 3600 s on the GSK; 12 / (0.2 · 500) = 0.12 min = 7.2 s on the Fanuc.
  const std::string_view program = "M03 S500\nG00 X40. Z2.\nG01 Z-10. F0.2\n";
  for (const auto& [preset, mode, seconds] :
       {std::tuple{"gsk980tdi", FeedMode::PerMinute, 3600.0}, {"fanuc-0i-t", FeedMode::PerRevolution, 7.2}}) {
    SCOPED_TRACE(preset);
    auto result = interpret(program, "t.nc", under(preset));
    ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
    ASSERT_EQ(result.toolpath.moves.size(), 2u);
    const Move& cut = result.toolpath.moves[1];
    EXPECT_EQ(cut.feedMode, mode);
    (void)assignMoveTimes(result.toolpath, MachineLimits{});
    EXPECT_NEAR(result.toolpath.moves[1].timeS, seconds, 1e-9);
  }
}

TEST(PresetDifference, G72InAnInchProgramCountsIncrementsAndRetractsAtRapidOnTheFanuc) {
  // fanuc-0i-t, G20, DPI 0, IS-B (0.0001 inch): G72 W1250 R500 is Δd 0.1250 inch = 3.175 mm (in
  // Z) and e 0.0500 inch = 1.27 mm; F.008 is 0.2032 mm/rev. A = X1. Z.1 = (r 12.7, Z2.54); the
  // contour: N10 rapid to Z-.5 (Z-12.7), N20 a face to the axis, so B′ = (12.7, -12.7). Levels at
  // Z 2.54 − 3.175 = -0.635, -3.81, -6.985, -10.16 (a fifth at -13.335 would pass B′), each cut
  // along X to r 0, the 45° retract of e at rapid (the Fanuc's), rapid back to r 12.7, infeed
  // Δd + e; then to B′, the semi-finishing face, and the rapid back to A.
  const std::string_view program =
      "G20\nG00 X1. Z.1\nG72 W1250 R500\nG72 P10 Q20 U0 W0 F.008\nN10 G00 Z-.5\nN20 G01 X0.\n";
  const auto result = interpret(program, "t.nc", under("fanuc-0i-t"));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const double f = 0.2032;
  std::vector<test::Expected> expected{{kRapid, 100, 200, 12.7, 2.54, 0, 0}};
  double from = 2.54;
  for (const double level : {-0.635, -3.81, -6.985, -10.16}) {
    expected.push_back({kRapid, 12.7, from, 12.7, level, 0, from == 2.54 ? 2 : 6});
    expected.push_back({kFeed, 12.7, level, 0, level, f, 3});
    expected.push_back({kRapid, 0, level, 1.27, level + 1.27, 0, 4});
    expected.push_back({kRapid, 1.27, level + 1.27, 12.7, level + 1.27, 0, 5});
    from = level + 1.27;
  }
  expected.push_back({kRapid, 12.7, from, 12.7, -12.7, 0, 6});
  expected.push_back({kFeed, 12.7, -12.7, 0, -12.7, f, 7});
  expected.push_back({kRapid, 0, -12.7, 12.7, 2.54, 0, 8});
  expectMoves(result.toolpath.moves, expected);
  // The GSK reads W1250 as 1250 inch: one infeed passes B′ at once, no level is cut.
  const auto gsk = interpret(program, "t.nc", under("gsk980tdi"));
  ASSERT_TRUE(gsk.ok()) << gsk.diagnostics[0].message;
  for (const Move& m : gsk.toolpath.moves) EXPECT_NE(m.cycleStep, 3);
}

TEST(PresetDifference, G73WithOnePass) {
  // G73 U2. R1 (Δi 2 of radius, d = 1) from A = (30, 2) to the contour N10 G01 X40. (r 20): the
  // GSK cuts d = 1 as two passes (§3.23.3), the first shifted by Δi to (32, 2) → (22, 2), the
  // second at no shift (30, 2) → (20, 2); the Fanuc preset cuts one pass at the allowance alone.
  const std::string_view program = "G00 X60. Z2.\nG73 U2. R1\nG73 P10 Q10 F0.2\nN10 G01 X40.\n";
  const auto gsk = interpret(program, "t.nc", under("gsk980tdi"));
  ASSERT_TRUE(gsk.ok()) << gsk.diagnostics[0].message;
  expectMoves(gsk.toolpath.moves, {{kRapid, 100, 200, 30, 2, 0, 0},
                                   {kRapid, 30, 2, 32, 2, 0, 1},
                                   {kFeed, 32, 2, 22, 2, 0.2, 2},
                                   {kRapid, 22, 2, 30, 2, 0, 1},
                                   {kFeed, 30, 2, 20, 2, 0.2, 2},
                                   {kRapid, 20, 2, 30, 2, 0, 4}});
  const auto fanuc = interpret(program, "t.nc", under("fanuc-0i-t"));
  ASSERT_TRUE(fanuc.ok()) << fanuc.diagnostics[0].message;
  expectMoves(fanuc.toolpath.moves, {{kRapid, 100, 200, 30, 2, 0, 0},
                                     {kFeed, 30, 2, 20, 2, 0.2, 2},
                                     {kRapid, 20, 2, 30, 2, 0, 4}});
}

TEST(PresetDifference, G74XWordsAreDiametersOnTheGskAndRadiiOnTheFanuc) {
  // A = (15, 1) to X20. Z-4. (r 10), Q5000 = one 5 mm peck per plunge, R0.5 the back-off. P4000
  // and R2000 are 4 and 2 mm: on the GSK diameters (plunges 2 apart in radius at 15, 13, 11, then
  // 10; relief 1 toward +X, away from the end); on the Fanuc radii (plunges at 15, 11, then 10,
  // clamped; relief 2). After each plunge: relief, back to Z1, then Δd + Δi to the next.
  const std::string_view program = "G00 X30. Z1.\nG74 R0.5\nG74 X20. Z-4. P4000 Q5000 R2000 F0.1\n";
  for (const auto& [preset, plunges, relief] :
       {std::tuple{"gsk980tdi", std::vector<double>{15, 13, 11, 10}, 1.0},
        {"fanuc-0i-t", std::vector<double>{15, 11, 10}, 2.0}}) {
    SCOPED_TRACE(preset);
    const auto result = interpret(program, "t.nc", under(preset));
    ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
    std::vector<test::Expected> expected{{kRapid, 100, 200, 15, 1, 0, 0}};
    for (std::size_t i = 0; i < plunges.size(); ++i) {
      const double r = plunges[i];
      expected.push_back({kFeed, r, 1, r, -4, 0.1, 1});
      expected.push_back({kRapid, r, -4, r + relief, -4, 0, 3});
      expected.push_back({kRapid, r + relief, -4, r + relief, 1, 0, 4});
      if (i + 1 < plunges.size()) expected.push_back({kRapid, r + relief, 1, plunges[i + 1], 1, 0, 5});
    }
    expected.push_back({kRapid, 10 + relief, 1, 15, 1, 0, 6});
    expectMoves(result.toolpath.moves, expected);
  }
}

}  // namespace
}  // namespace lathesim::interp
