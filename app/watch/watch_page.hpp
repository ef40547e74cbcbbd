#pragma once
// What `lathesim watch` adds to the report.html it serves: a script that asks the watcher every
// 0.7 s how its runs went, reloads the page (at the same place in it) when a run has written
// new outputs, shows "running…" while one is under way, and shows a failed run's diagnostics
// in a red banner above the last good part, which stays as it was.

#include <string>

namespace lathesim::app {

/// How the watcher's runs stand, as /watch/state says it (JSON).
struct WatchState {
  int generation = 0;      // runs finished
  int goodGeneration = 0;  // the last run that wrote its outputs (0: none yet)
  bool running = false;
  int status = 0;          // the last finished run's exit status
  std::string error;       // its diagnostics (stderr), when it wrote no outputs
};

std::string stateJson(const WatchState& state);

/// `html` (a report.html) with the following script added before its </body>.
std::string withWatchScript(std::string html, const WatchState& served);

/// The page served when no run has written a report yet: the diagnostics, and the script.
std::string waitingPage(const WatchState& state);

}  // namespace lathesim::app
