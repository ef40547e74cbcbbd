#pragma once
// Comparing a toolpath with a golden toolpath.csv, shared by the interp, parts and
// command-line tests.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "interp/toolpath_csv.hpp"

namespace lathesim::test {

/// The rows toolpath.csv would hold for these moves, without the CSV's rounding.
inline std::vector<interp::CsvRow> rowsOf(const interp::Toolpath& toolpath) {
  std::vector<interp::CsvRow> rows;
  for (const interp::Move& m : toolpath.moves)
    rows.push_back({m.line, interp::kindName(m.kind), diameterOf(m.from), m.from.y(), diameterOf(m.to), m.to.y(), m.feed});
  return rows;
}

/// Row by row; `label` names the golden file in failure messages.
inline void expectSameRows(const std::vector<interp::CsvRow>& actual, const std::vector<interp::CsvRow>& golden,
                           const std::string& label, double tolerance = 1e-9) {
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
  }
}

}  // namespace lathesim::test
