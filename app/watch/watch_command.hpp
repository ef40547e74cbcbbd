#pragma once
// `lathesim watch`: runs a program (as `lathesim run`, or as `lathesim check` when a drawing is
// given), then runs it again whenever one of its input files is saved, and serves the output
// folder's report.html on 127.0.0.1, where the open page follows the runs (app/watch/watch_page.hpp).
// Each run is a process of its own (the command's own `run` or `check`), so a run that fails
// or crashes leaves the watcher and the last good outputs as they were. Ctrl-C stops it: the
// run under way is stopped as a run is (app/interrupts.hpp) and the watcher exits 130.

#include <string>
#include <vector>

namespace lathesim::app {

struct WatchOptions {
  int port = 0;                        // 0: a free one the system chooses
  std::vector<std::string> arguments;  // run's (or check's) program and options, as given
};

int watchCommand(const WatchOptions& options);

}  // namespace lathesim::app
