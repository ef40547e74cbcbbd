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

/// What the command line overrides in the setup.
struct SetupOverrides {
  std::optional<interp::Dialect> dialect;    // --dialect: [machine] dialect
  std::optional<std::string> controlPreset;  // --control: the preset; the setup's [control] keys still apply
  std::optional<bool> blockSkip;             // --block-skip on|off: control.block_skip
};

/// The setup with the command line's overrides; nullopt (the problem printed) for an unknown
/// preset.
std::optional<Setup> overridden(Setup setup, const SetupOverrides& overrides);

std::optional<Job> loadJob(const std::filesystem::path& program, const std::optional<std::filesystem::path>& setupFile,
                           const SetupOverrides& overrides = {});

}  // namespace lathesim::job
