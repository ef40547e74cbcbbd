// Custom Macro B under the control's input parameters (lathe-cycles.md §10): a value a macro
// expression or a #variable gives is a length in mm (inch under G20) whichever way the control
// reads bare numbers, rounded to the preset's least input increment (Fanuc: "#1 = 123" holds
// 123.000; "the value of a variable is rounded to the least input increment of the address");
// a G65 argument written without a decimal point is counted in the least input increment of its
// address (Fanuc 16i/18i custom macro manual). Also how '/' and ',' read inside expressions next
// to the optional block skip and the comma words. The tool starts at X200 Z200 = (100, 200);
// every expected position is worked out by hand from those rules.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../test_support.hpp"
#include "interp/control/control_preset.hpp"

namespace lathesim::interp {
namespace {

using test::expectMoves;
using test::kFeed;
using test::kRapid;
using test::messageOf;
using test::under;
using test::warningsOf;

TEST(MacroInput, AVariablesValueIsMillimetresUnderEitherDecimalPointInput) {
  // #1 = 20 (no point: a macro constant is 20.000): X#1 is Φ20 (r 10), Z[#1/4] is Z5, U-#1
  // goes to Φ0 and W-[5] to Z0 — on the GSK (calculator input) and on the Fanuc (DPI = 0) alike.
  const std::string program = "#1 = 20\nG00 X#1 Z[#1/4]\nG00 U-#1 W-[5]\nM30\n";
  for (const char* preset : {"gsk980tdi", "fanuc-0i-t"}) {
    SCOPED_TRACE(preset);
    const auto result = interpret(program, "t.nc", under(preset));
    ASSERT_TRUE(result.ok()) << messageOf(result);
    expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 10, 5, 0, 0}, {kRapid, 10, 5, 0, 0, 0, 0}});
    EXPECT_TRUE(warningsOf(result).empty()) << warningsOf(result)[0].message;
  }
  // The same block written with numbers: the Fanuc counts X20 as 20 increments, 0.020 mm.
  const auto written = interpret("G00 X20 Z5\n", "t.nc", under("fanuc-0i-t"));
  ASSERT_TRUE(written.ok());
  expectMoves(written.toolpath.moves, {{kRapid, 100, 200, 0.01, 0.005, 0, 0}});
}

TEST(MacroInput, AVariableBesideABareLengthIsNoEvidenceOfMixedDecimalPoints) {
  // X#1 is a length under both readings, so only Z5 is a bare length: no mixed-point warning;
  // Z5 itself is 0.005 mm on the Fanuc.
  const auto result = interpret("#1 = 20\nG00 X#1 Z5\nM30\n", "t.nc", under("fanuc-0i-t"));
  ASSERT_TRUE(result.ok()) << messageOf(result);
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 10, 0.005, 0, 0}});
  EXPECT_TRUE(warningsOf(result).empty()) << warningsOf(result)[0].message;
}

TEST(MacroInput, ValuesAreRoundedToThePresetsLeastIncrement) {
  struct Case {
    const char* program;
    double leastIncrementMm;
    double radius;  // of X#1, worked by hand
  };
  // #1 = 12.34567 mm: IS-B 0.001 → X12.346 (r 6.173); IS-C 0.0001 → X12.3457 (r 6.17285).
  // Under G20 #1 = 1.23456 inch: IS-B 0.0001 inch → 1.2346 inch = 31.35884 mm (r 15.67942);
  // IS-C 0.00001 inch → 1.23456 inch = 31.357824 mm (r 15.678912).
  const std::vector<Case> cases{{"#1 = 12.34567\nG00 X#1 Z0.\n", 0.001, 6.173},
                                {"#1 = 12.34567\nG00 X#1 Z0.\n", 0.0001, 6.17285},
                                {"G20\n#1 = 1.23456\nG00 X#1 Z0.\n", 0.001, 15.67942},
                                {"G20\n#1 = 1.23456\nG00 X#1 Z0.\n", 0.0001, 15.678912}};
  for (const Case& c : cases) {
    SCOPED_TRACE(testing::Message() << c.program << " at " << c.leastIncrementMm);
    InterpreterOptions options = under("fanuc-0i-t");
    options.control.leastIncrementMm = c.leastIncrementMm;
    const auto result = interpret(c.program, "t.nc", options);
    ASSERT_TRUE(result.ok()) << messageOf(result);
    ASSERT_EQ(result.toolpath.moves.size(), 1u);
    EXPECT_NEAR(result.toolpath.moves[0].to.x(), c.radius, 1e-9);
  }
}

