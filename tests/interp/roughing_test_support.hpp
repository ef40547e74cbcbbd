#pragma once
// Helpers for the G71/G72 tests: contours written segment by segment, and leg lists compared
// with hand-worked ones to 1e-9 mm (the expansions compute positions, so exact equality of
// doubles is not expected).

#include <gtest/gtest.h>

#include <string_view>
#include <vector>

#include "interp/contour.hpp"
#include "interp/cycle_leg.hpp"
#include "interp/result.hpp"

namespace lathesim::interp::test {

/// A straight contour segment (r, z in mm, radius) made by the block on `line`, column 1.
inline ContourSegment segment(MoveKind kind, double r0, double z0, double r1, double z1,
                              int line) {
  return {kind, RZ(r0, z0), RZ(r1, z1), RZ(0, 0), line, 1};
}

/// An arc contour segment about (rc, zc).
inline ContourSegment arcSegment(MoveKind kind, double r0, double z0, double r1, double z1,
                                 double rc, double zc, int line) {
  return {kind, RZ(r0, z0), RZ(r1, z1), RZ(rc, zc), line, 1};
}

/// A leg as worked out by hand: positions are (radius, Z) in mm; the centre only for arcs.
struct HandLeg {
  MoveKind kind;
  double r0, z0, r1, z1;
  int step;
  double rc = 0, zc = 0;
};

inline void expectLegsNear(const std::vector<CycleLeg>& legs,
                           const std::vector<HandLeg>& expected) {
  ASSERT_EQ(legs.size(), expected.size());
  for (std::size_t i = 0; i < legs.size(); ++i) {
    SCOPED_TRACE(testing::Message() << "leg " << i);
    const HandLeg& e = expected[i];
    EXPECT_EQ(legs[i].kind, e.kind);
    EXPECT_NEAR(legs[i].from.x(), e.r0, 1e-9);
    EXPECT_NEAR(legs[i].from.y(), e.z0, 1e-9);
    EXPECT_NEAR(legs[i].to.x(), e.r1, 1e-9);
    EXPECT_NEAR(legs[i].to.y(), e.z1, 1e-9);
    EXPECT_EQ(legs[i].step, e.step);
    if (isArc(e.kind)) {
      EXPECT_NEAR(legs[i].center.x(), e.rc, 1e-9);
      EXPECT_NEAR(legs[i].center.y(), e.zc, 1e-9);
    }
  }
}

/// The expansion failed at line:column with a message containing `part`.
inline void expectRoughingError(const Result<std::vector<CycleLeg>>& result, int line,
                                int column, std::string_view part) {
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().line, line) << result.error().message;
  EXPECT_EQ(result.error().column, column) << result.error().message;
  EXPECT_NE(result.error().message.find(part), std::string::npos)
      << "message: " << result.error().message;
}

}  // namespace lathesim::interp::test
