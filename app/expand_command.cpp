// lathesim expand: the toolpath CSV, streamed through a temporary file (commands.hpp).

#include <iostream>
#include <stdexcept>

#include "app/commands.hpp"
#include "app/printed_diagnostics.hpp"
#include "interp/text/machine_choice.hpp"
#include "interp/base/printable_text.hpp"
#include "interp/output/toolpath_csv_spool.hpp"

namespace lathesim::app {

int expandCommand(const setup::JobRequest& request) {
  interp::ToolpathCsvSpool csv;
  const auto job = printed(setup::loadJob(request, csv));
  if (!job) return setup::kExitBadInput;
  // The CSV is standard output's: the machine it was read for is said on standard error.
  std::cerr << "lathesim: " << interp::printable(request.program.string()) << ": "
            << interp::printable(interp::describeMachine(job->machine)) << '\n';
  csv.copyTo(std::cout);
  if (!std::cout.flush()) throw std::runtime_error("cannot write the toolpath to standard output");
  return setup::kExitOk;
}

}  // namespace lathesim::app
