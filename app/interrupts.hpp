#pragma once
// Ctrl-C (SIGINT) or SIGTERM during a run: the files it was writing and the output folders it
// made are removed, and the process exits 130 or 143 (128 + the signal) at once, even in the
// middle of a simulation, a mesh or a render. The handler only unlinks, removes empty
// folders and writes one line (async-signal-safe calls), from any thread the signal lands on.
// A signal that arrives while the outputs are being renamed into place waits until they all
// are: the folder then holds the whole run, never part of it.

#include <filesystem>

namespace lathesim::app {

/// Installs the handlers for SIGINT and SIGTERM (and SIGHUP: the terminal went away).
void removeOutputsOnInterrupt();

/// What the handler removes: staged files (unlinked) and folders the run made (removed if
/// empty, most recently registered first). Registered paths stay until forgotten.
class InterruptCleanup {
 public:
  static void addFile(const std::filesystem::path& file);
  static void addFolder(const std::filesystem::path& folder);
  static void forget(const std::filesystem::path& path);

  /// Between these two a signal only marks itself; endCommit() then exits if one came.
  static void beginCommit();
  static void endCommit();
};

}  // namespace lathesim::app
