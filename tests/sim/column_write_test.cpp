// writeColumn against its rule worked out one voxel at a time (column_write.hpp): a sweep of
// stored values and distances at and around every bound the rule has (the band, the ghost
// window, the no-change threshold, a voxel's width), for both signs and three voxel sizes.

#include "sim/column_write.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

namespace lathesim::sim {
namespace {

struct Voxel {
  float phi;
  double psi;
  bool active;
};

// The rule for one voxel, written from its definition rather than the vector code.
struct Expected {
  float phi;
  bool active, ghost;
  double lost;
};
Expected expected(const ColumnWrite& w, const Voxel& v) {
  const double u = w.sign * v.phi;
  const bool open = u > -w.band;
  const bool change = open && v.psi < u - w.noChange;
  const float phi = change ? static_cast<float>(w.sign * std::max(v.psi, -w.band)) : v.phi;
  const auto share = [&](double value) { return std::clamp(0.5 - value / w.voxel, 0.0, 1.0); };
  const bool insideBand = phi < w.band && phi > -w.band;
  const bool ghost = open && std::abs(v.psi) < w.voxel && phi > w.notMaterial && phi < w.ghostCeiling;
  return {phi, change ? insideBand : v.active, ghost, share(v.phi) - share(phi)};
}

// Stored values and distances at and beside each bound.
std::vector<float> valuesAround(const ColumnWrite& w) {
  const float band = static_cast<float>(w.band), h = static_cast<float>(w.voxel);
  std::vector<float> values;
  for (const float at : {band, -band, 0.0f, 0.5f * h, -0.5f * h, w.notMaterial, w.ghostCeiling, 0.3f * h, -0.7f * h})
    for (const float v : {std::nextafter(at, -1.0f), at, std::nextafter(at, 1.0f)})
      if (v <= band && v >= -band) values.push_back(v);
  return values;
}
std::vector<double> distancesFor(const ColumnWrite& w, float phi) {
  const double u = w.sign * phi;
  return {u - w.noChange, std::nextafter(u - w.noChange, -1.0), u - 2.0 * w.noChange, u - 0.03 * w.voxel * 10.0,
          u + w.voxel, -w.band - w.voxel, w.voxel, std::nextafter(w.voxel, 0.0), -w.voxel,
          std::nextafter(-w.voxel, 0.0), 0.0, 2.0 * w.band};
}

TEST(ColumnWrite, EveryVoxelFollowsTheRuleAtEveryBound) {
  for (const double sign : {-1.0, 1.0})
    for (const double voxel : {0.05, 0.1, 0.2}) {
      SCOPED_TRACE(testing::Message() << "sign " << sign << ", voxel " << voxel);
      const ColumnWrite w = ColumnWrite::of(sign, voxel, static_cast<float>(3.0 * voxel));
      std::vector<Voxel> voxels;
      int n = 0;
      for (const float phi : valuesAround(w))
        for (const double psi : distancesFor(w, phi)) voxels.push_back({phi, psi, (n++ % 3) == 0});
      while (voxels.size() % 8) voxels.push_back({static_cast<float>(w.band), 0.0, false});
      int changed = 0;
      for (std::size_t first = 0; first < voxels.size(); first += 8) {
        float values[8];
        double psi[8];
        std::uint8_t activeBits = 0, ghostBits = 0xFF;
        double lostExpected = 0.0;
        for (int k = 0; k < 8; ++k) {
          values[k] = voxels[first + k].phi;
          psi[k] = voxels[first + k].psi;
          activeBits |= static_cast<std::uint8_t>(voxels[first + k].active << k);
        }
        const double lost = writeColumn(w, values, psi, activeBits, ghostBits);
        for (int k = 0; k < 8; ++k) {
          const Voxel& v = voxels[first + k];
          const Expected e = expected(w, v);
          SCOPED_TRACE(testing::Message() << "phi " << v.phi << ", psi " << v.psi);
          EXPECT_EQ(values[k], e.phi);
          EXPECT_EQ((activeBits >> k) & 1, e.active);
          EXPECT_EQ((ghostBits >> k) & 1, e.ghost);
          lostExpected += e.lost;
          changed += values[k] != v.phi;
        }
        EXPECT_NEAR(lost, lostExpected, 1e-12);
      }
      EXPECT_GT(changed, 0);  // the sweep does reach cells that change
    }
}

}  // namespace
}  // namespace lathesim::sim
