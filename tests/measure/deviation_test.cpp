// The deviation measure on sections whose answers are known exactly.

#include "measure/deviation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace lathesim::measure {
namespace {

/// φ of the solid r ≤ 10, −5 ≤ z ≤ 5 (exact signed distance), sampled every `h` from
/// z = −8 out to r 14, clamped at ±3h as a narrow band is.
SampledSection cylinderSection(double h) {
  SampledSection s;
  s.stepMm = h;
  s.zFirstMm = -8;
  s.rCount = static_cast<int>(14 / h);
  s.zCount = static_cast<int>(16 / h);
  s.clampMm = 3 * h;
  for (int k = 0; k < s.zCount; ++k)
    for (int i = 0; i < s.rCount; ++i) {
      const double dr = i * h - 10, dz = std::abs(s.zFirstMm + k * h) - 5;
      const double outside = std::hypot(std::max(dr, 0.0), std::max(dz, 0.0));
      s.phi.push_back(static_cast<float>(std::clamp(outside > 0 ? outside : std::max(dr, dz), -3 * h, 3 * h)));
    }
  return s;
}

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
