// Which band holds where on the outline: a size's line off its ends is the size check's; near
// a corner the looser band of the two lines; a corner the drawing lets be rounded allows its
// fillet — excess in a concave corner, gouge on a convex edge — and only as deep as the
// fillet lies there.

#include "measure/profile_limits.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "measure/drawing.hpp"

namespace lathesim::measure {
namespace {

// Φ20 to Z-10, a shoulder up to Φ30, Φ30 to Z-30, each ±0.1 (a diameter's ±0.05 normal to it).
DrawingResult shoulder(double cornerRadius) {
  DrawingResult r = parseDrawing("corner_radius = " + std::to_string(cornerRadius) +
                                     "\nprofile = [{x = 20, z = 0}, {x = 20, z = -10, tolerance = 0.1}, {x = 30, z = -10, "
                                     "tolerance = 0.1}, {x = 30, z = -30, tolerance = 0.1}]\n",
                                 "d.toml");
  EXPECT_TRUE(r.outline);
  return r;
}

// The fillet of radius R in a 90° corner is tangent T = R from it; at s from the corner along a
// line it lies R − √(R² − (T − s)²) off the line: R 0.8, s 0.3: 0.8 − √(0.64 − 0.25) = 0.17550.
TEST(ProfileLimits, AllowedCornerRadiusWidensTheBandByTheFillet) {
  const DrawingResult r = shoulder(0.8);
  const MeridianProfile drawing = MeridianProfile::fromPolygon(*r.outline);
  const ProfileLimits limits(drawing, *r.outline, r.lines, 'm', r.cornerRadiusMm, 1.0);
  const double fillet = 0.8 - std::sqrt(0.64 - 0.25);
  // The concave corner (r 10, Z-10), on the face 0.3 out from it: excess allowed.
  const auto concave = limits.at(RZ(10.3, -10));
  ASSERT_TRUE(concave);
  EXPECT_NEAR(concave->upperMm, 0.1 + fillet, 1e-9);  // the face's ±0.1, looser than the diameter's ±0.05
  EXPECT_NEAR(concave->lowerMm, -0.1, 1e-9);
  // The convex edge (r 15, Z-10), on the face 0.3 in from it: gouge allowed.
  const auto convex = limits.at(RZ(14.7, -10));
  ASSERT_TRUE(convex);
  EXPECT_NEAR(convex->lowerMm, -0.1 - fillet, 1e-9);
  EXPECT_NEAR(convex->upperMm, 0.1, 1e-9);
  // Beyond the tangent point the fillet is gone.
  const auto beyond = limits.at(RZ(10.9, -10));
  ASSERT_TRUE(beyond);
  EXPECT_NEAR(beyond->upperMm, 0.1, 1e-9);
  // Off the ends of a size's line the size check judges.
  EXPECT_FALSE(limits.at(RZ(10, -5)));
  EXPECT_FALSE(limits.at(RZ(15, -20)));
}

TEST(ProfileLimits, NoCornerRadiusNoFillet) {
  const DrawingResult r = shoulder(0);
  const MeridianProfile drawing = MeridianProfile::fromPolygon(*r.outline);
  const ProfileLimits limits(drawing, *r.outline, r.lines, 'm', r.cornerRadiusMm, 1.0);
  const auto concave = limits.at(RZ(10.3, -10));
  ASSERT_TRUE(concave);
  EXPECT_NEAR(concave->upperMm, 0.1, 1e-9);
  EXPECT_NEAR(concave->lowerMm, -0.1, 1e-9);
}

// A diameter's tolerance normal to it: half, and a bore's turned over (its excess shrinks it).
TEST(ProfileLimits, DiameterBandsAreHalvedAndTurnedForABore) {
  const DrawingResult r = parseDrawing(
      "profile = [{x = 30, z = 0}, {x = 50, z = 0}, {x = 50, z = -9, tolerance = [0, -0.04]},\n {x = 30, z = -9}, "
      "{x = 30, z = 0, tolerance = \"H7\"}]\n",
      "d.toml");
  ASSERT_TRUE(r.outline);
  const MeridianProfile drawing = MeridianProfile::fromPolygon(*r.outline);
  const Band shaft = normalBand(drawing, r.lines[1], *r.lines[1].tolerance);
  EXPECT_NEAR(shaft.upperMm, 0, 1e-12);
  EXPECT_NEAR(shaft.lowerMm, -0.02, 1e-12);
  const Band bore = normalBand(drawing, r.lines[3], *r.lines[3].tolerance);  // H7 on Φ30: +0.021/0
  EXPECT_NEAR(bore.upperMm, 0, 1e-12);
  EXPECT_NEAR(bore.lowerMm, -0.0105, 1e-12);
}

}  // namespace
}  // namespace lathesim::measure
