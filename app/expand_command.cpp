// lathesim expand: the toolpath CSV, streamed through a temporary file (commands.hpp).

#include <iostream>
#include <stdexcept>

#include "app/commands.hpp"
#include "interp/toolpath_csv_spool.hpp"

namespace lathesim::app {

int expandCommand(const job::JobRequest& request) {
  interp::ToolpathCsvSpool csv;
  if (!job::loadJob(request, csv)) return job::kExitBadInput;
  csv.copyTo(std::cout);
  if (!std::cout.flush()) throw std::runtime_error("cannot write the toolpath to standard output");
  return job::kExitOk;
}

}  // namespace lathesim::app
