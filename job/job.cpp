#include "job/job.hpp"

#include <fstream>
#include <iostream>
#include <sstream>

#include "interp/motion/cycle_time.hpp"
#include "interp/interpreter.hpp"

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
  options.dialect = setup.dialect;
  options.initialFeedMode = setup.initialFeedMode;
  options.offsets = setup.offsets;
  options.threadRunoutLeads = setup.threadRunoutLeads;
  for (const auto& tool : setup.tools) options.toolNumbers.push_back(tool.number);
  return options;
}

interp::Diagnostic Job::warningAt(int line, int column, std::string message) const {
  return {interp::Severity::Warning, toolpath.programName, line, column, std::move(message),
          interp::lineOf(programText, line)};
}

std::optional<Job> loadJob(const std::filesystem::path& program, const std::optional<std::filesystem::path>& setupFile,
                           std::optional<interp::Dialect> dialect) {
  Job job{defaultSetup(), {}, {}, {}};
  if (setupFile) {
    SetupResult loaded = loadSetup(*setupFile);
    print(loaded.diagnostics);
    if (!loaded.setup || hasError(loaded.diagnostics)) return std::nullopt;
    job.setup = std::move(*loaded.setup);
    job.warnings = std::move(loaded.diagnostics);  // what is left are warnings (e.g. an insert that
                                                   // does not match its holder's seat)
  }
  if (dialect) job.setup.dialect = *dialect;

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
