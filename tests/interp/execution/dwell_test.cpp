// G04: a Dwell move where the tool stands, X/U in seconds, P in milliseconds.

#include <gtest/gtest.h>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::run;

TEST(Dwell, EachTimeWordGivesADwellMoveWhereTheToolStands) {
  const auto result = run("G00 X40 Z10\nG04 X2.5\nG04 U1\nG04 P1500\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const auto& moves = result.toolpath.moves;
  ASSERT_EQ(moves.size(), 4u);
  // X2.5 → 2.5 s, U1 → 1 s, P1500 → 1500 ms = 1.5 s; all at X40 Z10 = (20, 10).
  const double seconds[] = {2.5, 1.0, 1.5};
  for (int i = 0; i < 3; ++i) {
    const Move& m = moves[1 + i];
    SCOPED_TRACE(i);
    EXPECT_EQ(m.kind, MoveKind::Dwell);
    EXPECT_EQ(m.from, RZ(20, 10));
    EXPECT_EQ(m.to, RZ(20, 10));
    EXPECT_DOUBLE_EQ(m.dwellS, seconds[i]);
    EXPECT_EQ(m.line, 2 + i);
  }
}

TEST(Dwell, ZeroSecondsIsStillADwell) {
  const auto result = run("G04 X0\n");
  ASSERT_TRUE(result.ok());
  ASSERT_EQ(result.toolpath.moves.size(), 1u);
  EXPECT_EQ(result.toolpath.moves[0].kind, MoveKind::Dwell);
  EXPECT_EQ(result.toolpath.moves[0].dwellS, 0.0);
}

TEST(Dwell, XUnderG20IsStillSeconds) {
  const auto result = run("G20\nG04 X2\n");
  ASSERT_TRUE(result.ok());
  EXPECT_DOUBLE_EQ(result.toolpath.moves[0].dwellS, 2.0);
}

}  // namespace
}  // namespace lathesim::interp
