// Dialects: one part written for three controls gives one toolpath, and each dialect's
// own codes mean what its control means by them.

#include "interp/control/dialect.hpp"

#include <gtest/gtest.h>

#include "interp/control/gcode_table.hpp"
#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;

InterpretResult runIn(Dialect dialect, std::string_view program) {
  InterpreterOptions options = test::defaultOptions();
  options.dialect = dialect;
  return test::run(program, options);
}

void expectSameToolpath(const InterpretResult& a, const InterpretResult& b) {
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_EQ(a.toolpath.moves.size(), b.toolpath.moves.size());
  for (std::size_t i = 0; i < a.toolpath.moves.size(); ++i) {
    SCOPED_TRACE(testing::Message() << "move " << i);
    const Move& m = a.toolpath.moves[i];
    const Move& n = b.toolpath.moves[i];
    EXPECT_EQ(m.kind, n.kind);
    EXPECT_EQ(m.from, n.from);
    EXPECT_EQ(m.to, n.to);
    EXPECT_EQ(m.feed, n.feed);
    EXPECT_EQ(m.feedMode, n.feedMode);
    EXPECT_EQ(m.line, n.line);
    EXPECT_EQ(m.cycleStep, n.cycleStep);
  }
}

// Seed 000's face-and-taper part with an axial pass added, line for line in each dialect:
// the feed mode, the coordinate setting, both single cycles (straight and taper) and
// incremental words. The HNC taper word is I for the axial cycle and K for the face cycle.
constexpr std::string_view kFanucA =
    "G50 X200 Z200\n"
    "G98 G00 X130 Z5 M3 S500\n"
    "G94 X0 Z0 F200\n"
    "X120 Z-110 F300\n"
    "G00 X120 Z0\n"
    "G94 X108 Z-30 R-10\n"
    "X96 R-20\n"
    "G00 X130 Z2\n"
    "G90 X110 Z-40 R-5\n"
    "U-30 W-10\n"
    "G99 G01 U-10 W-2 F0.2\n"
    "M30\n";
constexpr std::string_view kFanucB =
    "G92 X200 Z200\n"
    "G94 G00 X130 Z5 M3 S500\n"
    "G79 X0 Z0 F200\n"
    "X120 Z-110 F300\n"
    "G00 X120 Z0\n"
    "G79 X108 Z-30 R-10\n"
    "X96 R-20\n"
    "G00 X130 Z2\n"
    "G77 X110 Z-40 R-5\n"
    "G91 X-30 Z-10\n"
    "G95 G01 X-10 Z-2 F0.2\n"
    "M30\n";
constexpr std::string_view kHnc =
    "G92 X200 Z200\n"
    "G94 G00 X130 Z5 M3 S500\n"
    "G81 X0 Z0 F200\n"
    "X120 Z-110 F300\n"
    "G00 X120 Z0\n"
    "G81 X108 Z-30 K-10\n"
    "X96 K-20\n"
    "G00 X130 Z2\n"
    "G80 X110 Z-40 I-5\n"
    "G91 X-30 Z-10\n"
    "G95 G01 X-10 Z-2 F0.2\n"
    "M30\n";

TEST(Dialect, OnePartWrittenForThreeControlsGivesOneToolpath) {
  const auto a = runIn(Dialect::FanucA, kFanucA);
  ASSERT_TRUE(a.ok()) << a.diagnostics[0].message;
  // The hand expansion of the system-A program's last three blocks (radius, Z): G90 from
  // A = (65, 2) to C = (55, -40) with R-5 starts its cut at X_C + 2R = Φ100 → r 50; the
  // repeat U-30 W-10 ends at (65-15, 2-10) = (50, -8); G01 U-10 W-2 from A goes to (60, 0).
  const auto& moves = a.toolpath.moves;
  ASSERT_GE(moves.size(), 9u);
  const Move& lastCut = moves.back();
  EXPECT_EQ(lastCut.kind, MoveKind::Feed);
  EXPECT_EQ(lastCut.from, RZ(65, 2));
  EXPECT_EQ(lastCut.to, RZ(60, 0));
  EXPECT_EQ(lastCut.feedMode, FeedMode::PerRevolution);
  EXPECT_EQ(moves[moves.size() - 9].to, RZ(50, 2));  // G90 step 1: rapid to the cut's start
  EXPECT_EQ(moves[moves.size() - 8].to, RZ(55, -40));
  EXPECT_EQ(moves[moves.size() - 4].to, RZ(50, -8));  // the repeat's cut ends at C

  expectSameToolpath(a, runIn(Dialect::FanucB, kFanucB));
  expectSameToolpath(a, runIn(Dialect::Hnc, kHnc));
}

