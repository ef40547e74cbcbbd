// The geometry behind the part pictures: a sampled section's surface joined into polylines and
// thinned, revolved into a mesh for a picture, and the main dimensions read off it.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geometry/part_dimensions.hpp"
#include "geometry/profile_polylines.hpp"
#include "geometry/revolved_mesh.hpp"

namespace lathesim {
namespace {

/// φ sampled at step h over r ∈ [0, rMax], z ∈ [zLow, zHigh] from an outline's exact signed
/// distance (clamped at three steps, as the stock's narrow band is).
SampledSection sampled(const MeridianProfile& outline, double h, double rMax, double zLow, double zHigh) {
  SampledSection s;
  s.stepMm = h;
  s.zFirstMm = std::floor(zLow / h) * h;
  s.rCount = static_cast<int>(std::ceil(rMax / h)) + 1;
  s.zCount = static_cast<int>(std::ceil((zHigh - s.zFirstMm) / h)) + 1;
  s.clampMm = 3 * h;
  for (int k = 0; k < s.zCount; ++k)
    for (int i = 0; i < s.rCount; ++i) {
      const double d = outline.signedDistance(RZ(i * h, s.zFirstMm + k * h)).signedMm;
      s.phi.push_back(static_cast<float>(std::clamp(d, -s.clampMm, s.clampMm)));
    }
  return s;
}

TEST(ChainSegments, JoinsShuffledReversedSegmentsIntoOneLoop) {
  // A unit square's four sides, out of order, two of them reversed.
  const std::vector<Segment> sides{{{1, 0}, {1, 1}}, {{0, 0}, {1, 0}}, {{0, 1}, {1, 1}}, {{0, 1}, {0, 0}}};
  const auto lines = chainSegments(sides, 1e-9);
  ASSERT_EQ(lines.size(), 1u);
  ASSERT_EQ(lines[0].size(), 5u);
  EXPECT_EQ(lines[0].front(), lines[0].back());  // closed
  for (std::size_t i = 1; i < 5; ++i) EXPECT_DOUBLE_EQ((lines[0][i] - lines[0][i - 1]).norm(), 1.0);
}

TEST(ChainSegments, OpenChainsRunEndToEndAndEndsMatchWithinTheWeld) {
  // a–b, c–b (reversed), c–d; and a separate e–f. b is met at 1e-10 apart.
  const std::vector<Segment> segments{{{0, 0}, {1, 0}}, {{1, 1}, {1, 1e-10}}, {{1, 1}, {2, 1}}, {{5, 5}, {6, 5}}};
  auto lines = chainSegments(segments, 1e-6);
  ASSERT_EQ(lines.size(), 2u);
  std::sort(lines.begin(), lines.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
  ASSERT_EQ(lines[0].size(), 4u);
  const bool forward = lines[0].front() == RZ(0, 0);
  EXPECT_EQ(forward ? lines[0].back() : lines[0].front(), RZ(2, 1));
  EXPECT_EQ(lines[1].size(), 2u);
}

TEST(SimplifyPolyline, DropsPointsWithinTheToleranceAndKeepsTheOthers) {
  // On the line z = 0 but for one point 0.3 off at x = 5.
  const std::vector<RZ> line{{0, 0}, {1, 0.01}, {2, -0.01}, {5, 0.3}, {8, 0}, {10, 0}};
  EXPECT_EQ(simplifyPolyline(line, 0.5), (std::vector<RZ>{{0, 0}, {10, 0}}));
  // At 0.2 the two halves' points lie within it of the chords (0,0)–(5,0.3), (5,0.3)–(10,0)
  // (0.13 for (2,−0.01), 0.12 for (8,0)); at 0.1 they do not.
  EXPECT_EQ(simplifyPolyline(line, 0.2), (std::vector<RZ>{{0, 0}, {5, 0.3}, {10, 0}}));
  EXPECT_EQ(simplifyPolyline(line, 0.1), (std::vector<RZ>{{0, 0}, {2, -0.01}, {5, 0.3}, {8, 0}, {10, 0}}));
}

// A Φ2R × L cylinder revolved in n steps is an n-gon prism: volume (n/2)·R²·sin(2π/n)·L exactly.
TEST(RevolvedMesh, ProfileEndingOnTheAxisGivesAClosedPrismOfExactVolume) {
  for (int n : {12, 37, 96}) {
    const double r = 30, length = 60;
    // Material on the right: along the top face outwards, down the outside, back to the axis.
    const TriangleMesh mesh = revolvedMesh({{{0, length}, {r, length}, {r, 0}, {0, 0}}}, n);
    EXPECT_TRUE(isClosedAndOriented(mesh)) << n;
    EXPECT_NEAR(enclosedVolumeMm3(mesh), n / 2.0 * r * r * std::sin(2 * M_PI / n) * length, 1e-6 * r * r * length) << n;
  }
}

TEST(RevolvedMesh, ALoopGivesATubeOfExactVolumeFacingOutwards) {
  const int n = 64;
  const double outer = 25, bore = 10, length = 30;
  const TriangleMesh tube = revolvedMesh({{{outer, 0}, {outer, -length}, {bore, -length}, {bore, 0}, {outer, 0}}}, n);
  EXPECT_TRUE(isClosedAndOriented(tube));
  EXPECT_NEAR(enclosedVolumeMm3(tube), n / 2.0 * (outer * outer - bore * bore) * std::sin(2 * M_PI / n) * length, 1e-6 * 2e4);
}

TEST(RevolvedMesh, StepsFollowTheChordTolerance) {
  // r(1 − cos(π/n)) ≤ tolerance, and not for n − 1.
  for (double r : {5.0, 62.5, 400.0})
    for (double tolerance : {0.01, 0.1, 0.5}) {
      const int n = angularStepsFor(r, tolerance);
      EXPECT_LE(r * (1 - std::cos(M_PI / n)), tolerance * (1 + 1e-12));
      if (n > 12) {
        EXPECT_GT(r * (1 - std::cos(M_PI / (n - 1))), tolerance);
      }
    }
}

struct Shaft {
  double bigRadius, smallRadius, shoulderZ, length, boreRadius;  // the right-hand end at Z0
};

/// The stepped, bored shaft's outline: Φ2·small from Z0 to the shoulder, Φ2·big on to −length,
/// a bore through.
MeridianProfile outlineOf(const Shaft& s) {
  return MeridianProfile::fromPolygon({{s.boreRadius, 0},
                                       {s.smallRadius, 0},
                                       {s.smallRadius, s.shoulderZ},
                                       {s.bigRadius, s.shoulderZ},
                                       {s.bigRadius, -s.length},
                                       {s.boreRadius, -s.length},
                                       {s.boreRadius, 0}});
}

// The shaft sampled at several voxel sizes and offsets against the grid: revolved, it holds the
// Pappus volume to within the chords' error, and its dimensions are read to far below a voxel.
TEST(SampledShaft, RevolvesToItsVolumeAndReadsItsDimensions) {
  const std::vector<Shaft> shafts{{25, 15, -20, 60, 6}, {40.1, 22.37, -33.3, 91.7, 9.55}, {12.5, 7.5, -5.05, 30, 2.5}};
  for (const Shaft& shaft : shafts)
    for (double h : {0.1, 0.25, 0.4}) {
      const MeridianProfile outline = outlineOf(shaft);
      const MeridianProfile section = MeridianProfile::fromSection(sampled(outline, h, shaft.bigRadius + 4 * h, -shaft.length - 4 * h, 4 * h));
      const auto thin = profilePolylines(section, 0.1 * h);
      const int n = 720;
      const TriangleMesh mesh = revolvedMesh(thin, n);
      EXPECT_TRUE(isClosedAndOriented(mesh)) << h;
      const double polygonFactor = n / (2 * M_PI) * std::sin(2 * M_PI / n);
      const double pappus = M_PI * (shaft.smallRadius * shaft.smallRadius * -shaft.shoulderZ +
                                    shaft.bigRadius * shaft.bigRadius * (shaft.length + shaft.shoulderZ) -
                                    shaft.boreRadius * shaft.boreRadius * shaft.length);
      // Marching squares cuts each of the 6 corners by at most a triangle of legs h (h²/2 of
      // section), at r ≤ the big radius; the thinning moves no point more than 0.1 h, and only
      // at the corners (flat faces' points lie on one line).
      EXPECT_NEAR(enclosedVolumeMm3(mesh), pappus * polygonFactor, 6 * 2 * M_PI * shaft.bigRadius * h * h) << h;

      DimensionRules rules;
      rules.flatToleranceMm = 0.02 * h;
      rules.minFaceMm = 2.0;
      const PartDimensions dims = mainDimensions(section, chainSegments(section.surface(), 1e-6), rules);
      ASSERT_EQ(dims.diameters.size(), 3u) << h;  // by Z: the bore (whole length), Φbig, Φsmall
      std::vector<DiameterDimension> d = dims.diameters;
      std::sort(d.begin(), d.end(), [](const auto& a, const auto& b) { return a.diameterMm < b.diameterMm; });
      EXPECT_NEAR(d[0].diameterMm, 2 * shaft.boreRadius, 1e-3) << h;
      EXPECT_TRUE(d[0].bore);
      EXPECT_NEAR(d[1].diameterMm, 2 * shaft.smallRadius, 1e-3) << h;
      EXPECT_FALSE(d[1].bore);
      EXPECT_NEAR(d[2].diameterMm, 2 * shaft.bigRadius, 1e-3) << h;
      EXPECT_FALSE(d[2].bore);
      // The Φsmall face spans Z shoulder..0 but for the corners marching squares cuts (less than
      // two steps; the extents only place the dimension lines).
      EXPECT_NEAR(d[1].zLowMm, shaft.shoulderZ, 2 * h) << h;
      EXPECT_NEAR(d[1].zHighMm, 0.0, 2 * h) << h;
      ASSERT_EQ(dims.lengths.size(), 2u) << h;  // to the shoulder, then overall
      EXPECT_NEAR(dims.lengths[0].zHighMm - dims.lengths[0].zLowMm, -shaft.shoulderZ, 1e-3) << h;
      EXPECT_NEAR(dims.lengths[1].zHighMm - dims.lengths[1].zLowMm, shaft.length, 1e-3) << h;
      EXPECT_NEAR(dims.lengths[0].radiusLowMm, shaft.bigRadius, 2 * h) << h;  // the shoulder reaches out to Φbig
    }
}

TEST(SampledShaft, ATaperHasNoDiameterAndAnEmptySectionNoDimensions) {
  const double h = 0.2;
  const MeridianProfile cone = MeridianProfile::fromPolygon({{10, 0}, {20, -30}});
  const MeridianProfile section = MeridianProfile::fromSection(sampled(cone, h, 22, -31, 1));
  const PartDimensions dims = mainDimensions(section, chainSegments(section.surface(), 1e-6), DimensionRules{});
  EXPECT_TRUE(dims.diameters.empty());
  ASSERT_EQ(dims.lengths.size(), 1u);
  EXPECT_NEAR(dims.lengths[0].zHighMm - dims.lengths[0].zLowMm, 30.0, 1e-3);

  const MeridianProfile nothing = MeridianProfile::fromSurface({});
  EXPECT_TRUE(mainDimensions(nothing, {}, DimensionRules{}).lengths.empty());
}

}  // namespace
}  // namespace lathesim
