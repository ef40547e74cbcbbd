// A close-up's region: the box stretched to the picture's aspect with a 25 % reach, the front
// half of the part and a margin behind it, sampled finer the more a voxel is magnified.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "render/close_up_region.hpp"

namespace lathesim::render {
namespace {

// A thread's box, Z 10…16 and radius 8…12 (6 × 4 mm), in a 1600 × 1200 picture (aspect 4/3):
// by hand, half Z = 1.25 · max(3, 2 · 4/3) = 3.75, half X = 1.25 · max(2, 3 / (4/3)) = 2.8125;
// the reach 10 + 2.8125 = 12.8125 out, 2 · 2.8125 in from it, 2.8125 behind the meridian.
TEST(CloseUpRegion, BoxStretchedToThePictureByHand) {
  const CloseUp box{10, 16, 8, 12};
  const CloseUpRegion r = closeUpRegion(box, 1600, 1200, 0.2);
  EXPECT_NEAR(r.low.z(), 13 - 3.75, 1e-12);
  EXPECT_NEAR(r.high.z(), 13 + 3.75, 1e-12);
  EXPECT_NEAR(r.high.x(), 12.8125, 1e-12);
  EXPECT_NEAR(r.low.x(), 12.8125 - 5.625, 1e-12);
  EXPECT_NEAR(r.low.y(), -2.8125, 1e-12);
  EXPECT_NEAR(r.high.y(), 12.8125, 1e-12);
  // A voxel of 0.2 mm spans 0.2 · 1600 / 7.5 = 42.7 pixels: six 7-pixel facets, at most 4.
  EXPECT_EQ(r.subdivisions, 4);
}

// Facets of about 7 pixels: a voxel of v pixels is split round(v / 7) times, 1 to 4; a tall
// box is stretched in Z instead, and always holds the box.
TEST(CloseUpRegion, SubdivisionsFollowTheMagnificationAndTheBoxIsHeld) {
  for (const double voxelMm : {0.01, 0.05, 0.1, 0.2, 0.4}) {
    for (const CloseUp box : {CloseUp{10, 16, 8, 12}, CloseUp{-30, -29, 0, 20}}) {
      SCOPED_TRACE(voxelMm);
      const CloseUpRegion r = closeUpRegion(box, 800, 600, voxelMm);
      const double voxelPx = voxelMm * 800 / (r.high.z() - r.low.z());
      EXPECT_EQ(r.subdivisions, std::clamp(static_cast<int>(std::lround(voxelPx / 7)), 1, 4));
      EXPECT_LE(r.low.z(), box.zLowMm);
      EXPECT_GE(r.high.z(), box.zHighMm);
      EXPECT_LE(r.low.x(), box.radiusLowMm);
      EXPECT_GE(r.high.x(), box.radiusHighMm);
      EXPECT_NEAR((r.high.z() - r.low.z()) / (r.high.x() - r.low.x()), 800.0 / 600.0, 1e-9);
    }
  }
}

}  // namespace
}  // namespace lathesim::render
