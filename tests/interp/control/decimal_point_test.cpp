// Lengths written with and without a decimal point under each preset's decimal point input
// (lathe-cycles.md §10): the GSK980TDi reads a bare number in mm ("calculator" input), a Fanuc
// 0i-T with DPI = 0 counts least input increments (X20 = 0.020 mm at IS-B); [LII] words count
// increments under both. Every expected value is worked out by hand from those rules.

#include <gtest/gtest.h>

#include "../test_support.hpp"
#include "interp/control/control_preset.hpp"

namespace lathesim::interp {
namespace {

using test::expectMoves;
using test::kFeed;
using test::kRapid;
using test::under;
using test::warningsOf;

TEST(DecimalPoint, ABareLengthIsMillimetresOnTheGskAndIncrementsOnTheFanuc) {
  // X20 Z-10.: the GSK reads X20 as 20 mm (r 10); the Fanuc (DPI 0, IS-B) as 0.020 mm (r 0.01).
  const auto gsk = interpret("G00 X20 Z-10.\n", "t.nc", under("gsk980tdi"));
  ASSERT_TRUE(gsk.ok());
  expectMoves(gsk.toolpath.moves, {{kRapid, 100, 200, 10, -10, 0, 0}});
  const auto fanuc = interpret("G00 X20 Z-10.\n", "t.nc", under("fanuc-0i-t"));
  ASSERT_TRUE(fanuc.ok());
  expectMoves(fanuc.toolpath.moves, {{kRapid, 100, 200, 0.01, -10, 0, 0}});
  // IS-C: 20 × 0.0001 mm = 0.002 mm of diameter.
  InterpreterOptions isC = under("fanuc-0i-t");
  isC.control.leastIncrementMm = 0.0001;
  expectMoves(interpret("G00 X20 Z-10.\n", "t.nc", isC).toolpath.moves, {{kRapid, 100, 200, 0.001, -10, 0, 0}});
}

// The school trainers' control reads a bare number in mm, as their programs are written
// (G00 X26 Z2 beside M06 T0101), though it reads Fanuc's other words.
TEST(DecimalPoint, TheTrainersControlReadsABareLengthInMillimetres) {
  const auto denford = interpret("G00 X20 Z-10\n", "t.nc", under("denford"));
  ASSERT_TRUE(denford.ok());
  expectMoves(denford.toolpath.moves, {{kRapid, 100, 200, 10, -10, 0, 0}});
}

TEST(DecimalPoint, EveryReadingOfABareNumber) {
  // G00 X1234 W-567 from (r 100, Z200), under each decimal point input, increment system and unit.
  // By hand: calculator reads 1234 mm (inch); increments count 0.001 mm at IS-B, 0.0001 mm at
  // IS-C, a tenth of that in inch (0.0001 / 0.00001 inch), 25.4 mm to the inch. X is a diameter.
  struct Case {
    DecimalPointInput input;
    double leastIncrementMm;
    bool inch;
    double radiusMm, dzMm;
  };
  const Case cases[] = {
      {DecimalPointInput::Calculator, 0.001, false, 617, -567},
      {DecimalPointInput::Calculator, 0.0001, false, 617, -567},
      {DecimalPointInput::Calculator, 0.001, true, 15671.8, -14401.8},
      {DecimalPointInput::LeastIncrements, 0.001, false, 0.617, -0.567},
      {DecimalPointInput::LeastIncrements, 0.0001, false, 0.0617, -0.0567},
      {DecimalPointInput::LeastIncrements, 0.001, true, 1.56718, -1.44018},      // 0.1234 / 0.0567 inch
      {DecimalPointInput::LeastIncrements, 0.0001, true, 0.156718, -0.144018},  // 0.01234 / 0.00567 inch
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(testing::Message() << "increments " << (c.input == DecimalPointInput::LeastIncrements) << ", "
                                    << c.leastIncrementMm << " mm, inch " << c.inch);
    InterpreterOptions options = test::defaultOptions();
    options.control.decimalPointInput = c.input;
    options.control.leastIncrementMm = c.leastIncrementMm;
    const auto result = interpret(std::string(c.inch ? "G20 " : "") + "G00 X1234 W-567\n", "t.nc", options);
    ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
    ASSERT_EQ(result.toolpath.moves.size(), 1u);
    EXPECT_NEAR(result.toolpath.moves[0].to.x(), c.radiusMm, 1e-9);
    EXPECT_NEAR(result.toolpath.moves[0].to.y(), 200 + c.dzMm, 1e-9);
    // With a point the word is a length as written, under every reading.
    const auto pointed = interpret(std::string(c.inch ? "G20 " : "") + "G00 X12.34 W-5.67\n", "t.nc", options);
    ASSERT_TRUE(pointed.ok());
    EXPECT_NEAR(pointed.toolpath.moves[0].to.x(), (c.inch ? 25.4 : 1.0) * 6.17, 1e-9);
    EXPECT_NEAR(pointed.toolpath.moves[0].to.y(), 200 - (c.inch ? 25.4 : 1.0) * 5.67, 1e-9);
  }
}

TEST(DecimalPoint, AMixedBlockIsWarnedWithBothReadings) {
  const auto gsk = interpret("G00 X20 Z-10.\n", "t.nc", under("gsk980tdi"));
  ASSERT_EQ(warningsOf(gsk).size(), 1u);
  EXPECT_EQ(warningsOf(gsk)[0].line, 1);
  EXPECT_EQ(warningsOf(gsk)[0].column, 5);
  EXPECT_EQ(warningsOf(gsk)[0].message,
            "X20 has no decimal point while Z-10. in the same block has one: this control reads X20 as 20 mm "
            "(decimal_point_input = \"calculator\"), a control that counts least increments (Fanuc DPI = 0) reads "
            "it as 0.02 mm; a program that mixes the two forms crashes on one of them: write every length with a "
            "decimal point");
  const auto fanuc = interpret("G00 X20 Z-10.\n", "t.nc", under("fanuc-0i-t"));
  ASSERT_EQ(warningsOf(fanuc).size(), 1u);
  EXPECT_EQ(warningsOf(fanuc)[0].message,
            "X20 has no decimal point while Z-10. in the same block has one: this control reads X20 as 0.02 mm "
            "(decimal_point_input = \"increments\"), a control that takes it in mm (calculator input) reads it "
            "as 20 mm; a program that mixes the two forms crashes on one of them: write every length with a "
            "decimal point");
}

TEST(DecimalPoint, AProgramThatMixesAcrossBlocksIsWarnedOnceAtTheFirstBareLength) {
  // Inch: Z-1 reads 1 inch (calculator) or 0.0001 inch (increments, a tenth of IS-B's 0.001).
  const auto result = interpret("G20 G99\nG00 X2. Z.1\nG01 Z-1 F.01\nG01 X3 Z-2\n", "t.nc", under("gsk980tdi"));
  ASSERT_TRUE(result.ok());
  const auto warnings = warningsOf(result);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].line, 3);
  EXPECT_EQ(warnings[0].column, 5);
  EXPECT_EQ(warnings[0].message.rfind("Z-1 has no decimal point while X2. on line 2 has one: this control reads Z-1 "
                                      "as -1 inch (decimal_point_input = \"calculator\"), a control that counts "
                                      "least increments (Fanuc DPI = 0) reads it as -0.0001 inch;",
                                      0),
            0u)
      << warnings[0].message;
  // All with a point, or all without: nothing to warn.
  EXPECT_TRUE(warningsOf(interpret("G99 G00 X20. Z2.\nG01 Z-10. F.2\n", "t.nc", under("gsk980tdi"))).empty());
  EXPECT_TRUE(warningsOf(interpret("G99 G00 X20 Z2\nG01 Z-10 F.2\n", "t.nc", under("gsk980tdi"))).empty());
  // X0 reads the same either way: no evidence of a mix.
  EXPECT_TRUE(warningsOf(interpret("G99 G00 X0 Z2.\nG01 Z-10. F.2\n", "t.nc", under("gsk980tdi"))).empty());
}

