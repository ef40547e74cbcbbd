#pragma once
// One program of a batch: what to run, with which setup and drawing, and where its outputs go.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lathesim::batch {

/// What a job may set. The command line's batch options, a manifest's [defaults] and the
/// job's own keys are layered in that order (see over()).
struct JobSettings {
  std::optional<std::filesystem::path> setup;
  /// A drawing to check the part against (`check --target`). An empty path means "no
  /// drawing", overriding a default one.
  std::optional<std::filesystem::path> drawing;
  std::optional<std::filesystem::path> targetProgram;  // `check --target-program`
  std::optional<double> toleranceMm;                   // `check --tol`
  std::optional<double> voxelMm;                       // `--voxel`
  std::optional<double> timeLimitS;                    // the job is killed after this wall time
  /// Further options for `lathesim run`/`check`, passed through as given (e.g. --dialect hnc).
  std::vector<std::string> options;

  /// These settings with every unset one taken from `base`; options are base's, then these.
  JobSettings over(const JobSettings& base) const;
};

struct BatchJob {
  int index = 0;     // 0-based place in the manifest: the order of the summary
  std::string name;  // unique in the batch; the job's output folder under the batch's
  std::filesystem::path program;
  JobSettings settings;
  int manifestLine = 0;  // where the manifest lists it (0: found in a folder)

  bool checksDrawing() const;  // `check` rather than `run`
};

/// The lathesim arguments that run `job` with its outputs in `folder`:
/// run|check PROGRAM [--setup S] [--target D | --target-program P] [--tol T] [--voxel V] OPTIONS… --out FOLDER.
std::vector<std::string> commandArguments(const BatchJob& job, const std::filesystem::path& folder);

/// The values `options` gives option `name`: the words after it up to the next option, or
/// what follows '=' (`--programs a b`, `--stock=D40xL80`), for every time it is given.
std::vector<std::string> optionValues(const std::vector<std::string>& options, const std::string& name);

/// Options a job may not pass through because the batch sets them itself (from its keys).
/// Returns the key to use instead, or nullopt if `option` may be passed through.
std::optional<std::string> reservedOption(const std::string& option);

}  // namespace lathesim::batch
