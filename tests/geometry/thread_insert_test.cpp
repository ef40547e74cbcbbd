// Laydown threading insert codes (iso-tools.md §4.1): size → IC, application, hand, pitch and
// standard, against the catalogues' identification tables (Iscar, TaeguThread: 16 = 3/8 in,
// AG = 0.5–3.0 mm); the nose radius from the thread standard's root (ISO 68 / BS 84).

#include "geometry/thread_insert.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/tool_shape.hpp"

namespace lathesim {
namespace {

ThreadInsert parsed(std::string_view code) {
  const auto result = parseThreadInsert(code);
  EXPECT_TRUE(result.value) << (result.problem ? result.problem->message : "");
  return result.value.value_or(ThreadInsert{});
}

TEST(ThreadInsert, MetricExternalTwoMillimetres) {
  const ThreadInsert insert = parsed("16ER200ISO");
  EXPECT_NEAR(insert.inscribedCircleMm, 9.525, 1e-12);  // 3/8 in
  EXPECT_FALSE(insert.internal);
  EXPECT_EQ(insert.hand, "R");
  EXPECT_EQ(insert.standard, "ISO");
  EXPECT_EQ(insert.profileDeg, 60);
  EXPECT_FALSE(insert.partialProfile);
  EXPECT_DOUBLE_EQ(insert.pitchMm, 2.0);
  EXPECT_DOUBLE_EQ(insert.noseRadiusMm, 0.25);  // 0.125·P
}

TEST(ThreadInsert, PitchWrittenWithOrWithoutADecimalPoint) {
  for (const char* code : {"16ER2.00ISO", "16ER2.0ISO", "16 ER 2.00 ISO", "16erm2.00iso"}) {
    SCOPED_TRACE(code);
    EXPECT_DOUBLE_EQ(parsed(code).pitchMm, 2.0);
  }
  EXPECT_DOUBLE_EQ(parsed("11ER075ISO").pitchMm, 0.75);
  EXPECT_NEAR(parsed("11ER075ISO").inscribedCircleMm, 6.35, 1e-12);
}

TEST(ThreadInsert, MetricInternal) {
  const ThreadInsert insert = parsed("16IR1.5ISO");
  EXPECT_TRUE(insert.internal);
  EXPECT_DOUBLE_EQ(insert.pitchMm, 1.5);
  EXPECT_DOUBLE_EQ(insert.noseRadiusMm, 0.09375);  // 0.0625·P
}

TEST(ThreadInsert, InchStandardsAreThreadsPerInch) {
  const ThreadInsert whitworth = parsed("16ER14W");
  EXPECT_EQ(whitworth.profileDeg, 55);
  EXPECT_NEAR(whitworth.pitchMm, 25.4 / 14, 1e-12);
  EXPECT_NEAR(whitworth.noseRadiusMm, 0.137329 * 25.4 / 14, 1e-12);
  const ThreadInsert un = parsed("22ELM8UN");
  EXPECT_NEAR(un.inscribedCircleMm, 12.7, 1e-12);
  EXPECT_EQ(un.hand, "L");
  EXPECT_NEAR(un.pitchMm, 3.175, 1e-12);
  EXPECT_EQ(un.profileDeg, 60);
  EXPECT_NEAR(parsed("16ER11.5NPT").pitchMm, 25.4 / 11.5, 1e-12);
  EXPECT_EQ(parsed("16ER11BSPT").profileDeg, 55);
}

TEST(ThreadInsert, PartialProfiles) {
  const ThreadInsert ag = parsed("16ERAG60");
  EXPECT_TRUE(ag.partialProfile);
  EXPECT_EQ(ag.profileDeg, 60);
  EXPECT_DOUBLE_EQ(ag.minPitchMm, 0.5);
  EXPECT_DOUBLE_EQ(ag.pitchMm, 3.0);
  EXPECT_DOUBLE_EQ(ag.noseRadiusMm, 0.0625);
  const ThreadInsert n = parsed("27IRLN55");
  EXPECT_TRUE(n.internal);
  EXPECT_EQ(n.hand, "RL");
  EXPECT_EQ(n.profileDeg, 55);
  EXPECT_DOUBLE_EQ(n.minPitchMm, 3.5);
  EXPECT_DOUBLE_EQ(n.pitchMm, 5.0);
}

TEST(ThreadInsert, BadCodesPointAtTheCharacter) {
  const auto size = parseThreadInsert("17ER2ISO");
  ASSERT_TRUE(size.problem);
  EXPECT_EQ(size.problem->index, 0u);
  EXPECT_NE(size.problem->message.find("'17' is not a size"), std::string::npos);
  EXPECT_EQ(parseThreadInsert("16XR2ISO").problem->index, 2u);
  EXPECT_EQ(parseThreadInsert("16 EX 2 ISO").problem->index, 4u);  // spaces counted as written
  EXPECT_NE(parseThreadInsert("16ER2TR").problem->message.find("not one lathesim reads"), std::string::npos);
  EXPECT_NE(parseThreadInsert("16ERZZ60").problem->message.find("'ZZ' is not a partial-profile range"),
            std::string::npos);
  EXPECT_NE(parseThreadInsert("16ERISO").problem->message.find("is not a pitch"), std::string::npos);
  EXPECT_TRUE(looksLikeThreadInsert("16ER200ISO"));
  EXPECT_FALSE(looksLikeThreadInsert("CNMG120408"));
}

// The outline: the fundamental triangle of the pitch, its point the programmed point; an
// internal insert points outward (+X).
TEST(ThreadInsert, ExternalAndInternalOutlines) {
  const auto external = threadTool(60, 2.0, 0.25, std::nullopt, false);
  ASSERT_TRUE(external.tool);
  EXPECT_EQ(external.tool->tipNumber, 8);
  EXPECT_NEAR(external.tool->cutter.lowerBound().x(), 0.0, 1e-12);
  EXPECT_NEAR(external.tool->cutter.upperBound().y() - external.tool->cutter.lowerBound().y(), 2.0, 1e-12);
  const auto internal = threadTool(60, 1.5, 0.09375, std::nullopt, true);
  ASSERT_TRUE(internal.tool);
  EXPECT_EQ(internal.tool->tipNumber, 6);
  EXPECT_NEAR(internal.tool->cutter.upperBound().x(), 0.0, 1e-12);
  // It reaches inward the fundamental height 1.5/(2·tan 30°) from the sharp point, which lies
  // r·(1/sin 30° − 1) beyond the programmed point (the top of the nose).
  EXPECT_NEAR(internal.tool->cutter.lowerBound().x(), -(1.5 / (2 * std::tan(M_PI / 6)) - 0.09375), 1e-9);
  EXPECT_FALSE(threadTool(60, 2.0, 0.25, 8, true).tool);  // tip 8 is an external tool's
}

}  // namespace
}  // namespace lathesim
