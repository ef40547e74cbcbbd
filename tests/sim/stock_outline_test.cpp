// The stock's section in the meridian plane: the bar's outline where the bar is, and a cut's
// outline where the cut went.

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/meridian_profile.hpp"
#include "sim/stock.hpp"

namespace lathesim::sim {
namespace {

TEST(StockOutline, BarSectionIsItsRectangle) {
  const double h = 0.25;
  Stock stock(StockSpec{50.0, 60.0, 0.0}, h);  // Φ50, Z-60..0
  const SampledSection section = stock.meridianSection();
  EXPECT_EQ(section.stepMm, h);
  EXPECT_EQ(section.clampMm, 3 * h);
  const MeridianProfile bar = MeridianProfile::fromSection(section);
  EXPECT_NEAR(bar.lowerBound().y(), -60.0, 1e-6);
  EXPECT_NEAR(bar.upperBound().y(), 0.0, 1e-6);
  EXPECT_NEAR(bar.upperBound().x(), 25.0, 1e-6);
  EXPECT_NEAR(bar.signedDistance({25.4, -30}).signedMm, 0.4, 1e-5);
  EXPECT_NEAR(bar.signedDistance({30, -30}).signedMm, 5.0, 1e-5);
  EXPECT_NEAR(bar.signedDistance({20, -30}).signedMm, -5.0, 1e-5);
  EXPECT_NEAR(bar.signedDistance({10, -2.1}).signedMm, -2.1, 1e-5);
}

// Turning r 25 → r 20.1 over Z-10.05..0: the step (r 20.1, between samples) is where the cut put it.
TEST(StockOutline, CutShowsBetweenSamples) {
  const double h = 0.25;
  Stock stock(StockSpec{50.0, 60.0, 0.0}, h);
  stock.remove(RevolvedRegion({ConvexPolygon::hullOf(std::vector<RZ>{{20.1, -10.05}, {30, -10.05}, {30, 5}, {20.1, 5}})}));
  const MeridianProfile part = MeridianProfile::fromSection(stock.meridianSection());
  EXPECT_NEAR(part.signedDistance({20.1, -5}).signedMm, 0.0, 0.01 * h);
  EXPECT_NEAR(part.signedDistance({22, -10.05}).signedMm, 0.0, 0.01 * h);  // the step's face
  EXPECT_LT(std::abs(part.signedDistance({25, -10.05}).signedMm), 0.26 * h);  // its outer corner
  EXPECT_NEAR(part.signedDistance({23, -5}).signedMm, 2.9, 0.01 * h);
  EXPECT_TRUE(part.contains({20, -5}));
  EXPECT_FALSE(part.contains({20.2, -5}));
}

}  // namespace
}  // namespace lathesim::sim
