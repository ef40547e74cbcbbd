#include "app/job.hpp"

#include <fstream>
#include <iostream>
#include <sstream>

#include "interp/interpreter.hpp"

namespace lathesim::app {
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

std::optional<Job> loadJob(const std::filesystem::path& program, const std::optional<std::filesystem::path>& setupFile) {
  Job job{defaultSetup(), {}, {}};
  if (setupFile) {
    SetupResult loaded = loadSetup(*setupFile);
    print(loaded.diagnostics);
    if (!loaded.setup || hasError(loaded.diagnostics)) return std::nullopt;
    job.setup = std::move(*loaded.setup);
  }

  std::ifstream in(program, std::ios::binary);
  if (!in) {
    std::cerr << program.string() << ": error: cannot read the program file\n";
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();

  interp::InterpreterOptions options;
  options.startPosition = job.setup.startPosition;
  for (const auto& tool : job.setup.tools) options.toolNumbers.push_back(tool.number);
  options.offsets = job.setup.offsets;
  interp::InterpretResult result = interp::interpret(text.str(), program.string(), options);
  print(result.diagnostics);
  if (!result.ok()) return std::nullopt;
  for (auto& d : result.diagnostics)
    if (d.severity == interp::Severity::Warning) job.warnings.push_back(std::move(d));
  job.toolpath = std::move(result.toolpath);
  return job;
}

}  // namespace lathesim::app
