// --stock D40xL80: the bar on the command line.

#include "job/stock_option.hpp"

#include <gtest/gtest.h>

namespace lathesim::job {
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
  EXPECT_NE(problem("D40xQ3xL8").find("'Q3' is not D, L or Z"), std::string::npos);
  EXPECT_NE(problem("D40xxL8").find("an empty part"), std::string::npos);
  EXPECT_NE(problem("D60xd40xL80").find("tube stock"), std::string::npos);
}

}  // namespace
}  // namespace lathesim::job
