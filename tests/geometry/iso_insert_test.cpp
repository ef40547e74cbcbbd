// ISO 1832 insert designations against the catalogue values of ../shared/spec/iso-tools.md §1
// (IC from the code table §1.5, l = d·factor with the factors printed there, thickness §1.6,
// nose radius §1.7).

#include "geometry/iso_insert.hpp"

#include <gtest/gtest.h>

namespace lathesim {
namespace {

IsoInsert insertOf(std::string_view code) {
  const auto parsed = parseIsoInsert(code);
  EXPECT_TRUE(parsed.value) << code << ": " << (parsed.problem ? parsed.problem->message : "");
  return parsed.value.value_or(IsoInsert{});
}

CodeProblem insertProblemOf(std::string_view code) {
  const auto parsed = parseIsoInsert(code);
  EXPECT_FALSE(parsed.value) << code;
  return parsed.problem.value_or(CodeProblem{});
}

TEST(IsoInsert, CNMG120408) {
  const IsoInsert i = insertOf("CNMG120408");
  EXPECT_EQ(i.shape, 'C');
  EXPECT_DOUBLE_EQ(i.noseAngleDeg, 80.0);
  EXPECT_EQ(i.clearance, 'N');
  EXPECT_DOUBLE_EQ(i.clearanceDeg, 0.0);
  EXPECT_EQ(i.tolerance, 'M');
  EXPECT_EQ(i.type, 'G');
  EXPECT_DOUBLE_EQ(i.inscribedCircleMm, 12.70);        // table: C12 → 12.70
  EXPECT_NEAR(i.edgeLengthMm, 12.70 * 1.0154, 0.001);  // l = d / sin 80° (factor 1.0154)
  EXPECT_DOUBLE_EQ(i.thicknessMm, 4.76);               // 04
  EXPECT_DOUBLE_EQ(i.noseRadiusMm, 0.8);               // 08
  EXPECT_FALSE(i.vendorSpecialSize);
}

TEST(IsoInsert, DNMG150608) {
  const IsoInsert i = insertOf("DNMG150608");
  EXPECT_DOUBLE_EQ(i.noseAngleDeg, 55.0);
  EXPECT_DOUBLE_EQ(i.inscribedCircleMm, 12.70);        // D15 → 12.70
  EXPECT_NEAR(i.edgeLengthMm, 12.70 * 1.2208, 0.001);  // factor 1.2208 = 1/sin 55°
  EXPECT_DOUBLE_EQ(i.thicknessMm, 6.35);               // 06
  EXPECT_DOUBLE_EQ(i.noseRadiusMm, 0.8);
}

TEST(IsoInsert, VBMT160404) {
  const IsoInsert i = insertOf("VBMT160404");
  EXPECT_DOUBLE_EQ(i.noseAngleDeg, 35.0);
  EXPECT_EQ(i.clearance, 'B');
  EXPECT_DOUBLE_EQ(i.clearanceDeg, 5.0);
  EXPECT_EQ(i.type, 'T');
  EXPECT_DOUBLE_EQ(i.inscribedCircleMm, 9.525);        // V16 → 9.525
  EXPECT_NEAR(i.edgeLengthMm, 9.525 * 1.7434, 0.001);  // 16.6
  EXPECT_DOUBLE_EQ(i.thicknessMm, 4.76);
  EXPECT_DOUBLE_EQ(i.noseRadiusMm, 0.4);
}

TEST(IsoInsert, WNMG080408) {
  const IsoInsert i = insertOf("WNMG080408");
  EXPECT_DOUBLE_EQ(i.noseAngleDeg, 80.0);
  EXPECT_DOUBLE_EQ(i.inscribedCircleMm, 12.70);        // W08 → 12.70 (verified in the reference)
  EXPECT_NEAR(i.edgeLengthMm, 12.70 * 0.6840, 0.001);  // (d/2)(cot 40° + cot 80°)
  EXPECT_DOUBLE_EQ(i.noseRadiusMm, 0.8);
}

TEST(IsoInsert, SNMG120408) {
  const IsoInsert i = insertOf("SNMG120408");
  EXPECT_DOUBLE_EQ(i.noseAngleDeg, 90.0);
  EXPECT_DOUBLE_EQ(i.inscribedCircleMm, 12.70);
  EXPECT_DOUBLE_EQ(i.edgeLengthMm, 12.70);
}

TEST(IsoInsert, TNMG160408) {
  const IsoInsert i = insertOf("TNMG160408");
  EXPECT_DOUBLE_EQ(i.noseAngleDeg, 60.0);
  EXPECT_DOUBLE_EQ(i.inscribedCircleMm, 9.525);        // T16 → 9.525
  EXPECT_NEAR(i.edgeLengthMm, 9.525 * 1.7321, 0.001);  // 16.5 = d·√3
  EXPECT_DOUBLE_EQ(i.thicknessMm, 4.76);
}

TEST(IsoInsert, CCMT060204) {
  const IsoInsert i = insertOf("CCMT060204");
  EXPECT_DOUBLE_EQ(i.clearanceDeg, 7.0);
  EXPECT_DOUBLE_EQ(i.inscribedCircleMm, 6.35);  // C06 → 6.35
  EXPECT_DOUBLE_EQ(i.thicknessMm, 2.38);        // 02
  EXPECT_DOUBLE_EQ(i.noseRadiusMm, 0.4);
}

TEST(IsoInsert, ThicknessCodesWithT) {
  EXPECT_DOUBLE_EQ(insertOf("CCMT09T308").thicknessMm, 3.97);  // T3
  EXPECT_DOUBLE_EQ(insertOf("CCMT09T308").inscribedCircleMm, 9.525);
  EXPECT_DOUBLE_EQ(insertOf("DCMT07T102").thicknessMm, 1.98);  // T1
}

TEST(IsoInsert, CollisionCodesWithSPrefix) {
  EXPECT_DOUBLE_EQ(insertOf("CCMTS40102").inscribedCircleMm, 3.97);  // C S4 → 3.97, C 04 → 4.76
  EXPECT_DOUBLE_EQ(insertOf("CCMT040102").inscribedCircleMm, 4.76);
  EXPECT_DOUBLE_EQ(insertOf("WCMTS30102").inscribedCircleMm, 4.76);  // W S3 → 4.76, W 03 → 5.56
}

TEST(IsoInsert, RoundMetricAndInch) {
  const IsoInsert metric = insertOf("RCMT1204M0");
  EXPECT_TRUE(metric.round());
  EXPECT_DOUBLE_EQ(metric.clearanceDeg, 7.0);
  EXPECT_DOUBLE_EQ(metric.inscribedCircleMm, 12.0);  // M0: the digits are the metric diameter
  EXPECT_DOUBLE_EQ(metric.noseRadiusMm, 6.0);
  EXPECT_DOUBLE_EQ(metric.thicknessMm, 4.76);
  EXPECT_DOUBLE_EQ(insertOf("RNMG120400").inscribedCircleMm, 12.70);  // 00: inch, R12 → 12.70
}

TEST(IsoInsert, ShapeOutsideThePrintedTableUsesTheInchSeries) {
  // E (75°) at 12.70: l = 12.70·1.0353 = 13.15 → "13"; the neighbours 11.11 → 11.50 → "11" and
  // 14.29 → 14.79 → "14" do not collide.
  const IsoInsert i = insertOf("ENMG130408");
  EXPECT_DOUBLE_EQ(i.inscribedCircleMm, 12.70);
  EXPECT_FALSE(i.vendorSpecialSize);
}

TEST(IsoInsert, SeedsTBHG120408IsAVendorSpecial) {
  const auto parsed = parseIsoInsert("TBHG120408");
  ASSERT_TRUE(parsed.value);
  const IsoInsert& i = *parsed.value;
  EXPECT_DOUBLE_EQ(i.noseAngleDeg, 60.0);
  EXPECT_DOUBLE_EQ(i.clearanceDeg, 5.0);  // B
  EXPECT_EQ(i.tolerance, 'H');
  EXPECT_EQ(i.type, 'G');
  EXPECT_TRUE(i.vendorSpecialSize);
  EXPECT_DOUBLE_EQ(i.edgeLengthMm, 12.0);               // "12" read as the edge length
  EXPECT_NEAR(i.inscribedCircleMm, 12.0 / 1.7321, 1e-3);  // 6.928 = 12/√3
  EXPECT_DOUBLE_EQ(i.thicknessMm, 4.76);
  EXPECT_DOUBLE_EQ(i.noseRadiusMm, 0.8);
  ASSERT_EQ(parsed.warnings.size(), 1u);
  EXPECT_NE(parsed.warnings[0].find("vendor special"), std::string::npos) << parsed.warnings[0];
}

TEST(IsoInsert, OptionalPositionsAndMakersSuffix) {
  const IsoInsert i = insertOf("cnmg120408ER-pm");
  EXPECT_EQ(i.code, "CNMG120408ER-PM");
  EXPECT_EQ(i.edgeCondition, 'E');
  EXPECT_EQ(i.hand, 'R');
  EXPECT_DOUBLE_EQ(i.inscribedCircleMm, 12.70);
  EXPECT_EQ(insertOf("VBMT160404-MF").hand, 0);
}

TEST(IsoInsertErrors, EachPositionNamesItsCharacter) {
  CodeProblem p = insertProblemOf("TBXG120408");
  EXPECT_EQ(p.message, "insert TBXG120408: position 3 'X' is not a tolerance class; expected one of A F C H E G J K L M N U");
  EXPECT_EQ(p.index, 2u);
  p = insertProblemOf("XNMG120408");
  EXPECT_EQ(p.message, "insert XNMG120408: position 1 'X' is not an insert shape; expected one of C D E M V S T W R H O P");
  EXPECT_EQ(p.index, 0u);
  p = insertProblemOf("CZMG120408");
  EXPECT_EQ(p.message, "insert CZMG120408: position 2 'Z' is not a clearance angle; expected one of A B C D E F G N P O");
  p = insertProblemOf("CNMZ120408");
  EXPECT_EQ(p.message, "insert CNMZ120408: position 4 'Z' is not an insert type; expected one of N R F A M G W T Q U B H C J X");
  EXPECT_EQ(p.index, 3u);
  p = insertProblemOf("CNMG1X0408");
  EXPECT_EQ(p.message, "insert CNMG1X0408: position 5 '1X' is not a size code for shape C; expected two digits, the edge length in mm");
  EXPECT_EQ(p.index, 4u);
  p = insertProblemOf("CNMG120808");
  EXPECT_EQ(p.message, "insert CNMG120808: position 6 '08' is not a thickness code; expected one of 01 T1 02 03 T3 04 05 06 07 09");
  EXPECT_EQ(p.index, 6u);
  p = insertProblemOf("CNMG1204M0");
  EXPECT_EQ(p.index, 8u);
  EXPECT_NE(p.message.find("position 7 'M0' is not a corner radius"), std::string::npos) << p.message;
  p = insertProblemOf("RCMT120408");
  EXPECT_NE(p.message.find("position 7 '08' is not a round insert's corner; expected 00 (inch diameter) or M0"), std::string::npos)
      << p.message;
  p = insertProblemOf("CNMG120408Z");
  EXPECT_EQ(p.index, 10u);
  EXPECT_NE(p.message.find("position 8 'Z' is not an edge condition or hand"), std::string::npos) << p.message;
}

TEST(IsoInsertErrors, ShortUnsupportedAndImpossible) {
  EXPECT_NE(insertProblemOf("CNMG1204").message.find("insert CNMG1204: too short"), std::string::npos);
  EXPECT_NE(insertProblemOf("KNUX160405").message.find("position 1 'K' is a parallelogram or rectangle"), std::string::npos);
  // 9.9 mm nose on a 12.70 mm IC (radius must stay below d/2 = 6.35)
  EXPECT_NE(insertProblemOf("CNMG120499").message.find("position 7 '99' is a nose radius that does not fit"), std::string::npos);
}

}  // namespace
}  // namespace lathesim
