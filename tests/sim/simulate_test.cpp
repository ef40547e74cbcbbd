#include "sim/simulate.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "interp/interpreter.hpp"
#include "test_moves.hpp"

namespace lathesim::sim {
namespace {

interp::Move move(interp::MoveKind kind, RZ from, RZ to, int block, int line) {
  return test::turningMove(kind, from, to, block, line);
}

TEST(Simulate, RapidIntoTheBarIsACollisionOnItsLine) {
  Stock stock({40.0, 30.0, 0.0}, 0.25);
  interp::Toolpath path;
  path.blockCount = 2;
  // A rapid straight down to r = 15 at Z-5 ploughs a 5 mm deep groove; then a feed
  // along the surface that removes nothing.
  path.moves.push_back(move(interp::MoveKind::Rapid, {30, -5}, {15, -5}, 0, 3));
  path.moves.push_back(move(interp::MoveKind::Rapid, {15, -5}, {30, -5}, 1, 4));
  const SimulationResult result = simulate(path, test::squareTool(4), stock);
  ASSERT_EQ(result.collisions.size(), 1u);
  EXPECT_EQ(result.collisions[0].line, 3);
  EXPECT_EQ(result.collisions[0].kind, "rapid_into_stock");
  // The square's trace: a ring r 15..20, Z -5..-1 (4 mm wide).
  const double groove = M_PI * (20.0 * 20.0 - 15.0 * 15.0) * 4.0;
  EXPECT_NEAR(result.collisions[0].volumeMm3, groove, 0.1 * 0.25 * (2 * M_PI * 15 * 4 + 2 * M_PI * (400 - 225)));
  ASSERT_EQ(result.blocks.size(), 2u);
  EXPECT_NEAR(result.blocks[1].removedMm3, 0.0, 1.0);
}

TEST(Simulate, RapidGrazingTheSurfaceIsNoCollision) {
  Stock stock({40.0, 30.0, 0.0}, 0.25);
  interp::Toolpath path;
  path.blockCount = 1;
  // Tool tip running along the bar's own surface (r = 20): nothing to remove.
  path.moves.push_back(move(interp::MoveKind::Rapid, {20, 5}, {20, -25}, 0, 1));
  const SimulationResult result = simulate(path, test::squareTool(4), stock);
  EXPECT_TRUE(result.collisions.empty()) << "removed " << result.collisions[0].volumeMm3;
}

TEST(Simulate, FeedsOfOneBlockAreMeasuredTogether) {
  Stock stock({40.0, 30.0, 0.0}, 0.25);
  interp::Toolpath path;
  path.blockCount = 1;
  // A G94-like face cut: plunge to the axis at Z-2, retract along Z: removes a 2 mm slice.
  path.moves.push_back(move(interp::MoveKind::Feed, {25, -2}, {0, -2}, 0, 7));
  path.moves.push_back(move(interp::MoveKind::Feed, {0, -2}, {0, 5}, 0, 7));
  const SimulationResult result = simulate(path, test::squareTool(4), stock);
  ASSERT_EQ(result.blocks.size(), 1u);
  EXPECT_EQ(result.blocks[0].line, 7);
  EXPECT_NEAR(result.blocks[0].removedMm3, M_PI * 400 * 2, 0.1 * 0.25 * (2 * M_PI * 400 + 2 * M_PI * 20 * 2));
  EXPECT_NEAR(stock.volumeMm3(), M_PI * 400 * 28, 0.1 * 0.25 * (4 * M_PI * 400 + 2 * M_PI * 20 * 30));
}

// G84 sweeps the tap as the mounted tool's outline revolved, like a drill: a tap that fits the
// drilled hole removes nothing more, a wider one cuts. Bar Φ40×30, face at Z0; a flat drill of
// radius 5 (T1) drills Z0..−20 by G81: π·5²·20 = 500π mm³. A tap of radius 5 (T2) then removes
// nothing; a tap of radius 6 (T3) the ring π(6² − 5²)·20 = 220π mm³, down and not again back out.
TEST(Simulate, ATapCutsOnlyWhereItIsWiderThanTheHole) {
  const auto flat = [](double radius) {
    const std::vector<RZ> outline{{0, 0}, {radius, 0}, {radius, 40}, {0, 40}};
    return *ConvexPolygon::fromOutline(outline).polygon;
  };
  ToolOutlines tools;
  tools.emplace(1, flat(5));
  tools.emplace(2, flat(5));
  tools.emplace(3, flat(6));
  interp::InterpreterOptions options;
  options.startPosition = RZ(50, 50);
  options.toolNumbers = {1, 2, 3};
  const double h = 0.25;
  const double tolerance = 0.1 * h * (2 * M_PI * 6 * 20 + M_PI * 36);
  for (const int tap : {2, 3}) {
    SCOPED_TRACE(tap);
    const auto program = interp::interpret("G99 G97 S300 M03\nT0101\nG00 X0 Z5\nG81 Z-20 R2 F0.1\nG80\nT0" +
                                               std::to_string(tap) + "00\nG84 Z-20 R2 F1.5\n",
                                           "tap.nc", options);
    ASSERT_TRUE(program.ok()) << program.diagnostics[0].message;
    Stock stock({40.0, 30.0, 0.0}, h);
    const SimulationResult result = simulate(program.toolpath, tools, stock);
    EXPECT_TRUE(result.collisions.empty());
    double drilled = 0, tapped = 0;
    for (const auto& block : result.blocks) (block.line == 4 ? drilled : tapped) += block.removedMm3;
    EXPECT_NEAR(drilled, 500 * M_PI, tolerance);
    EXPECT_NEAR(tapped, tap == 2 ? 0.0 : 220 * M_PI, tolerance);
  }
}

}  // namespace
}  // namespace lathesim::sim
