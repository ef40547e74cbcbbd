// [machine] tailstock and [stock] material read from the setup file, and the tailstock's
// regions the collision check uses, worked out by hand.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "setup/setup.hpp"

namespace lathesim::setup {
namespace {

TEST(TailstockSetup, ReadsThePointAndTheQuillAndTheMaterial) {
  const SetupResult result = parseSetup(
      "[stock]\ndiameter = 40.0\nlength = 60.0\nmaterial = \"C45\"\n[machine]\ntailstock = { z = 1.5, diameter = 20 }\n",
      "part.toml");
  ASSERT_TRUE(result.setup) << (result.diagnostics.empty() ? "" : result.diagnostics[0].message);
  ASSERT_TRUE(result.setup->tailstock);
  EXPECT_DOUBLE_EQ(result.setup->tailstock->pointZMm, 1.5);
  EXPECT_DOUBLE_EQ(result.setup->tailstock->quillDiameterMm, 20.0);
  EXPECT_EQ(result.setup->stockMaterial, "C45");
  EXPECT_EQ(result.setup->stockBy, "part.toml:1 [stock]");
  EXPECT_FALSE(defaultSetup().tailstock);
}

TEST(TailstockSetup, ItsCentreIsASixtyDegreeConeThenTheQuillThreeDiametersLong) {
  // Point at Z1.5, Φ20: the cone reaches r 10 at Z1.5 + 10 / tan 30° = 18.820; the quill runs
  // 60 mm further, to Z78.820.
  const Tailstock tailstock{1.5, 20.0};
  const double coneEnd = 1.5 + 10.0 * std::sqrt(3.0);
  EXPECT_NEAR(coneEndZMm(tailstock), coneEnd, 1e-12);
  const std::vector<ConvexPolygon> regions = tailstockRegions(tailstock);
  ASSERT_EQ(regions.size(), 2u);
  const auto bounds = [](const ConvexPolygon& p) {
    RZ low = p.vertices().front(), high = low;
    for (const RZ& v : p.vertices()) low = low.cwiseMin(v), high = high.cwiseMax(v);
    return std::pair{low, high};
  };
  const auto [coneLow, coneHigh] = bounds(regions[0]);
  EXPECT_EQ(regions[0].vertices().size(), 3u);
  EXPECT_NEAR(coneLow.y(), 1.5, 1e-12);
  EXPECT_NEAR(coneHigh.y(), coneEnd, 1e-12);
  EXPECT_NEAR(coneHigh.x(), 10.0, 1e-12);
  const auto [quillLow, quillHigh] = bounds(regions[1]);
  EXPECT_NEAR(quillLow.y(), coneEnd, 1e-12);
  EXPECT_NEAR(quillHigh.y(), coneEnd + 60.0, 1e-12);
  EXPECT_NEAR(quillLow.x(), 0.0, 1e-12);
  EXPECT_NEAR(quillHigh.x(), 10.0, 1e-12);
}

TEST(TailstockSetup, BadKeysAreErrorsAtTheirPlace) {
  const SetupResult notTable = parseSetup("[machine]\ntailstock = 30.0\n", "part.toml");
  ASSERT_FALSE(notTable.setup);
  EXPECT_EQ(notTable.diagnostics[0].line, 2);
  EXPECT_EQ(notTable.diagnostics[0].column, 13);
  EXPECT_NE(notTable.diagnostics[0].message.find("machine.tailstock must be a table"), std::string::npos);
  const SetupResult word = parseSetup("[machine]\ntailstock = { z = \"face\", diameter = 20 }\n", "part.toml");
  ASSERT_FALSE(word.setup);
  EXPECT_EQ(word.diagnostics[0].column, 19);
  EXPECT_EQ(word.diagnostics[0].message, "machine.tailstock.z must be a number of mm");
  const SetupResult material = parseSetup("[stock]\nmaterial = 45\n", "part.toml");
  ASSERT_FALSE(material.setup);
  EXPECT_NE(material.diagnostics[0].message.find("stock.material must be text in quotes"), std::string::npos);
}

}  // namespace
}  // namespace lathesim::setup
