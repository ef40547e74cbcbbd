// Holder and chuck collisions, with volumes worked out by hand.

#include "sim/holder_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/simulate.hpp"
#include "test_moves.hpp"

namespace lathesim::sim {
namespace {


interp::Move move(interp::MoveKind kind, RZ from, RZ to, int block, int line) {
  return test::turningMove(kind, from, to, block, line);
}

ConvexPolygon box(double r0, double z0, double r1, double z1) {
  const std::vector<RZ> corners{{r0, z0}, {r1, z0}, {r1, z1}, {r0, z1}};
  return ConvexPolygon::hullOf(corners);
}

/// A 2×2 cutter at the programmed point and a holder body r 5..20, z 0..10 above it.
CollisionChecks checksFor(const StockSpec& stock, const ChuckSpec& chuck) {
  CollisionChecks checks;
  checks.cutters.emplace(1, box(0, 0, 2, 2));
  checks.holders.emplace(1, box(5, 0, 20, 10));
  checks.chuck = chuckRegions(chuck, stock);
  return checks;
}

TEST(ChuckRegions, DefaultJawsHoldTheBarBehindItsLeftEnd) {
  // Φ50 × 60 bar, face Z0: left end Z−60; jaws r 25..45 (Φ50 + 40), Z −80..−60; body behind.
  const auto regions = chuckRegions(ChuckSpec{}, StockSpec{50.0, 60.0, 0.0});
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_EQ(regions[0].lowerBound(), RZ(25, -80));
  EXPECT_EQ(regions[0].upperBound(), RZ(45, -60));
  EXPECT_EQ(regions[1].lowerBound(), RZ(0, -180));
  EXPECT_EQ(regions[1].upperBound(), RZ(45, -80));
}

TEST(ChuckRegions, JawsMayGripTheStocksOwnEnd) {
  // face_z at Z−40: the jaws grip the bar's left 20 mm, Z −60..−40, r 25..30.
  const auto regions = chuckRegions(ChuckSpec{20.0, 60.0, -40.0}, StockSpec{50.0, 60.0, 0.0});
  EXPECT_EQ(regions[0].lowerBound(), RZ(25, -60));
  EXPECT_EQ(regions[0].upperBound(), RZ(30, -40));
  EXPECT_EQ(regions[1].lowerBound(), RZ(0, -160));
}

TEST(HolderCheck, RapidAlongsideTheBarIntoTheJawsIsIntoChuck) {
  const StockSpec bar{50.0, 60.0, 0.0};
  Stock stock(bar, 0.25);
  const CollisionChecks checks = checksFor(bar, ChuckSpec{20.0, std::nullopt, -40.0});
  interp::Toolpath path;
  path.blockCount = 1;
  // Jaws on the bar's left 20 mm (face_z −40). The cutter at r 30..32 runs from Z5 down to Z−50; the holder (r 35..50) follows. The
  // cutter's sweep r 30..32, Z −50..7 meets the jaws (r 25..45, Z −60..−40) in r 30..32,
  // Z −50..−40: area 20, centroid r 31 → 20·2π·31 = 3895.6 mm³. The holder's sweep, r 35..50,
  // Z −50..15, meets them in r 35..45, Z −50..−40: area 100, centroid r 40 → 100·2π·40 =
  // 25132.7 mm³, the larger, which is reported.
  path.moves.push_back(move(interp::MoveKind::Rapid, {30, 5}, {30, -50}, 0, 7));
  const SimulationResult result = simulate(path, {{1, checks.cutters.at(1)}}, stock, {{}, &checks, {}, {}});
  ASSERT_EQ(result.collisions.size(), 1u);
  EXPECT_EQ(result.collisions[0].kind, "into_chuck");
  EXPECT_EQ(result.collisions[0].line, 7);
  EXPECT_NEAR(result.collisions[0].volumeMm3, 100.0 * 2.0 * std::numbers::pi * 40.0, 1e-6);
}

TEST(HolderCheck, ArcDippingIntoTheJawsIsFollowedNotCutShort) {
  const StockSpec bar{50.0, 60.0, 0.0};
  Stock stock(bar, 0.25);
  const CollisionChecks checks = checksFor(bar, ChuckSpec{20.0, std::nullopt, -40.0});  // jaws r 25..45, Z −60..−40
  interp::Toolpath path;
  path.blockCount = 1;
  // G02 about (r 50, Z−50), radius 20, from Z−30 to Z−70 through r 30 at Z−50 (clockwise in the
  // drawing view). Its chord stays at r 50, clear of the jaws; the arc itself dips into them.
  interp::Move arc = move(interp::MoveKind::ArcCW, {50, -30}, {50, -70}, 0, 12);
  arc.center = RZ(50, -50);
  path.moves.push_back(arc);
  const SimulationResult result = simulate(path, {{1, checks.cutters.at(1)}}, stock, {{}, &checks, {}, {}});
  ASSERT_EQ(result.collisions.size(), 1u);
  EXPECT_EQ(result.collisions[0].kind, "into_chuck");
  EXPECT_EQ(result.collisions[0].line, 12);
  // A straight move along the chord touches nothing.
  path.moves[0].kind = interp::MoveKind::Feed;
  Stock fresh(bar, 0.25);
  EXPECT_TRUE(simulate(path, {{1, checks.cutters.at(1)}}, fresh, {{}, &checks, {}, {}}).collisions.empty());
}

TEST(HolderCheck, HolderDrivenIntoTheBarIsMeasuredNotCut) {
  const StockSpec bar{50.0, 60.0, 0.0};
  const double h = 0.2;
  Stock stock(bar, h);
  const CollisionChecks checks = checksFor(bar, ChuckSpec{});
  interp::Toolpath path;
  path.blockCount = 1;
  // The cutter feeds at r 15 from Z5 to Z−10 (its groove: r 15..17). The holder body, r 20..35
  // and Z from −10 to 15 over the move, overlaps the bar (r ≤ 25, Z ≤ 0) in r 20..25, Z −10..0.
  // Counted one voxel inside the holder's boundary: r 20.2..25, Z −9.8..0, i.e.
  // π(25² − 20.2²)·9.8 = 6679.7 mm³.
  path.moves.push_back(move(interp::MoveKind::Feed, {15, 5}, {15, -10}, 0, 9));
  const double before = stock.volumeMm3();
  const SimulationResult result = simulate(path, {{1, checks.cutters.at(1)}}, stock, {{}, &checks, {}, {}});
  ASSERT_EQ(result.collisions.size(), 1u);
  EXPECT_EQ(result.collisions[0].kind, "holder_into_stock");
  EXPECT_EQ(result.collisions[0].line, 9);
  const double expected = std::numbers::pi * (25.0 * 25.0 - 20.2 * 20.2) * 9.8;
  EXPECT_NEAR(result.collisions[0].volumeMm3, expected, 0.01 * expected);
  // Only the cutter removed anything: its groove r 15..17, Z −10..0 = π(17² − 15²)·10 = 2010.6.
  EXPECT_NEAR(before - stock.volumeMm3(), std::numbers::pi * (17.0 * 17.0 - 15.0 * 15.0) * 10.0, 0.02 * 2010.6);
}

TEST(HolderCheck, HolderAboveTheBarIsNoCollision) {
  const StockSpec bar{50.0, 60.0, 0.0};
  Stock stock(bar, 0.25);
  const CollisionChecks checks = checksFor(bar, ChuckSpec{});
  interp::Toolpath path;
  path.blockCount = 1;
  // A 3 mm deep turning pass at r 22: the holder (from r 27) clears the bar's r 25.
  path.moves.push_back(move(interp::MoveKind::Feed, {22, 2}, {22, -30}, 0, 4));
  const SimulationResult result = simulate(path, {{1, checks.cutters.at(1)}}, stock, {{}, &checks, {}, {}});
  EXPECT_TRUE(result.collisions.empty()) << result.collisions[0].kind << " " << result.collisions[0].volumeMm3;
}

}  // namespace
}  // namespace lathesim::sim
