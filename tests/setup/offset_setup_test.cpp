// The setup file's [[offset]] tables: values read, defaults, and each error with its key and line.

#include <gtest/gtest.h>

#include "setup/setup.hpp"
#include "tests/setup/setup_text.hpp"

namespace lathesim::setup {
namespace {

using test::onlyDiagnostic;
using test::parse;

TEST(OffsetSetup, NoOffsetsByDefault) { EXPECT_TRUE(defaultSetup().offsets.empty()); }

TEST(OffsetSetup, ReadsEveryKeyAndDefaultsTheRestToZero) {
  const SetupResult result = parse(
      "[[offset]]\nnumber = 1\nx = 0.4\nz = -0.1\nradius = 0.8\ntip = 3\nwear_x = 0.02\n"
      "wear_z = 0.01\n"
      "[[offset]]\nnumber = 7\n");
  ASSERT_TRUE(result.setup.has_value()) << result.diagnostics.front().message;
  const auto& offsets = result.setup->offsets;
  ASSERT_EQ(offsets.size(), 2u);
  const interp::ToolOffset& one = offsets.at(1);
  EXPECT_DOUBLE_EQ(one.xDiameterMm, 0.4);
  EXPECT_DOUBLE_EQ(one.zMm, -0.1);
  EXPECT_DOUBLE_EQ(one.radiusMm, 0.8);
  EXPECT_EQ(one.tip, 3);
  EXPECT_DOUBLE_EQ(one.wearXDiameterMm, 0.02);
  EXPECT_DOUBLE_EQ(one.wearZMm, 0.01);
  // The tip lands at the programmed point + ((0.4 + 0.02)/2, -0.1 + 0.01).
  EXPECT_NEAR(interp::offsetShift(offsets, 1).x(), 0.21, 1e-12);
  EXPECT_NEAR(interp::offsetShift(offsets, 1).y(), -0.09, 1e-12);
  const interp::ToolOffset& seven = offsets.at(7);
  EXPECT_EQ(seven.radiusMm, 0.0);
  EXPECT_EQ(seven.tip, 0);
  EXPECT_EQ(interp::offsetShift(offsets, 7), RZ(0, 0));
}

TEST(OffsetSetup, MissingNumberIsAnError) {
  const auto d = onlyDiagnostic("[[offset]]\nradius = 0.8\n");
  EXPECT_EQ(d.line, 1);
  EXPECT_EQ(d.message, "offset[1] has no number (add number = 1..99)");
}

TEST(OffsetSetup, NegativeRadiusIsAnError) {
  const auto d = onlyDiagnostic("[[offset]]\nnumber = 1\nradius = -0.8\n");
  EXPECT_EQ(d.line, 3);
  EXPECT_EQ(d.message, "offset[1].radius is a nose radius and must be ≥ 0");
}

TEST(OffsetSetup, TipOutsideZeroToNineIsAnError) {
  const auto d = onlyDiagnostic("[[offset]]\nnumber = 1\ntip = 10\n");
  EXPECT_EQ(d.line, 3);
  EXPECT_EQ(d.message, "offset[1].tip must be an integer 0..9");
}

TEST(OffsetSetup, NonNumericShiftIsAnError) {
  const auto d = onlyDiagnostic("[[offset]]\nnumber = 1\nwear_x = \"a lot\"\n");
  EXPECT_EQ(d.line, 3);
  EXPECT_EQ(d.message, "offset[1].wear_x must be a number of mm");
}

TEST(OffsetSetup, UnknownKeyIsAnError) {
  const auto d = onlyDiagnostic("[[offset]]\nnumber = 1\nnose = 0.8\n");
  EXPECT_EQ(d.line, 3);
  EXPECT_EQ(d.message,
            "unknown key 'offset[1].nose' (expected number, x, z, radius, tip, wear_x, wear_z)");
}

TEST(OffsetSetup, NumberDefinedTwiceIsAnError) {
  const auto d = onlyDiagnostic("[[offset]]\nnumber = 2\n[[offset]]\nnumber = 2\n");
  EXPECT_EQ(d.line, 4);
  EXPECT_EQ(d.message, "offset number 2 is defined twice (offset[1] and offset[2])");
}

TEST(OffsetSetup, NotAnArrayOfTablesIsAnError) {
  const auto d = onlyDiagnostic("offset = 3\n");
  EXPECT_EQ(d.line, 1);
  EXPECT_EQ(d.message, "offset must be given as [[offset]] tables");
}

}  // namespace
}  // namespace lathesim::setup
