// The deviation measure on sections whose answers are known exactly.

#include "measure/deviation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/support/cylinder_section.hpp"

namespace lathesim::measure {
namespace {

using test::cylinderSection;

// A part measured against itself (as --target-program with the same program): nothing.
TEST(Deviation, SectionAgainstItselfIsZeroEverywhere) {
  const SampledSection section = cylinderSection(0.3);
  const MeridianProfile part = MeridianProfile::fromSection(section);
  const DeviationReport d = measureDeviation(section, part, part, 0.0);
  EXPECT_LT(d.maxExcessMm, 1e-6);
  EXPECT_LT(d.maxGougeMm, 1e-6);
  EXPECT_LT(d.excessVolumeMm3, 1e-9);  // rounding only
  EXPECT_LT(d.gougeVolumeMm3, 1e-9);
}

// Drawn Φ21 (r 10.5), made Φ20: a gouge 0.5 deep over Z-5..5; volume π(10.5² − 10²)·10 =
// 102.5π ≈ 322.0 mm³. The drawn end faces (Z±5, r 10..10.5) are in the air too, at most 0.5
// from the part. No excess: the part lies inside the drawing everywhere.
TEST(Deviation, UndersizeDiameterIsOneGougeRegion) {
  const double h = 0.3;
  const SampledSection section = cylinderSection(h);
  const MeridianProfile part = MeridianProfile::fromSection(section);
  const MeridianProfile drawing = MeridianProfile::fromPolygon({{10.5, 5}, {10.5, -5}});
  const DeviationReport d = measureDeviation(section, part, drawing, 0.1);
  EXPECT_NEAR(d.maxGougeMm, 0.5, 0.26 * h);  // the corners read within h/4 (meridian_profile.hpp)
  EXPECT_LT(d.maxExcessMm, 1e-6);
  EXPECT_NEAR(d.gougeVolumeMm3, 102.5 * M_PI, 0.05 * h * 2 * M_PI * 10.25 * 10);
  EXPECT_LT(d.excessVolumeMm3, 1e-6);
  ASSERT_EQ(d.regions.size(), 1u);
  EXPECT_TRUE(d.regions[0].gouge);
  EXPECT_NEAR(d.regions[0].lower.y(), -5, 1e-6);
  EXPECT_NEAR(d.regions[0].upper.y(), 5, 1e-6);
  EXPECT_NEAR(d.regions[0].upper.x(), 10.5, 1e-6);
  EXPECT_FALSE(d.withinTolerance());
}

}  // namespace
}  // namespace lathesim::measure
