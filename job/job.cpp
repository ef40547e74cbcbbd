#include "job/job.hpp"

#include <fstream>
#include <iostream>
#include <sstream>

#include "interp/motion/cycle_time.hpp"
#include "interp/interpreter.hpp"
#include "job/control_setup.hpp"

namespace lathesim::job {
namespace {

void print(const std::vector<interp::Diagnostic>& diagnostics) {
  for (const auto& d : diagnostics) std::cerr << interp::format(d) << '\n';
}

bool hasError(const std::vector<interp::Diagnostic>& diagnostics) {
  for (const auto& d : diagnostics)
    if (d.severity == interp::Severity::Error) return true;
  return false;
}

}  // namespace

interp::InterpreterOptions interpreterOptionsOf(const Setup& setup) {
  interp::InterpreterOptions options;
  options.startPosition = setup.startPosition;
  options.referencePosition = setup.referencePosition;
  options.machine = setup.machine;
  options.machine.travel = travelOf(setup);
  options.dialect = setup.dialect;
  options.control = setup.control.parameters;
  options.offsets = setup.offsets;
  for (const auto& tool : setup.tools) options.toolNumbers.push_back(tool.number);
  return options;
}

interp::Diagnostic Job::warningAt(int line, int column, std::string message) const {
  return {interp::Severity::Warning, toolpath.programName, line, column, std::move(message),
          interp::lineOf(programText, line)};
}

std::optional<Setup> overridden(Setup setup, const SetupOverrides& overrides) {
  if (overrides.dialect) setup.dialect = *overrides.dialect;
  if (overrides.controlPreset) {
    std::optional<interp::Control> chosen = withPreset(setup.control, *overrides.controlPreset);
    if (!chosen) {
      std::string names;
      for (std::string_view n : interp::controlPresets()) names += (names.empty() ? "" : ", ") + std::string(n);
      std::cerr << "lathesim: error: --control " << *overrides.controlPreset << ": no such control preset (expected "
                << names << ")\n";
      return std::nullopt;
    }
    setup.control = std::move(*chosen);
  }
  if (overrides.blockSkip)
    (void)setup.control.set("block_skip", std::string(*overrides.blockSkip ? "on" : "off"), "command line");
  return setup;
}

std::optional<Job> loadJob(const std::filesystem::path& program, const std::optional<std::filesystem::path>& setupFile,
                           const SetupOverrides& overrides) {
  Job job{defaultSetup(), {}, {}, {}};
  if (setupFile) {
    SetupResult loaded = loadSetup(*setupFile);
    print(loaded.diagnostics);
    if (!loaded.setup || hasError(loaded.diagnostics)) return std::nullopt;
    job.setup = std::move(*loaded.setup);
    job.warnings = std::move(loaded.diagnostics);  // what is left are warnings (e.g. an insert that
                                                   // does not match its holder's seat)
  }
  std::optional<Setup> setup = overridden(std::move(job.setup), overrides);
  if (!setup) return std::nullopt;
  job.setup = std::move(*setup);

  std::ifstream in(program, std::ios::binary);
  if (!in) {
    std::cerr << program.string() << ": error: cannot read the program file\n";
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();

  job.programText = text.str();
  interp::InterpretResult result =
      interp::interpret(job.programText, program.string(), interpreterOptionsOf(job.setup));
  print(result.diagnostics);
  if (!result.ok()) return std::nullopt;
  for (auto& d : result.diagnostics)
    if (d.severity == interp::Severity::Warning) job.warnings.push_back(std::move(d));
  job.toolpath = std::move(result.toolpath);
  for (const interp::Error& w : interp::assignMoveTimes(job.toolpath, job.setup.machine)) {
    job.warnings.push_back(job.warningAt(w.line, w.column, w.message));
    print({job.warnings.back()});
  }
  return job;
}

}  // namespace lathesim::job
