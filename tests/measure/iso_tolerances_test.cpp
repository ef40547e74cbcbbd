// ISO 286 fits and ISO 2768-1 general tolerances against values read by hand from the
// standards' own tables (ISO 286-2:2010 Tables 2–17, ISO 2768-1:1989 Table 1).

#include "measure/iso_tolerances.hpp"

#include <gtest/gtest.h>

namespace lathesim::measure {
namespace {

struct FitCase {
  const char* fit;
  double nominalMm;
  double upperMm, lowerMm;  // from ISO 286-2's table for that letter and grade
};

class IsoFits : public testing::TestWithParam<FitCase> {};

TEST_P(IsoFits, MatchTheStandardsTables) {
  const FitCase& c = GetParam();
  std::string problem;
  const auto t = isoFit(c.fit, c.nominalMm, problem);
  ASSERT_TRUE(t) << problem;
  EXPECT_NEAR(t->upperMm, c.upperMm, 1e-9) << c.fit << " Ø" << c.nominalMm;
  EXPECT_NEAR(t->lowerMm, c.lowerMm, 1e-9) << c.fit << " Ø" << c.nominalMm;
  EXPECT_EQ(t->source, c.fit);
}

INSTANTIATE_TEST_SUITE_P(
    Iso286, IsoFits,
    testing::Values(FitCase{"h7", 20, 0, -0.021}, FitCase{"g6", 20, -0.007, -0.020}, FitCase{"H7", 50, 0.025, 0},
                    FitCase{"f7", 25, -0.020, -0.041},
                    // a size on a step's upper bound belongs to that step; just above, to the next
                    FitCase{"H7", 30, 0.021, 0}, FitCase{"h6", 30.001, 0, -0.016}, FitCase{"h5", 3, 0, -0.004},
                    FitCase{"js6", 10, 0.0045, -0.0045}, FitCase{"js7", 20, 0.010, -0.010},  // IT7 21 → 20 (odd, rounded)
                    FitCase{"k6", 20, 0.015, 0.002}, FitCase{"k8", 20, 0.033, 0}, FitCase{"m6", 20, 0.021, 0.008},
                    FitCase{"n6", 20, 0.028, 0.015}, FitCase{"p6", 20, 0.035, 0.022}, FitCase{"d9", 40, -0.080, -0.142},
                    FitCase{"e8", 500, -0.135, -0.232}, FitCase{"h11", 400, 0, -0.360},
                    FitCase{"K7", 20, 0.006, -0.015}, FitCase{"M7", 20, 0, -0.021}, FitCase{"N7", 20, -0.007, -0.028},
                    FitCase{"P7", 20, -0.014, -0.035}, FitCase{"N9", 20, 0, -0.052}, FitCase{"M6", 2, -0.002, -0.008},
                    FitCase{"F8", 20, 0.053, 0.020}, FitCase{"E9", 20, 0.092, 0.040}, FitCase{"D10", 20, 0.149, 0.065},
                    FitCase{"G7", 100, 0.047, 0.012}, FitCase{"JS8", 60, 0.023, -0.023}));

TEST(IsoFits, RefuseWhatIsNotTabled) {
  for (const auto& [fit, size] : std::vector<std::pair<const char*, double>>{
           {"h12", 20}, {"h4", 20}, {"z7", 20}, {"Hh7", 20}, {"h7", 501}, {"h", 20}, {"7", 20}, {"h7x", 20}, {"h7", 0}}) {
    std::string problem;
    EXPECT_FALSE(isoFit(fit, size, problem)) << fit << " Ø" << size;
    EXPECT_FALSE(problem.empty()) << fit;
  }
}

TEST(IsoFits, CaseTellsAHoleFromAShaft) {
  EXPECT_TRUE(isHoleFit("H7"));
  EXPECT_TRUE(isHoleFit("JS6"));
  EXPECT_FALSE(isHoleFit("h7"));
  EXPECT_FALSE(isHoleFit("js6"));
}

TEST(Iso2768, LinearTolerancesByClassAndSize) {
  struct Case {
    char toleranceClass;
    double sizeMm, plusMinusMm;
  };
  for (const Case& c : {Case{'m', 0.5, 0.1}, Case{'m', 6, 0.1}, Case{'m', 6.01, 0.2}, Case{'m', 20, 0.2}, Case{'m', 30, 0.2},
                        Case{'m', 31, 0.3}, Case{'m', 400, 0.5}, Case{'m', 401, 0.8}, Case{'m', 1500, 1.2},
                        Case{'f', 2, 0.05}, Case{'f', 20, 0.1}, Case{'f', 100, 0.15}, Case{'f', 200, 0.2}, Case{'f', 999, 0.3},
                        Case{'c', 2, 0.2}, Case{'c', 5, 0.3}, Case{'c', 20, 0.5}, Case{'c', 100, 0.8}, Case{'c', 500, 2},
                        Case{'v', 5, 0.5}, Case{'v', 20, 1}}) {
    const auto t = generalLinearTolerance(c.toleranceClass, c.sizeMm);
    ASSERT_TRUE(t) << c.toleranceClass << " " << c.sizeMm;
    EXPECT_DOUBLE_EQ(*t, c.plusMinusMm) << c.toleranceClass << " " << c.sizeMm;
  }
  EXPECT_FALSE(generalLinearTolerance('v', 2));  // the standard's "—"
  EXPECT_FALSE(generalLinearTolerance('x', 20));
}

}  // namespace
}  // namespace lathesim::measure
