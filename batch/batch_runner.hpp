#pragma once
// `lathesim batch`: runs every job of a manifest or folder (or of one shard of it), each as
// its own lathesim process with its own output folder and time limit, as many at once as
// the cores and memory allow, and writes the summary. One X display serves every job.
// Jobs whose inputs have not changed since their result was stamped are not run again.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>

#include "batch/batch_job.hpp"
#include "batch/child_process.hpp"
#include "batch/shard.hpp"

namespace lathesim::batch {

/// The log a job's lathesim writes in its folder (its stdout and stderr).
inline constexpr const char* kJobLogFileName = "lathesim.log";

/// What the command that runs a batch does for its jobs' processes (app/ gives render/'s):
struct JobPreparation {
  /// Before the first job starts, once: what every job inherits (a display to draw on: one for
  /// all of them, rather than one each).
  std::function<void()> beforeJobs;
  /// When jobs are forked from the batch, started once before the first: work done while the
  /// first jobs run (learning which libraries drawing loads) that is finished in the batch by
  /// calling what it returns until that says true, so that each job forked after finds it done
  /// (the libraries loaded). It must start no thread.
  std::function<std::function<bool()>()> forForks;
};

struct BatchOptions {
  std::filesystem::path source;  // a .toml or .csv manifest, or a folder of programs
  std::filesystem::path out = "out";
  JobSettings defaults;                      // --setup, --target, --tol, --voxel, --time-limit
  std::optional<int> jobs;                   // at most this many at once (default: the CPUs)
  std::optional<std::uint64_t> memoryBytes;  // what the jobs may fill together (default: 80 % of what is free)
  Shard shard;
  std::filesystem::path binary;  // the lathesim that runs the jobs (default: this executable)
  /// When given, a job runs in a fork of the batch that calls this with the job's arguments,
  /// rather than in `binary` started anew — as long as the batch has no more threads than
  /// `threadsAtStart` (threadCount() before it started any work: the libraries' own).
  InProcessMain jobMain;
  int threadsAtStart = 0;
  /// How the command prepares the processes the batch starts; batch/ itself knows nothing of
  /// what they draw with. Either may be empty.
  JobPreparation preparation;
};

/// The batch's exit status: 0 every job passed, 1 some failed (or the manifest is bad: its
/// diagnostics are printed, nothing is run), 3 some parts out of tolerance; 128 + the signal
/// when SIGINT, SIGTERM or SIGHUP stopped it (the finished jobs' results are kept).
int runBatch(const BatchOptions& options);

}  // namespace lathesim::batch
