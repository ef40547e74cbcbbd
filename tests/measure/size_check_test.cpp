// Sizes checked as an inspector checks them, on sections whose answers are known exactly:
// a Φ20 journal turned undersize by e, against h7, ±0.1 and ISO 2768-m, at three voxels.

#include "measure/size_check.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace lathesim::measure {
namespace {

/// φ of the solid r ≤ radius, zLow ≤ z ≤ 0 (exact signed distance), sampled every `h`
/// from z = zLow − 2 to 2 and r 0 to radius + 4, clamped at ±3h as a narrow band is.
SampledSection shaftSection(double radius, double zLow, double h) {
  SampledSection s;
  s.stepMm = h;
  s.zFirstMm = zLow - 2;
  s.rCount = static_cast<int>(std::ceil((radius + 4) / h));
  s.zCount = static_cast<int>(std::ceil((-zLow + 4) / h));
  s.clampMm = 3 * h;
  for (int k = 0; k < s.zCount; ++k)
    for (int i = 0; i < s.rCount; ++i) {
      const double z = s.zFirstMm + k * h;
      const double dr = i * h - radius, dz = std::max(z, zLow - z);
      const double outside = std::hypot(std::max(dr, 0.0), std::max(dz, 0.0));
      s.phi.push_back(static_cast<float>(std::clamp(outside > 0 ? outside : std::max(dr, dz), -3 * h, 3 * h)));
    }
  return s;
}

/// The drawing of a Φ20 × 30 journal: its front face, its diameter (with `tolerance`), its back face.
std::vector<DrawnLine> journal(std::optional<Tolerance> tolerance) {
  return {{RZ(0, 0), RZ(10, 0), 2, false, std::nullopt},
          {RZ(10, 0), RZ(10, -30), 5, false, tolerance},
          {RZ(10, -30), RZ(0, -30), 8, false, std::nullopt}};
}

MeridianProfile journalOutline() { return MeridianProfile::fromPolygon({RZ(0, 0), RZ(10, 0), RZ(10, -30), RZ(0, -30)}); }

const SizeCheck& diameterOf(const std::vector<SizeCheck>& checks) {
  return *std::find_if(checks.begin(), checks.end(), [](const SizeCheck& c) { return c.diameter; });
}

// The hand-worked table. A section found at voxel h is within h/16 of the true surface
// (surfaceUncertaintyMm), so a diameter is known to ±h/8: ±0.025 at 0.2, ±0.0125 at 0.1,
// ±0.00625 at 0.05. The limits on Φ20: h7 0/−0.021 (ISO 286-2: 18–30 mm, IT7 = 21 µm, es = 0),
// ±0.1, ISO 2768-m ±0.2 (over 6 up to 30 mm). Undersize e measures 20 − e, which lies
// max(lower limit − (20 − e), (20 − e) − upper limit) beyond the nearer limit (< 0: inside);
// the verdict is out when that is ≥ the uncertainty, within when ≤ −it, else undecided:
//
//   e     limits      beyond                      h 0.2 (±.025)  h 0.1 (±.0125)  h 0.05 (±.00625)
//   0.5   0/−0.021    max(0.479, −0.5)  = +0.479   out            out             out
//   0.5   ±0.1        max(0.4, −0.6)    = +0.4     out            out             out
//   0.5   ±0.2 (m)    max(0.3, −0.7)    = +0.3     out            out             out
//   0.05  0/−0.021    max(0.029, −0.05) = +0.029   out            out             out
//   0.05  ±0.1        max(−0.05, −0.15) = −0.05    within         within          within
//   0.05  ±0.2 (m)    max(−0.15, −0.25) = −0.15    within         within          within
//   0.01  0/−0.021    max(−0.011, −0.01) = −0.01   undecided      undecided       within
//   0.01  ±0.1        max(−0.09, −0.11) = −0.09    within         within          within
//   0.01  ±0.2 (m)    max(−0.19, −0.21) = −0.19    within         within          within
//
// (0.01 under h7 lies nearer its upper limit, Φ20 itself, than its lower.)
struct UndersizeCase {
  double undersizeMm;
  const char* limit;  // "h7", "0.1" (±) or "m" (none stated: ISO 2768-m)
  Verdict atVoxel[3];
};
constexpr double kVoxels[3] = {0.2, 0.1, 0.05};

class UndersizeTable : public testing::TestWithParam<UndersizeCase> {};

TEST_P(UndersizeTable, VerdictAsWorkedByHand) {
  const UndersizeCase& c = GetParam();
  std::optional<Tolerance> stated;
  if (std::string(c.limit) == "h7") stated = Tolerance{0, -0.021, "h7"};
  if (std::string(c.limit) == "0.1") stated = Tolerance{0.1, -0.1, "±0.1"};
  for (int v = 0; v < 3; ++v) {
    const double h = kVoxels[v];
    const SampledSection section = shaftSection(10 - c.undersizeMm / 2, -30, h);
    const auto checks = checkSizes(section, journalOutline(), journal(stated), 'm', 0, {});
    const SizeCheck& d = diameterOf(checks);
    EXPECT_NEAR(d.leastMm, 20 - c.undersizeMm, 1e-4) << "h " << h;
    EXPECT_NEAR(d.greatestMm, 20 - c.undersizeMm, 1e-4) << "h " << h;
    EXPECT_DOUBLE_EQ(d.uncertaintyMm, h / 8);
    EXPECT_EQ(d.verdict, c.atVoxel[v]) << c.undersizeMm << " against " << c.limit << " at voxel " << h << ": "
                                       << verdictName(d.verdict) << ", " << d.outsideMm << " beyond";
    if (d.verdict == Verdict::Undecided) {
      // The voxel it names decides: its uncertainty is under the margin.
      const auto finer = decidingVoxelMm(d.outsideMm, h, d.uncertaintyMm);
      ASSERT_TRUE(finer);
      EXPECT_LT(2 * surfaceUncertaintyMm(*finer), std::abs(d.outsideMm));
      EXPECT_GT(*finer, 0.5 * h * std::abs(d.outsideMm) / d.uncertaintyMm);  // and is not needlessly fine
    }
  }
}

using V = Verdict;
INSTANTIATE_TEST_SUITE_P(
    HandWorked, UndersizeTable,
    testing::Values(UndersizeCase{0.5, "h7", {V::Out, V::Out, V::Out}}, UndersizeCase{0.5, "0.1", {V::Out, V::Out, V::Out}},
                    UndersizeCase{0.5, "m", {V::Out, V::Out, V::Out}},
                    UndersizeCase{0.05, "h7", {V::Out, V::Out, V::Out}},
                    UndersizeCase{0.05, "0.1", {V::Within, V::Within, V::Within}},
                    UndersizeCase{0.05, "m", {V::Within, V::Within, V::Within}},
                    UndersizeCase{0.01, "h7", {V::Undecided, V::Undecided, V::Within}},
                    UndersizeCase{0.01, "0.1", {V::Within, V::Within, V::Within}},
                    UndersizeCase{0.01, "m", {V::Within, V::Within, V::Within}}));

// Oversize is beyond the upper limit the same way; g6 on Φ20 is −0.007/−0.020 (ISO 286-2),
// so the drawn Φ20 itself is 0.007 oversize.
TEST(SizeCheck, OversizeAgainstTheUpperLimit) {
  const SampledSection section = shaftSection(10.05, -30, 0.05);  // Φ20.1
  const auto checks = checkSizes(section, journalOutline(), journal(Tolerance{-0.007, -0.020, "g6"}), 'm', 0, {});
  const SizeCheck& d = diameterOf(checks);
  EXPECT_NEAR(d.outsideMm, 0.107, 1e-4);
  EXPECT_NEAR(d.worstMm, 20.1, 1e-4);
  EXPECT_EQ(d.verdict, Verdict::Out);
  EXPECT_FALSE(d.bore);
  EXPECT_TRUE(d.stated);
}

// The faces are lengths: the front face Z0 against 2768-m for 0 mm (±0.1), the back face
// Z-30 against 2768-m for 30 mm (±0.2). A part 0.3 short at the back is 0.1 beyond.
TEST(SizeCheck, FacesAreLengthsFromTheFrontFace) {
  SampledSection section = shaftSection(10, -29.7, 0.05);
  const auto checks = checkSizes(section, journalOutline(), journal(std::nullopt), 'm', 0, {});
  ASSERT_EQ(checks.size(), 3u);
  const SizeCheck& front = checks[0];
  const SizeCheck& back = checks[2];
  EXPECT_FALSE(front.diameter);
  EXPECT_NEAR(front.worstMm, 0, 1e-4);
  EXPECT_DOUBLE_EQ(front.tolerance.upperMm, 0.1);
  EXPECT_EQ(front.verdict, Verdict::Within);
  EXPECT_NEAR(back.worstMm, -29.7, 1e-4);
  EXPECT_DOUBLE_EQ(back.tolerance.upperMm, 0.2);
  EXPECT_NE(back.tolerance.source.find("ISO 2768-m"), std::string::npos) << back.tolerance.source;
  EXPECT_NEAR(back.outsideMm, 0.1, 1e-4);
  EXPECT_EQ(back.verdict, Verdict::Out);
  EXPECT_DOUBLE_EQ(back.uncertaintyMm, 0.05 / 16);  // one surface: a sixteenth of a voxel
}

// Tolerances from the general table: f, c, and v where the standard has none for ≤ 3 mm.
TEST(SizeCheck, GeneralToleranceSaysWhichAndWhy) {
  const DrawnLine diameter{RZ(10, 0), RZ(10, -30), 5, false, std::nullopt};
  EXPECT_DOUBLE_EQ(generalTolerance(diameter, 'f', 0).upperMm, 0.1);
  EXPECT_DOUBLE_EQ(generalTolerance(diameter, 'c', 0).lowerMm, -0.5);
  EXPECT_EQ(generalTolerance(diameter, 'm', 0).source, "ISO 2768-m for Ø20 (±0.2)");
  const DrawnLine face{RZ(10, -30), RZ(0, -30), 8, false, std::nullopt};
  EXPECT_DOUBLE_EQ(generalTolerance(face, 'm', 0).upperMm, 0.2);
  EXPECT_DOUBLE_EQ(generalTolerance(face, 'm', -28).upperMm, 0.1);  // 2 mm from a datum at Z-28
}

// Verdicts at the uncertainty's edges, and the voxel named to decide.
TEST(SizeCheck, VerdictBoundaries) {
  EXPECT_EQ(verdictOf(0.05, 0.04), Verdict::Out);
  EXPECT_EQ(verdictOf(0.04, 0.04), Verdict::Out);
  EXPECT_EQ(verdictOf(0.039, 0.04), Verdict::Undecided);
  EXPECT_EQ(verdictOf(-0.039, 0.04), Verdict::Undecided);
  EXPECT_EQ(verdictOf(-0.04, 0.04), Verdict::Within);
  // 0.011 beyond a diameter's limit at 0.1 (±0.02): 0.9·0.1·0.011/0.02 = 0.0495 → 0.049,
  // where a diameter is known to ±0.0098.
  EXPECT_NEAR(*decidingVoxelMm(-0.011, 0.1, 0.02), 0.049, 1e-12);
  EXPECT_NEAR(*decidingVoxelMm(0.029, 0.2, 0.04), 0.13, 1e-12);  // 0.9·0.2·0.029/0.04 = 0.1305
  EXPECT_FALSE(decidingVoxelMm(0.0005, 0.1, 0.02));
}

}  // namespace
}  // namespace lathesim::measure
