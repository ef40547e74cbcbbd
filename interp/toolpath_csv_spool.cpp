#include "interp/toolpath_csv_spool.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

#include "interp/toolpath_csv.hpp"

namespace lathesim::interp {

ToolpathCsvSpool::ToolpathCsvSpool() : file_(std::tmpfile(), &std::fclose) {
  if (!file_) throw std::runtime_error(std::string("cannot make a temporary file for the toolpath: ") + std::strerror(errno));
  write(toolpathCsvHeader());
}

void ToolpathCsvSpool::take(Move move) { write(toolpathCsvRow(move)); }

void ToolpathCsvSpool::copyTo(std::ostream& out) {
  if (std::fflush(file_.get()) != 0 || std::ferror(file_.get()))
    throw std::runtime_error(std::string("cannot write the toolpath to a temporary file: ") + std::strerror(errno));
  std::rewind(file_.get());
  char buffer[1 << 16];
  for (std::size_t got; (got = std::fread(buffer, 1, sizeof buffer, file_.get())) > 0;)
    out.write(buffer, static_cast<std::streamsize>(got));
  if (std::ferror(file_.get())) throw std::runtime_error("cannot read back the toolpath's temporary file");
}

void ToolpathCsvSpool::write(const std::string& text) { std::fwrite(text.data(), 1, text.size(), file_.get()); }

}  // namespace lathesim::interp
