// The meridian-plane outlines a drawing check compares: a drawn polygon closed via the axis,
// and a sampled level set's zero crossings.

#include "geometry/meridian_profile.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/support/cylinder_section.hpp"

namespace lathesim {
namespace {

// Seed 001's drawing: (r 15, Z0) → (r 25, Z-20) → (r 25, Z-60), closed via the axis.
MeridianProfile seed001Drawing() { return MeridianProfile::fromPolygon({{15, 0}, {25, -20}, {25, -60}}); }

TEST(MeridianProfile, PolygonIsClosedViaTheAxisButTheAxisIsNoSurface) {
  const MeridianProfile drawing = seed001Drawing();
  // Face (0,0)→(15,0), cone, cylinder, end face (25,-60)→(0,-60); the axis edge is left out.
  EXPECT_EQ(drawing.surface().size(), 4u);
  EXPECT_TRUE(drawing.contains({1, -30}));
  EXPECT_FALSE(drawing.contains({26, -30}));
  EXPECT_FALSE(drawing.contains({10, 1}));
  // 1 mm from the axis, the nearest surface is the cylinder 24 mm away, not the axis.
  EXPECT_NEAR(drawing.signedDistance({1, -30}).signedMm, -24.0, 1e-12);
  // Normal to the cone 2r + z − 30 = 0: (2·25 − 50/3 − 30)/√5 = 2√5/3 outside.
  const SurfaceDistance d = drawing.signedDistance({25, -50.0 / 3});
  EXPECT_NEAR(d.signedMm, 2 * std::sqrt(5.0) / 3, 1e-12);
  EXPECT_NEAR(2 * d.nearest.x() + d.nearest.y() - 30, 0.0, 1e-12);
}

// A bored part: Φ50 outside, Φ20 bore, Z-30..0; the outline ends where it starts, so it is
// closed as given and the bore (r 10) is a surface, the axis inside the bore is air.
TEST(MeridianProfile, OutlineEndingWhereItStartsIsABoredPart) {
  const MeridianProfile ring = MeridianProfile::fromPolygon({{10, 0}, {25, 0}, {25, -30}, {10, -30}, {10, 0}});
  EXPECT_EQ(ring.surface().size(), 4u);
  EXPECT_FALSE(ring.contains({5, -15}));
  EXPECT_TRUE(ring.contains({15, -15}));
  EXPECT_NEAR(ring.signedDistance({5, -15}).signedMm, 5.0, 1e-12);
  EXPECT_NEAR(ring.signedDistance({12, -15}).signedMm, -2.0, 1e-12);
}

using test::cylinderSection;

TEST(MeridianProfile, SectionSurfaceLiesOnTheZeroCrossings) {
  const double h = 0.3;  // the rectangle's sides fall between samples
  const MeridianProfile part = MeridianProfile::fromSection(cylinderSection(h));
  for (const Segment& s : part.surface())
    for (const RZ& p : {s.a, s.b}) {
      // Every vertex is on a side (r = 10 or |z| = 5), up to float rounding.
      const double off = std::min(std::abs(p.x() - 10), std::abs(std::abs(p.y()) - 5));
      EXPECT_LT(off, 1e-5) << p.transpose();
    }
  EXPECT_TRUE(part.contains({5, 0}));
  EXPECT_FALSE(part.contains({11, 0}));
  // Within the band, φ interpolated: on a side exactly; at the corner (10, 5), which the
  // chords cut off by up to h/√2, within a quarter voxel (bilinear over the curved φ outside
  // a convex corner overshoots; here the corner is 0.1 and 0.1 from the nearest samples).
  EXPECT_LT(std::abs(part.signedDistance({10, 5}).signedMm), 0.26 * h);
  EXPECT_NEAR(part.signedDistance({10.5, 0}).signedMm, 0.5, 1e-5);
  // Beyond it the distance to the chords: 3 mm out from the side r = 10.
  EXPECT_NEAR(part.signedDistance({13, 0}).signedMm, 3.0, 1e-5);
  EXPECT_NEAR(part.signedDistance({2, 0}).signedMm, -5.0, 1e-5);  // to the end faces, not the axis
}

}  // namespace
}  // namespace lathesim
