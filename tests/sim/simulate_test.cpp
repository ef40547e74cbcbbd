#include "sim/simulate.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lathesim::sim {
namespace {

interp::Move move(interp::MoveKind kind, RZ from, RZ to, int block, int line) {
  interp::Move m;
  m.kind = kind;
  m.from = from;
  m.to = to;
  m.feed = kind == interp::MoveKind::Feed ? 0.1 : 0.0;
  m.tool = 1;
  m.block = block;
  m.line = line;
  m.column = 1;
  m.spindleOn = true;
  m.spindleS = 500;  // turning (S0 would be a stopped spindle)
  return m;
}

ToolOutlines squareTool() {
  const std::vector<RZ> square{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  ToolOutlines tools;
  tools.emplace(1, *ConvexPolygon::fromOutline(square).polygon);
  return tools;
}

TEST(Simulate, RapidIntoTheBarIsACollisionOnItsLine) {
  Stock stock({40.0, 30.0, 0.0}, 0.25);
  interp::Toolpath path;
  path.blockCount = 2;
  // A rapid straight down to r = 15 at Z-5 ploughs a 5 mm deep groove; then a feed
  // along the surface that removes nothing.
  path.moves.push_back(move(interp::MoveKind::Rapid, {30, -5}, {15, -5}, 0, 3));
  path.moves.push_back(move(interp::MoveKind::Rapid, {15, -5}, {30, -5}, 1, 4));
  const SimulationResult result = simulate(path, squareTool(), stock);
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
  const SimulationResult result = simulate(path, squareTool(), stock);
  EXPECT_TRUE(result.collisions.empty()) << "removed " << result.collisions[0].volumeMm3;
}

TEST(Simulate, FeedsOfOneBlockAreMeasuredTogether) {
  Stock stock({40.0, 30.0, 0.0}, 0.25);
  interp::Toolpath path;
  path.blockCount = 1;
  // A G94-like face cut: plunge to the axis at Z-2, retract along Z: removes a 2 mm slice.
  path.moves.push_back(move(interp::MoveKind::Feed, {25, -2}, {0, -2}, 0, 7));
  path.moves.push_back(move(interp::MoveKind::Feed, {0, -2}, {0, 5}, 0, 7));
  const SimulationResult result = simulate(path, squareTool(), stock);
  ASSERT_EQ(result.blocks.size(), 1u);
  EXPECT_EQ(result.blocks[0].line, 7);
  EXPECT_NEAR(result.blocks[0].removedMm3, M_PI * 400 * 2, 0.1 * 0.25 * (2 * M_PI * 400 + 2 * M_PI * 20 * 2));
  EXPECT_NEAR(stock.volumeMm3(), M_PI * 400 * 28, 0.1 * 0.25 * (4 * M_PI * 400 + 2 * M_PI * 20 * 30));
}

}  // namespace
}  // namespace lathesim::sim
