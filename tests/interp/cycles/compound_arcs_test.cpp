// Arcs inside a compound cycle's contour reach the moves with their centres: the G-code
// side (contour blocks run through the executor) and the expansion (G71's semi-finishing
// pass, G70) meet here.

#include <gtest/gtest.h>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

// A = (X44, Z2). Contour: N10 G00 X20 → G01 Z-10 → G02 X30 Z-15 R5 → N20 G01 X44.
// The G02 goes from (r 10, z -10) to (r 15, z -15). Of the two centres 5 mm from both
// points, (r 15, z -10) and (r 10, z -15), the clockwise minor arc in the drawing view
// (Z right, X up) is about (r 15, z -10): seen from it the start lies straight down
// (−90°), the end straight left (180°), and clockwise turns −90° → −180°, a quarter
// circle. So the fillet is concave: its centre lies outside the material.
constexpr std::string_view kProgram =
    "G00 X44 Z2\n"
    "G71 U2 R0.5\n"
    "G71 P10 Q20 U0 W0 F0.2\n"
    "N10 G00 X20\n"
    "G01 Z-10\n"
    "G02 X30 Z-15 R5\n"
    "N20 G01 X44\n"
    "G70 P10 Q20\n"
    "M30\n";

TEST(CompoundCycleArcs, SemiFinishingPassAndG70CarryTheArcAndItsCentre) {
  const auto result = test::run(kProgram);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  std::vector<Move> arcs;
  for (const Move& m : result.toolpath.moves)
    if (isArc(m.kind)) arcs.push_back(m);
  // With no allowance (U0 W0) G71's semi-finishing pass runs on the contour itself, and
  // G70 runs it once more: the same quarter circle twice.
  ASSERT_EQ(arcs.size(), 2u);
  for (const Move& arc : arcs) {
    EXPECT_EQ(arc.kind, MoveKind::ArcCW);
    EXPECT_NEAR(arc.from.x(), 10, 1e-9);
    EXPECT_NEAR(arc.from.y(), -10, 1e-9);
    EXPECT_NEAR(arc.to.x(), 15, 1e-9);
    EXPECT_NEAR(arc.to.y(), -15, 1e-9);
    EXPECT_NEAR(arc.center.x(), 15, 1e-9);
    EXPECT_NEAR(arc.center.y(), -10, 1e-9);
    EXPECT_NEAR(arc.feed, 0.2, 1e-12);  // G71's F, modal into G70's contour
  }
  // Both are the G02 block's (line 6): the surface they cut is blamed on the block that drew
  // it, G71's pass along the contour as G70's (G71's own legs keep line 3).
  EXPECT_EQ(arcs[0].line, 6);
  EXPECT_EQ(arcs[0].block, 2);  // still the G71 block's move (its ordinal), for the block rows
  EXPECT_EQ(arcs[1].line, 6);
}

TEST(CompoundCycleArcs, FanucBWritesTheSameCompoundCycle) {
  // System B keeps G70–G76 and G00–G03; only the feed mode is G95 there.
  InterpreterOptions options = test::defaultOptions();
  options.dialect = Dialect::FanucB;
  const std::string programB = "G95\n" + std::string(kProgram);
  const auto b = test::run(programB, options);
  ASSERT_TRUE(b.ok()) << b.diagnostics[0].message;
  const auto a = test::run("G99\n" + std::string(kProgram));
  ASSERT_TRUE(a.ok());
  ASSERT_EQ(a.toolpath.moves.size(), b.toolpath.moves.size());
  for (std::size_t i = 0; i < a.toolpath.moves.size(); ++i) {
    EXPECT_EQ(a.toolpath.moves[i].from, b.toolpath.moves[i].from);
    EXPECT_EQ(a.toolpath.moves[i].to, b.toolpath.moves[i].to);
    EXPECT_EQ(a.toolpath.moves[i].kind, b.toolpath.moves[i].kind);
  }
}

}  // namespace
}  // namespace lathesim::interp
