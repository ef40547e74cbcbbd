// The meridian section of a revolved mesh is the profile it was revolved from.

#include "geometry/mesh_slice.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/render/test_meshes.hpp"

namespace lathesim {
namespace {

// Seed 001's drawing revolved with 96 facets around (a vertex ring at angle 0, in the plane):
// the slice is the profile itself, so distances come out as for the polygon.
TEST(MeshSlice, RevolvedProfileSlicesBackToItself) {
  const TriangleMesh design = render::test::revolved({{0, 0}, {15, 0}, {25, -20}, {25, -60}, {0, -60}}, 96);
  const std::vector<Segment> slice = meridianSlice(design);
  ASSERT_FALSE(slice.empty());
  for (const Segment& s : slice) {
    EXPECT_GE(s.a.x(), 0.0);
    EXPECT_GE(s.b.x(), 0.0);
  }
  const MeridianProfile profile = MeridianProfile::fromSurface(slice);
  EXPECT_TRUE(profile.contains({10, -30}));
  // At Z-10 the cone is at r 15 + 10/2 = 20.
  EXPECT_TRUE(profile.contains({19.9, -10}));
  EXPECT_FALSE(profile.contains({20.1, -10}));
  // The part's corner of seed 001's R-20 cone: 2√5/3 outside the drawn cone (see check_cli_test).
  EXPECT_NEAR(profile.signedDistance({25, -50.0 / 3}).signedMm, 2 * std::sqrt(5.0) / 3, 1e-5);
  EXPECT_NEAR(profile.signedDistance({1, -30}).signedMm, -24.0, 1e-5);  // the axis is no surface
}

}  // namespace
}  // namespace lathesim
