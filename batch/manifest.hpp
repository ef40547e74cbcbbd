#pragma once
// The jobs of a batch: from a manifest (TOML or CSV) or from a folder of programs.
//
// TOML: an optional [defaults] table and one [[job]] table per program, each with the keys
// program (required), name, setup, drawing, target_program, tolerance, voxel, time_limit
// and options (a list of further `lathesim run`/`check` options). CSV: a header row naming
// the same columns (options as words separated by spaces), then one row per job; an empty
// cell leaves the default. Paths are relative to the manifest's folder.
//
// A folder: every program (*.nc, *.ngc, *.tap, *.cnc, *.gcode) in it and in its immediate
// subfolders, in path order; a program's setup is the setup.toml beside it, its drawing the
// drawing.toml or drawing.stl beside it, else the batch's defaults. A job's name is the
// program's path without extension, '/' written '-'; a subfolder's program.nc is named
// after the subfolder.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "batch/batch_job.hpp"
#include "interp/base/diagnostic.hpp"

namespace lathesim::batch {

struct JobList {
  std::optional<std::vector<BatchJob>> jobs;  // nullopt when there are errors
  std::vector<interp::Diagnostic> diagnostics;
};

/// The jobs `source` (a .toml or .csv manifest, or a folder) names, every job's settings
/// layered over `defaults` (the batch's command-line options).
JobList readJobs(const std::filesystem::path& source, const JobSettings& defaults);

JobList readTomlManifest(const std::filesystem::path& file, const JobSettings& defaults);
JobList readCsvManifest(const std::filesystem::path& file, const JobSettings& defaults);
JobList jobsInFolder(const std::filesystem::path& folder, const JobSettings& defaults);

/// A job's default name: the program's file name without extension, or for a file named
/// program.* its folder's name.
std::string defaultJobName(const std::filesystem::path& program);

/// Why `name` cannot name a job's output folder (empty, '/', "..", a summary file's name),
/// or nullopt.
std::optional<std::string> badJobName(const std::string& name);

/// Adds a diagnostic for every job whose name is bad or another job took first (at the
/// job's line of `sourceText`, the manifest's text); false if any.
bool checkNamesUnique(const std::vector<BatchJob>& jobs, const std::filesystem::path& source, std::string_view sourceText,
                      std::vector<interp::Diagnostic>& diagnostics);

}  // namespace lathesim::batch
