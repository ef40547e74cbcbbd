// Tools named in comments: what each kind of comment mounts, and what it does not.

#include "setup/comment_tools.hpp"

#include <gtest/gtest.h>

#include "geometry/iso_holder.hpp"
#include "geometry/iso_insert.hpp"
#include "geometry/tool_shape.hpp"

namespace lathesim::setup {
namespace {

constexpr double kBarMm = 40.0;

void expectSameOutline(const ConvexPolygon& a, const ConvexPolygon& b) {
  ASSERT_EQ(a.vertices().size(), b.vertices().size());
  for (std::size_t i = 0; i < a.vertices().size(); ++i) EXPECT_LT((a.vertices()[i] - b.vertices()[i]).norm(), 1e-12);
}

TEST(CommentTools, IsoInsertsWithTheUsualOrTheNamedHolder) {
  struct Case {
    std::string comment;
    std::string insert, holder;
  };
  const Case cases[] = {
      {"CNMG 120408", "CNMG120408", "PCLNR2525M12"},
      {"OD ROUGH - CNMG120408-PM", "CNMG120408", "PCLNR2525M12"},
      {"VBMT160404 R0.4", "VBMT160404", "SVJBR2525M16"},
      {"FINISH DNMG 150608 PDJNR2525M15", "DNMG150608", "PDJNR2525M15"},
      {"tnmg 160408", "TNMG160408", "PTGNR2525M16"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.comment);
    const auto named = toolNamedIn(c.comment, 4, kBarMm);
    ASSERT_TRUE(named.has_value());
    EXPECT_EQ(named->tool.number, 4);
    const auto built = turningTool(*parseIsoInsert(c.insert).value, *parseIsoHolder(c.holder).value, std::nullopt);
    ASSERT_TRUE(built.tool.has_value());
    expectSameOutline(named->tool.outline, built.tool->cutter);
    EXPECT_DOUBLE_EQ(named->tool.noseRadiusMm, built.tool->noseRadiusMm);
    EXPECT_NE(named->description.find(c.holder), std::string::npos) << named->description;
  }
}

TEST(CommentTools, KindsWithTheirSizes) {
  auto groove = toolNamedIn("parting tool 3mm", 5, kBarMm);
  ASSERT_TRUE(groove.has_value());
  expectSameOutline(groove->tool.outline, grooveTool(3.0, 0, 0, 25.0, 3).tool->cutter);  // depth: 20 + 5
  groove = toolNamedIn("GROOVE W2.5", 6, kBarMm);
  ASSERT_TRUE(groove.has_value());
  expectSameOutline(groove->tool.outline, grooveTool(2.5, 0, 0, 25.0, 3).tool->cutter);
  const auto drill = toolNamedIn("DRILL 12", 7, kBarMm);
  ASSERT_TRUE(drill.has_value());
  expectSameOutline(drill->tool.outline, drillTool(12.0, 118.0, 120.0).tool->cutter);
  const auto drill2 = toolNamedIn("Ø8.5 DRILL", 7, kBarMm);
  ASSERT_TRUE(drill2.has_value());
  expectSameOutline(drill2->tool.outline, drillTool(8.5, 118.0, 85.0).tool->cutter);
  const auto thread = toolNamedIn("THREAD M20X1.5", 8, kBarMm);
  ASSERT_TRUE(thread.has_value());
  expectSameOutline(thread->tool.outline, threadTool(60.0, 1.5, 0.1875, 8).tool->cutter);
  const auto partial = toolNamedIn("THREAD 55 DEG", 8, kBarMm);
  ASSERT_TRUE(partial.has_value());
  expectSameOutline(partial->tool.outline, threadTool(55.0, 3.0, 0.0625, 8).tool->cutter);
}

TEST(CommentTools, CommentsThatNameNoToolMountNothing) {
  for (std::string_view comment : {"OD ROUGH", "GROOVE", "DRILL", "FINISH PASS 0.2MM", "T1 D=0.8 CR=0.4", "BORING BAR", "PART NO 1234 4MM"}) {
    SCOPED_TRACE(std::string(comment));
    EXPECT_FALSE(toolNamedIn(std::string(comment), 1, kBarMm).has_value());
  }
}

}  // namespace
}  // namespace lathesim::setup

namespace lathesim::setup {
namespace {

// A comment of 300 000 characters overflowed the stack in std::regex (a crash); a drill of
// 400 digits made std::stod throw. Neither names a drill; a pitch of 400 digits is no pitch
// (the partial-profile insert); the usual comment still names its tool.
TEST(CommentTools, VeryLongCommentsAndNumbersAreReadWithoutHarm) {
  EXPECT_FALSE(toolNamedIn("DRILL " + std::string(300000, '1'), 5, kBarMm));
  EXPECT_FALSE(toolNamedIn("DRILL " + std::string(400, '9'), 5, kBarMm));
  const auto thread = toolNamedIn("THREAD 60 DEG P" + std::string(400, '9'), 5, kBarMm);
  ASSERT_TRUE(thread);
  EXPECT_NE(thread->description.find("partial-profile"), std::string::npos) << thread->description;
  EXPECT_TRUE(toolNamedIn("DRILL 12" + std::string(300000, ' '), 5, kBarMm));
}

// Found by the ISO code harness: this comment drew its 69 km nose with 300 000 chords.
TEST(CommentTools, AThreadOfAbsurdPitchIsDrawnAtOnce) {
  const auto thread = toolNamedIn("THREAD 55 DEG\xa0P555555552", 3, kBarMm);
  ASSERT_TRUE(thread);
  EXPECT_LT(thread->tool.outline.vertices().size(), 3000u);
}

}  // namespace
}  // namespace lathesim::setup
