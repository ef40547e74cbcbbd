#pragma once
// What every command starts from: the setup read, the program interpreted. Diagnostics are
// printed as they are found; a job with errors is not returned.

#include <filesystem>
#include <optional>

#include "app/setup.hpp"
#include "interp/move.hpp"

namespace lathesim::app {

struct Job {
  Setup setup;
  interp::Toolpath toolpath;
  std::vector<interp::Diagnostic> warnings;
};

std::optional<Job> loadJob(const std::filesystem::path& program, const std::optional<std::filesystem::path>& setupFile);

}  // namespace lathesim::app
