#pragma once
// Resuming a batch: a job's stamp file, written last into its folder, holds a hash of the
// job's inputs and its result. A job whose inputs hash the same as its stamp's is not run
// again; its result is read from the stamp.

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "batch/batch_job.hpp"
#include "batch/job_result.hpp"

namespace lathesim::batch {

inline constexpr const char* kStampFileName = "batch-stamp.json";

/// The hash of what a job's result depends on: the lathesim build, the command (run or
/// check and every option), the contents of the program and of every file an argument
/// names (setup, drawing, …), and of every file M98 could read a subprogram from (named
/// O1234.nc and the like, interp/text/program_library.hpp) in the program's folder and the
/// --programs folders — not their paths, so a moved folder keeps its results.
class InputStamper {
 public:
  explicit InputStamper(std::string buildId) : buildId_(std::move(buildId)) {}
  std::string stampOf(const BatchJob& job);

 private:
  /// The names and contents of a folder's program files, hashed once per batch.
  const std::string& programFilesHash(const std::filesystem::path& folder);
  std::string buildId_;
  std::map<std::filesystem::path, std::string> folderHashes_;
};

/// Writes the stamp (atomically: a temporary renamed into place).
void writeStamp(const std::filesystem::path& folder, const std::string& inputs, const JobResult& result);

/// The result stamped in `folder` if its inputs are `inputs` and it still stands: a job
/// that crashed is run again, and one that timed out only keeps its result under the same
/// time limit. nullopt otherwise (no stamp, a different one, or an unreadable one).
std::optional<JobResult> stampedResult(const std::filesystem::path& folder, const std::string& inputs,
                                       const BatchJob& job);

}  // namespace lathesim::batch
