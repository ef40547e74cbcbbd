#include "interp/output/toolpath_csv_spool.hpp"

#include "interp/output/toolpath_csv.hpp"

namespace lathesim::interp {

ToolpathCsvSpool::ToolpathCsvSpool() { file_.append(toolpathCsvHeader()); }

void ToolpathCsvSpool::take(Move move) { file_.append(toolpathCsvRow(move)); }

void ToolpathCsvSpool::copyTo(std::ostream& out) const {
  file_.readBack(1 << 16, [&](std::string_view chunk) { out.write(chunk.data(), static_cast<std::streamsize>(chunk.size())); });
}

}  // namespace lathesim::interp
