// --stock D40xL80: the bar on the command line.

#include "setup/stock_option.hpp"

#include <gtest/gtest.h>

namespace lathesim::setup {
namespace {

TEST(StockOption, DiameterLengthAndFace) {
  auto spec = std::get<sim::StockSpec>(parseStockOption("D40xL80"));
  EXPECT_DOUBLE_EQ(spec.diameterMm, 40);
  EXPECT_DOUBLE_EQ(spec.lengthMm, 80);
  EXPECT_DOUBLE_EQ(spec.faceZMm, 0);
  spec = std::get<sim::StockSpec>(parseStockOption("L80.5XD25.4xZ-1.5"));
  EXPECT_DOUBLE_EQ(spec.diameterMm, 25.4);
  EXPECT_DOUBLE_EQ(spec.lengthMm, 80.5);
  EXPECT_DOUBLE_EQ(spec.faceZMm, -1.5);
}

TEST(StockOption, ProblemsAreSaid) {
  const auto problem = [](std::string_view text) { return std::get<std::string>(parseStockOption(text)); };
  EXPECT_NE(problem("D40").find("L is missing"), std::string::npos);
  EXPECT_NE(problem("L40").find("D is missing"), std::string::npos);
  EXPECT_NE(problem("D40xL0").find("L0 must be positive"), std::string::npos);
  EXPECT_NE(problem("D40xD30xL8").find("D is given twice"), std::string::npos);
  EXPECT_NE(problem("D40xQ3xL8").find("'Q3' is not D, d, L or Z"), std::string::npos);
  EXPECT_NE(problem("D40xxL8").find("an empty part"), std::string::npos);
  EXPECT_EQ(problem("D40xd40xL80"),
            "--stock D40xd40xL80: the bore d40 must be smaller than the diameter D40; give the bar as "
            "D<diameter>[xd<bore>]xL<length>[xZ<face>], e.g. D40xL80, D40xL80xZ1 or D60xd40xL80");
  EXPECT_NE(problem("d50xD40xL80").find("the bore d50 must be smaller than the diameter D40"), std::string::npos);
  EXPECT_NE(problem("D40xd0xL80").find("d0 must be positive"), std::string::npos);
  EXPECT_NE(problem("D40xd-3xL80").find("d-3 must be positive"), std::string::npos);
  EXPECT_NE(problem("D60xd40xd30xL80").find("d is given twice"), std::string::npos);
}

TEST(StockOption, ABoreMakesATube) {
  auto spec = std::get<sim::StockSpec>(parseStockOption("D60xd40xL80"));
  EXPECT_DOUBLE_EQ(spec.diameterMm, 60);
  EXPECT_DOUBLE_EQ(spec.boreMm, 40);
  EXPECT_DOUBLE_EQ(spec.lengthMm, 80);
  EXPECT_DOUBLE_EQ(spec.faceZMm, 0);
  spec = std::get<sim::StockSpec>(parseStockOption("L35Xd12.7XZ1.5XD25.4"));  // any order
  EXPECT_DOUBLE_EQ(spec.diameterMm, 25.4);
  EXPECT_DOUBLE_EQ(spec.boreMm, 12.7);
  EXPECT_DOUBLE_EQ(spec.lengthMm, 35);
  EXPECT_DOUBLE_EQ(spec.faceZMm, 1.5);
  EXPECT_DOUBLE_EQ(std::get<sim::StockSpec>(parseStockOption("D40xL80")).boreMm, 0.0);
}

}  // namespace
}  // namespace lathesim::setup
