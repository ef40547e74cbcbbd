#pragma once
// The lathesim subcommands. Each returns the process exit status:
// 0 done, 1 bad input (diagnostics printed, no output written).

#include <filesystem>
#include <optional>

namespace lathesim::app {

/// The voxel size used when neither --voxel nor [sim] voxel says: the default part runs in
/// about a second with it, and volumes come within a few hundredths of a percent.
inline constexpr double kDefaultVoxelMm = 0.2;

/// Mesh adaptivity of the exported part: merges facets on flat and gently curved faces so a
/// Φ125 part at 0.1 mm stays in the tens of MB, without visible faceting.
inline constexpr double kExportAdaptivity = 0.05;

struct RunOptions {
  std::filesystem::path program;
  std::optional<std::filesystem::path> setup;
  std::filesystem::path out = "out";
  std::optional<double> voxelMm;
};

int runCommand(const RunOptions& options);

int expandCommand(const std::filesystem::path& program, const std::optional<std::filesystem::path>& setup);

}  // namespace lathesim::app
