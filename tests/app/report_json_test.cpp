// report.json as writeReport writes it (app/report.cpp): the report's tree with its block rows
// written one by one must be the very text nlohmann writes for the whole tree with the rows in
// it, whatever the rows and whatever the tree holds around them.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "app/report.hpp"
#include "sim/block_rows.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::app {
namespace {

using OrderedJson = nlohmann::ordered_json;

// A report with nested objects and arrays (empty ones too) before and after "blocks", and a
// note quoting bytes that are not UTF-8.
OrderedJson reportAround() {
  OrderedJson report;
  report["program"] = "part.nc";
  report["bar"] = {{"diameter_mm", 50.0}, {"length_mm", 112}, {"faces", OrderedJson::array({1, 2})}};
  report["collisions"] = OrderedJson::array();
  report["blocks"] = OrderedJson::array();
  report["notes"] = OrderedJson::array({{{"line", 3}, {"message", std::string("comment \xff\xfe here")}}});
  report["empty"] = OrderedJson::object();
  report["timing_s"] = {{"total", 1.25}};
  return report;
}

TEST(ReportJson, RowsWrittenInPlaceGiveTheTextOfTheWholeTree) {
  test::ScratchDir dir("report-json");
  for (const std::size_t count : {0u, 1u, 2u, 7u}) {
    std::vector<sim::BlockRemoval> rows;
    for (std::size_t i = 0; i < count; ++i)
      rows.push_back({static_cast<int>(i), static_cast<int>(i) + 1, 1, 0.1 * static_cast<double>(i) + 1e-9, 0.5});
    const auto file = dir.path() / ("report-" + std::to_string(count) + ".json");
    writeReport(reportAround(), sim::HeldBlockRows(rows), file);

    OrderedJson whole = reportAround();
    for (const sim::BlockRemoval& b : rows)
      whole["blocks"].push_back(
          {{"line", b.line}, {"column", b.column}, {"removed_volume_mm3", b.removedMm3}, {"time_s", b.timeS}});
    EXPECT_EQ(test::readFile(file), whole.dump(2, ' ', false, OrderedJson::error_handler_t::replace) + "\n") << count << " rows";
  }
}

TEST(ReportJson, AnEmptyReportIsAnEmptyObject) {
  test::ScratchDir dir("report-json-empty");
  writeReport(OrderedJson::object(), sim::HeldBlockRows({}), dir.path() / "report.json");
  EXPECT_EQ(test::readFile(dir.path() / "report.json"), "{}\n");
}

}  // namespace
}  // namespace lathesim::app
