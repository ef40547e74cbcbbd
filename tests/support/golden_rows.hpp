#pragma once
// Comparing a toolpath with a golden toolpath.csv, shared by the interp, parts and
// command-line tests.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "interp/output/toolpath_csv.hpp"

namespace lathesim::test {

/// The rows toolpath.csv would hold for these moves, without the CSV's rounding.
inline std::vector<interp::CsvRow> rowsOf(const interp::Toolpath& toolpath) {
  std::vector<interp::CsvRow> rows;
  for (const interp::Move& m : toolpath.moves) {
    interp::CsvRow row;
    row.line = m.line;
    row.kind = interp::kindName(m.kind);
    row.x0 = diameterOf(m.from);
    row.z0 = m.from.y();
    row.x1 = diameterOf(m.to);
    row.z1 = m.to.y();
    row.feed = m.feed;
    if (interp::isArc(m.kind)) {
      row.xc = diameterOf(m.center);
      row.zc = m.center.y();
    }
    row.timeS = m.timeS;
    if (m.kind == interp::MoveKind::Thread) {
      row.threadDeg = m.thread.startAngleDeg;
      row.spindle = m.spindleDirection == interp::SpindleDirection::Clockwise ? "cw" : "ccw";
    }
    rows.push_back(row);
  }
  return rows;
}

/// Row by row; `label` names the golden file in failure messages. An arc's centre is
/// compared whenever the golden row is an arc; times only when the golden file has them,
/// within `relativeTimeTolerance` (the CSV rounds them to 4 decimals).
inline void expectSameRows(const std::vector<interp::CsvRow>& actual, const std::vector<interp::CsvRow>& golden,
                           const std::string& label, double tolerance = 1e-9,
                           double relativeTimeTolerance = 1e-3) {
  ASSERT_EQ(actual.size(), golden.size()) << label;
  for (std::size_t i = 0; i < golden.size(); ++i) {
    SCOPED_TRACE(testing::Message() << label << " row " << i + 1 << " (line " << golden[i].line << ")");
    EXPECT_EQ(actual[i].line, golden[i].line);
    EXPECT_EQ(actual[i].kind, golden[i].kind);
    EXPECT_NEAR(actual[i].x0, golden[i].x0, tolerance);
    EXPECT_NEAR(actual[i].z0, golden[i].z0, tolerance);
    EXPECT_NEAR(actual[i].x1, golden[i].x1, tolerance);
    EXPECT_NEAR(actual[i].z1, golden[i].z1, tolerance);
    EXPECT_NEAR(actual[i].feed, golden[i].feed, tolerance);
    EXPECT_EQ(actual[i].xc.has_value(), golden[i].xc.has_value());
    if (actual[i].xc && golden[i].xc) {
      EXPECT_NEAR(*actual[i].xc, *golden[i].xc, tolerance);
      EXPECT_NEAR(*actual[i].zc, *golden[i].zc, tolerance);
    }
    if (golden[i].threadDeg) {  // a golden file with the thread columns: a thread row's angle and spindle
      ASSERT_TRUE(actual[i].threadDeg.has_value());
      EXPECT_NEAR(*actual[i].threadDeg, *golden[i].threadDeg, 1e-4);  // the CSV's rounding
      EXPECT_EQ(actual[i].spindle, golden[i].spindle);
    }
    if (actual[i].timeS && golden[i].timeS) {
      EXPECT_NEAR(*actual[i].timeS, *golden[i].timeS, relativeTimeTolerance * *golden[i].timeS + 1e-4);
    }
  }
}

}  // namespace lathesim::test