TEST(DecimalPoint, CycleLengthsCountIncrementsTooInAnInchShopProgram) {
  // fanuc-0i-t, G20, IS-B: a least increment is 0.0001 inch. G71 U630 R500 is Δd = 0.0630 inch
  // = 1.6002 mm and e = 0.0500 inch = 1.27 mm. From A = X2. Z.1 = (r 25.4, Z2.54) the contour
  // goes to X1. (r 12.7), then Z-1. (Z-25.4): 12.7 mm to cut in levels of 1.6002 mm, the last
  // at 7 × 1.6002 = 11.2014 (8 × 1.6002 would pass B′). Under calculator input U630 would be
  // 630 inch: no level at all.
  const std::string_view program =
      "G20 G99\nG00 X2. Z.1\nG71 U630 R500\nG71 P10 Q20 U0 W0 F.01\nN10 G01 X1.\nN20 Z-1.\n";
  const auto result = interpret(program, "t.nc", under("fanuc-0i-t"));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const auto& moves = result.toolpath.moves;
  ASSERT_GE(moves.size(), 6u);
  // Level 1: infeed Δd at F (the ns block is G01), cut to C′'s Z, retract e at 45° (rapid on
  // the Fanuc), rapid back to Z2.54, infeed Δd + e to level 2.
  expectMoves({moves.begin() + 1, moves.begin() + 6},
              {{kFeed, 25.4, 2.54, 23.7998, 2.54, 0.254, 2},
               {kFeed, 23.7998, 2.54, 23.7998, -25.4, 0.254, 3},
               {kRapid, 23.7998, -25.4, 25.0698, -24.13, 0, 4},
               {kRapid, 25.0698, -24.13, 25.0698, 2.54, 0, 5},
               {kFeed, 25.0698, 2.54, 22.1996, 2.54, 0.254, 6}});
  int levels = 0;
  for (const Move& m : moves) levels += m.cycleStep == 3 ? 1 : 0;
  EXPECT_EQ(levels, 7);
  InterpreterOptions calculator = under("fanuc-0i-t");
  calculator.control.decimalPointInput = DecimalPointInput::Calculator;
  const auto asInches = interpret(program, "t.nc", calculator);
  ASSERT_TRUE(asInches.ok());
  for (const Move& m : asInches.toolpath.moves) EXPECT_NE(m.cycleStep, 3);
}