TEST(Dialect, G91MakesXAndZIncrementalUntilG90) {
  const auto result = runIn(Dialect::FanucB, "G91 G00 X-20 Z-50\nX-10\nG90 X100\n");
  ASSERT_TRUE(result.ok());
  test::expectMoves(result.toolpath.moves, {{test::kRapid, 100, 200, 90, 150, 0, 0},
                                            {test::kRapid, 90, 150, 85, 150, 0, 0},
                                            {test::kRapid, 85, 150, 50, 150, 0, 0}});
}

TEST(Dialect, CoordinateSettingStaysAbsoluteUnderG91) {
  // G92 X50 Z10 declares where the tool is (setup r100 Z200), even in incremental mode; the
  // move after it is then 10 mm back in Z from there: setup (100, 190).
  const auto result = runIn(Dialect::FanucB, "G91 G92 X50 Z10\nG00 Z-10\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  test::expectMoves(result.toolpath.moves, {{test::kRapid, 100, 200, 100, 190, 0, 0}});
}

TEST(Dialect, G91WithBothXAndUIsTwoWordsForOneAxis) {
  expectError(runIn(Dialect::FanucB, "G91 G00 X-20 U-10\n"), 1, 14, "both give the X axis");
}

TEST(Dialect, CodesOfAnotherDialectAreUnknownAndTheErrorNamesTheDialect) {
  expectError(runIn(Dialect::FanucB, "G50 X20 Z0\n"), 1, 1, "unknown G code G50");
  expectError(runIn(Dialect::FanucB, "G50 X20 Z0\n"), 1, 1, "(dialect fanuc-b)");
  expectError(runIn(Dialect::FanucA, "G91 X20\n"), 1, 1, "unknown G code G91");
  expectError(runIn(Dialect::Hnc, "G79 X20 Z0 F1\n"), 1, 1, "unknown G code G79");
}

TEST(Dialect, MessagesNameTheCycleAsTheProgramWroteIt) {
  expectError(runIn(Dialect::FanucB, "G77 X20 F0.2\n"), 1, 1, "G77 needs X(U) and Z(W)");
  expectError(runIn(Dialect::Hnc, "G81 Z-2 F0.2\n"), 1, 1, "G81 needs X(U) and Z(W)");
}

TEST(Dialect, HncCompoundCyclesAreRefusedRatherThanMisread) {
  // HNC's G71 is a one-block cycle with other words (U R P Q X Z F): reading it as Fanuc's
  // two-block G71 would make a different part.
  expectError(runIn(Dialect::Hnc, "G71 U1 R0.5 P10 Q20 X0.5 Z0.1 F0.2\n"), 1, 1,
              "G71 (OD/ID roughing cycle in hnc's one-block form) is not supported");
}

TEST(Dialect, NamesRoundTrip) {
  for (Dialect d : {Dialect::FanucA, Dialect::FanucB, Dialect::Hnc}) EXPECT_EQ(dialectNamed(dialectName(d)), d);
  EXPECT_FALSE(dialectNamed("fanuc-c").has_value());
  EXPECT_EQ(writtenGCode(94, GGroup::Motion, Dialect::FanucB), "G79");
  EXPECT_EQ(writtenGCode(98, GGroup::FeedMode, Dialect::Hnc), "G94");
  EXPECT_EQ(writtenGCode(90, GGroup::Motion, Dialect::FanucA), "G90");
}

}  // namespace
}  // namespace lathesim::interp
