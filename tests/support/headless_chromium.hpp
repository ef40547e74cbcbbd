#pragma once
// Opening a page in Debian's headless Chromium from a test, with the flags that work on this
// machine, and reading back what the page wrote to its console.

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/lathesim_process.hpp"

namespace lathesim::test {

inline const std::filesystem::path kChromium = "/usr/bin/chromium";

struct BrowserRun {
  ProcessOutcome outcome;
  std::vector<std::string> consoleLines;  // what the page wrote to its console, errors included
};

/// Opens `url` in a fresh headless Chromium and `extra` flags (--screenshot=…, --dump-dom).
/// `networkOff`: inside a network namespace of its own with no interface up (unshare -n,
/// as root), so that nothing can be fetched.
inline BrowserRun openInChromium(const ScratchDir& dir, const std::string& url, const std::vector<std::string>& extra,
                                 bool networkOff = false) {
  static int profile = 0;
  std::vector<std::string> args{"--headless",
                                "--no-sandbox",
                                "--disable-gpu",
                                "--disable-quic",
                                "--no-first-run",
                                "--disable-background-networking",
                                "--disable-component-update",
                                "--disable-sync",
                                "--user-data-dir=" + (dir.path() / ("profile" + std::to_string(profile++))).string(),
                                "--enable-logging=stderr",
                                "--v=0",
                                "--window-size=1400,1000"};
  args.insert(args.end(), extra.begin(), extra.end());
  args.push_back(url);
  BrowserRun run;
  if (networkOff) {
    args.insert(args.begin(), {"--net", kChromium.string()});
    run.outcome = runProcess("/usr/bin/unshare", args, dir.path());
  } else {
    run.outcome = runProcess(kChromium, args, dir.path());
  }
  std::istringstream lines(run.outcome.err);
  for (std::string line; std::getline(lines, line);)
    if (line.find(":CONSOLE") != std::string::npos) run.consoleLines.push_back(line);
  return run;
}

}  // namespace lathesim::test