TEST(DecimalPoint, G75RetractCountsIncrementsToo) {
  // fanuc-0i-t, G20: G75 R20 is e = 0.0020 inch = 0.0508 mm; P1000 = 0.1 inch = 2.54 mm, a radius
  // on the Fanuc. From X1.2 Z-.5 (r 15.24, Z-12.7) to X.8 (r 10.16): a peck of 2.54 to r 12.7,
  // back e to 12.7508, then the last peck to r 10.16, and out to r 15.24.
  const auto result = interpret("G20 G99\nG00 X1.2 Z-.5\nG75 R20\nG75 X.8 P1000 F.004\n", "t.nc", under("fanuc-0i-t"));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const auto& moves = result.toolpath.moves;
  expectMoves({moves.begin() + 1, moves.end()}, {{kFeed, 15.24, -12.7, 12.7, -12.7, 0.1016, 1},
                                                {kRapid, 12.7, -12.7, 12.7508, -12.7, 0, 2},
                                                {kFeed, 12.7508, -12.7, 10.16, -12.7, 0.1016, 1},
                                                {kRapid, 10.16, -12.7, 15.24, -12.7, 0, 4}});
}

TEST(DecimalPoint, IncrementWordsFollowTheLeastIncrementAndGsk1827) {
  // G74 Q6000 pecks 6 mm at IS-B, 0.6 mm at IS-C; with increment_words = "calculator" (GSK
  // No.182#7 = 1) Q6. and Q6 are both 6 mm. From X0 Z2 to Z-4: IS-C pecks 0.6 ten times.
  InterpreterOptions isC = test::defaultOptions();
  isC.control.leastIncrementMm = 0.0001;
  const auto fine = interpret("G00 X0 Z2\nG74 X0 Z-4 Q6000 F0.1\n", "t.nc", isC);
  ASSERT_TRUE(fine.ok()) << fine.diagnostics[0].message;
  int pecks = 0;
  for (const Move& m : fine.toolpath.moves) pecks += m.cycleStep == 1 ? 1 : 0;
  EXPECT_EQ(pecks, 10);
  InterpreterOptions millimetres = test::defaultOptions();
  millimetres.control.incrementWordInput = IncrementWordInput::Calculator;
  const auto coarse = interpret("G00 X0 Z2\nG74 X0 Z-4 Q6 F0.1\n", "t.nc", millimetres);
  ASSERT_TRUE(coarse.ok());
  expectMoves({coarse.toolpath.moves.begin() + 1, coarse.toolpath.moves.end()},
              {{kFeed, 0, 2, 0, -4, 0.1, 1}, {kRapid, 0, -4, 0, 2, 0, 4}});
}

TEST(DecimalPoint, ABareDwellTimeCountsIncrementsUnderDpi0) {
  // G04 X1500: 1.5 s on the Fanuc (0.001 s increments at IS-B), 1500 s on the GSK. P is ms on both.
  const auto fanuc = interpret("G04 X1500\nG04 X2.5\nG04 P300\n", "t.nc", under("fanuc-0i-t"));
  ASSERT_TRUE(fanuc.ok());
  ASSERT_EQ(fanuc.toolpath.moves.size(), 3u);
  EXPECT_DOUBLE_EQ(fanuc.toolpath.moves[0].dwellS, 1.5);
  EXPECT_DOUBLE_EQ(fanuc.toolpath.moves[1].dwellS, 2.5);
  EXPECT_DOUBLE_EQ(fanuc.toolpath.moves[2].dwellS, 0.3);
  const auto gsk = interpret("G04 X1500\n", "t.nc", under("gsk980tdi"));
  EXPECT_DOUBLE_EQ(gsk.toolpath.moves[0].dwellS, 1500);
}

}  // namespace
}  // namespace lathesim::interp
