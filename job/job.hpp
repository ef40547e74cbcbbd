#pragma once
// What every command starts from: the setup read, the program interpreted. Diagnostics are
// printed as they are found; a job with errors is not returned.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "job/setup.hpp"
#include "interp/control/dialect.hpp"
#include "interp/interpreter.hpp"
#include "interp/move.hpp"

namespace lathesim::job {

struct Job {
  Setup setup;
  interp::Toolpath toolpath;  // every move's timeS filled in
  std::vector<interp::Diagnostic> warnings;
  std::string programText;

  /// A warning located in the program, ready to print and report.
  interp::Diagnostic warningAt(int line, int column, std::string message) const;
};

/// What the interpreter needs to know of the setup: start, reference, machine, dialect, tools.
interp::InterpreterOptions interpreterOptionsOf(const Setup& setup);

/// `dialect`, when given (--dialect), overrides the setup's [machine] dialect; `maxSteps`
/// (--max-steps) its [macro] max_steps.
std::optional<Job> loadJob(const std::filesystem::path& program, const std::optional<std::filesystem::path>& setupFile,
                           std::optional<interp::Dialect> dialect = std::nullopt,
                           std::optional<long long> maxSteps = std::nullopt);

}  // namespace lathesim::job
