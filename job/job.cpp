#include "job/job.hpp"

#include <fstream>
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "interp/motion/cycle_time.hpp"
#include "interp/text/stated_stock.hpp"
#include "job/stock_option.hpp"
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
  options.workOffsets = setup.workOffsets;
  options.machineZero = setup.machineZero;
  for (const auto& tool : setup.tools) options.toolNumbers.push_back(tool.number);
  return options;
}

interp::Diagnostic Job::warningAt(int line, int column, std::string message) const {
  return {interp::Severity::Warning, toolpath.programName, line, column, std::move(message),
          interp::lineOf(programText, line)};
}

std::optional<Job> loadJob(const JobRequest& request) {
  const std::filesystem::path& program = request.program;
  const std::optional<std::filesystem::path>& setupFile = request.setup;
  const std::optional<interp::Dialect>& dialect = request.dialect;
  Job job{defaultSetup(), {}, {}, {}, {}};
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
  if (request.stock) {
    auto stock = parseStockOption(*request.stock);
    if (const auto* problem = std::get_if<std::string>(&stock)) {
      std::cerr << "lathesim: error: " << *problem << '\n';
      return std::nullopt;
    }
    job.setup.stock = std::get<sim::StockSpec>(stock);
    job.setup.stockGiven = true;
    job.setup.sourceName += " with --stock " + *request.stock;
  } else if (!job.setup.stockGiven) {
    if (const auto stated = interp::stockStatedIn(job.programText)) {
      job.setup.stock = sim::StockSpec{stated->diameterMm, stated->lengthMm, 0.0};
      job.notes.push_back({interp::Severity::Note, program.string(), stated->line, stated->column,
                           fmt::format("the bar is Φ{:g} × {:g} as the program states ({}), its face at "
                                       "Z0: no setup gives the stock",
                                       stated->diameterMm, stated->lengthMm, stated->text),
                           interp::lineOf(job.programText, stated->line)});
      print({job.notes.back()});
    }
  }
  interp::InterpreterOptions options = interpreterOptionsOf(job.setup);
  options.programDirectories = request.programDirectories;
  options.programDirectories.push_back(program.parent_path().empty() ? std::filesystem::path(".") : program.parent_path());
  interp::InterpretResult result = interp::interpret(job.programText, program.string(), options);
  print(result.diagnostics);
  if (!result.ok()) return std::nullopt;
  for (auto& d : result.diagnostics)
    if (d.severity == interp::Severity::Warning) job.warnings.push_back(std::move(d));
    else if (d.severity == interp::Severity::Note) job.notes.push_back(std::move(d));
  job.toolpath = std::move(result.toolpath);
  for (const interp::Error& w : interp::assignMoveTimes(job.toolpath, job.setup.machine)) {
    job.warnings.push_back(job.warningAt(w.line, w.column, w.message));
    print({job.warnings.back()});
  }
  return job;
}

}  // namespace lathesim::job