TEST(MacroInput, AG65ArgumentWithoutAPointCountsTheLeastIncrementOfItsAddress) {
  // O9000 moves to X#24 Z#26, then W-#1 and U#18. X20 (#24) and R5 (#18) have no point: on the
  // Fanuc (DPI = 0) 0.020 and 0.005 mm, on the GSK 20 and 5 mm; Z-10. is -10 on both; A20
  // (#1) is no length and passes 20 on both.
  //   Fanuc: (r 0.01, Z-10) → W-20 → Z-30 → U0.005 → r 0.0125
  //   GSK:   (r 10,   Z-10) → W-20 → Z-30 → U5     → r 12.5
  const std::string program =
      "G65 P9000 X20 Z-10. A20 R5\n"
      "M30\n"
      "O9000\n"
      "G00 X#24 Z#26\n"
      "W-#1\n"
      "U#18\n"
      "M99\n";
  const auto fanuc = interpret(program, "t.nc", under("fanuc-0i-t"));
  ASSERT_TRUE(fanuc.ok()) << messageOf(fanuc);
  expectMoves(fanuc.toolpath.moves, {{kRapid, 100, 200, 0.01, -10, 0, 0},
                                     {kRapid, 0.01, -10, 0.01, -30, 0, 0},
                                     {kRapid, 0.01, -30, 0.0125, -30, 0, 0}});
  const auto gsk = interpret(program, "t.nc", under("gsk980tdi"));
  ASSERT_TRUE(gsk.ok()) << messageOf(gsk);
  expectMoves(gsk.toolpath.moves, {{kRapid, 100, 200, 10, -10, 0, 0},
                                   {kRapid, 10, -10, 10, -30, 0, 0},
                                   {kRapid, 10, -30, 12.5, -30, 0, 0}});
  // The call mixes X20 with Z-10.: the classic crash, warned at X20 as for any block.
  for (const auto* result : {&fanuc, &gsk}) {
    const auto warnings = warningsOf(*result);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].line, 1);
    EXPECT_EQ(warnings[0].column, 11);
    EXPECT_EQ(warnings[0].message.rfind("X20 has no decimal point while Z-10. in the same block has one", 0), 0u)
        << warnings[0].message;
  }
}

TEST(MacroInput, AnExpressionsValueInAnArgumentIsPassedAsItIs) {
  // X[20] and X#2 are values, not digits written without a point: 20 mm on the Fanuc too.
  const auto result = interpret("#2 = 20\nG65 P9000 X[20] Z-#2\nM30\nO9000\nG00 X#24 Z#26\nM99\n", "t.nc",
                                under("fanuc-0i-t"));
  ASSERT_TRUE(result.ok()) << messageOf(result);
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 10, -20, 0, 0}});
}

TEST(MacroInput, ASlashDividesInsideAnExpressionAndSkipsBetweenWords) {
  // #1 = 10/4 = 2.5; X[#1*8] = X20 (r 10), Z[20/#1] = Z8; IF [#1/2 GT 1] holds (1.25), so
  // #2 = #1/5 = 0.5. The '/' after X30. stands between words: the optional block skip drops Z0.
  // when the switch is on, and the block is X30. Z0. when it is off.
  const std::string program =
      "#1 = 10/4\n"
      "G00 X[#1*8] Z[20/#1]\n"
      "IF [#1/2 GT 1] THEN #2 = #1/5\n"
      "G00 X30. /Z0.\n"
      "G00 X[#2*4] /W-[#1]\n"
      "M30\n";
  InterpreterOptions options = under("gsk980tdi");
  const auto skipped = interpret(program, "t.nc", options);
  ASSERT_TRUE(skipped.ok()) << messageOf(skipped);
  expectMoves(skipped.toolpath.moves, {{kRapid, 100, 200, 10, 8, 0, 0},
                                       {kRapid, 10, 8, 15, 8, 0, 0},
                                       {kRapid, 15, 8, 1, 8, 0, 0}});
  options.control.blockSkip = false;
  const auto run = interpret(program, "t.nc", options);
  ASSERT_TRUE(run.ok()) << messageOf(run);
  expectMoves(run.toolpath.moves, {{kRapid, 100, 200, 10, 8, 0, 0},
                                   {kRapid, 10, 8, 15, 0, 0, 0},
                                   {kRapid, 15, 0, 1, -2.5, 0, 0}});
}

TEST(MacroInput, ACommaPartsArgumentsInsideBracketsAndMakesACommaWordOutside) {
  // ATAN[1,SIN[90]] = ATAN[1,1] = 45: X#1 is Φ45 (r 22.5).
  const auto atan = interpret("#1 = ATAN[1,SIN[90]]\nG00 X#1 Z0\nM30\n", "t.nc", under("gsk980tdi"));
  ASSERT_TRUE(atan.ok()) << messageOf(atan);
  expectMoves(atan.toolpath.moves, {{kRapid, 100, 200, 22.5, 0, 0, 0}});
  // ,C#1 with #1 = 2 is the Fanuc chamfer ,C2.: 2 mm from the corner (r 15, Z0) along both cuts.
  const auto chamfer =
      interpret("#1 = 2\nG99 G00 X20. Z0.\nG01 X30. ,C#1 F0.1\nG01 Z-10.\n", "t.nc", under("fanuc-0i-t"));
  ASSERT_TRUE(chamfer.ok()) << messageOf(chamfer);
  expectMoves(chamfer.toolpath.moves, {{kRapid, 100, 200, 10, 0, 0, 0},
                                       {kFeed, 10, 0, 13, 0, 0.1, 0},
                                       {kFeed, 13, 0, 15, -2, 0.1, 0},
                                       {kFeed, 15, -2, 15, -10, 0.1, 0}});
}

}  // namespace
}  // namespace lathesim::interp
