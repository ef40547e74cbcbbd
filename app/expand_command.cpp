// lathesim expand: the toolpath CSV, streamed through a temporary file (commands.hpp).

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "app/commands.hpp"
#include "interp/toolpath_csv.hpp"

namespace lathesim::app {
namespace {

// The CSV rows, written to an unnamed temporary file (gone when closed, or when the process
// ends however it ends) until the run is known to be good.
class SpooledCsv final : public interp::MoveSink {
 public:
  SpooledCsv() : file_(std::tmpfile(), &std::fclose) {
    if (!file_) throw std::runtime_error(std::string("cannot make a temporary file for the toolpath: ") + std::strerror(errno));
    write(interp::toolpathCsvHeader());
  }
  void take(interp::Move move) override { write(interp::toolpathCsvRow(move)); }

  /// Everything written, to `out`; throws if the temporary file failed (a full disk).
  void copyTo(std::ostream& out) {
    if (std::fflush(file_.get()) != 0 || std::ferror(file_.get()))
      throw std::runtime_error(std::string("cannot write the toolpath to a temporary file: ") + std::strerror(errno));
    std::rewind(file_.get());
    char buffer[1 << 16];
    for (std::size_t got; (got = std::fread(buffer, 1, sizeof buffer, file_.get())) > 0;)
      out.write(buffer, static_cast<std::streamsize>(got));
    if (std::ferror(file_.get())) throw std::runtime_error("cannot read back the toolpath's temporary file");
    if (!out.flush()) throw std::runtime_error("cannot write the toolpath to standard output");
  }

 private:
  void write(const std::string& text) { std::fwrite(text.data(), 1, text.size(), file_.get()); }

  std::unique_ptr<std::FILE, decltype(&std::fclose)> file_;
};

}  // namespace

int expandCommand(const job::JobRequest& request) {
  SpooledCsv csv;
  if (!job::loadJob(request, csv)) return job::kExitBadInput;
  csv.copyTo(std::cout);
  return job::kExitOk;
}

}  // namespace lathesim::app
