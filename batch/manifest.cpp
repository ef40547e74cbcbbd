#include "batch/manifest.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <regex>

namespace lathesim::batch {
namespace {

std::string lowerExtension(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

interp::Diagnostic problem(const std::filesystem::path& source, int line, std::string message,
                           std::string_view sourceText = {}) {
  interp::Diagnostic d;
  d.file = source.string();
  d.line = line;
  d.column = line > 0 ? 1 : 0;
  d.message = std::move(message);
  d.sourceLine = interp::lineOf(sourceText, line);
  return d;
}

}  // namespace

JobList readJobs(const std::filesystem::path& source, const JobSettings& defaults) {
  std::error_code ec;
  if (std::filesystem::is_directory(source, ec)) return jobsInFolder(source, defaults);
  if (!std::filesystem::exists(source, ec)) return {std::nullopt, {problem(source, 0, "no such manifest or folder")}};
  const std::string extension = lowerExtension(source);
  if (extension == ".toml") return readTomlManifest(source, defaults);
  if (extension == ".csv") return readCsvManifest(source, defaults);
  return {std::nullopt, {problem(source, 0, "a manifest must be a .toml or .csv file (or give a folder of programs)")}};
}

std::string defaultJobName(const std::filesystem::path& program) {
  const std::string stem = program.stem().string();
  if (stem == "program" && program.has_parent_path() && !program.parent_path().filename().empty()) {
    const std::string folder = program.parent_path().filename().string();
    if (folder != "." && folder != "..") return folder;
  }
  return stem;
}

std::optional<std::string> badJobName(const std::string& name) {
  if (name.empty()) return "a job's name must not be empty";
  if (name == "." || name == "..") return "a job's name must not be '.' or '..'";
  for (unsigned char c : name)
    if (c == '/' || c == '\\' || c < 0x20)
      return "a job's name names its output folder: no '/', '\\' or control characters (got \"" + name + "\")";
  // The batch writes its summaries beside the job folders.
  static const std::regex summaryFile(R"(summary(-\d+-of-\d+)?\.(csv|json|html))");
  if (std::regex_match(name, summaryFile)) return "a job's name must not be that of a summary file (" + name + ")";
  return std::nullopt;
}

bool checkNamesUnique(const std::vector<BatchJob>& jobs, const std::filesystem::path& source, std::string_view sourceText,
                      std::vector<interp::Diagnostic>& diagnostics) {
  std::map<std::string, const BatchJob*> seen;
  bool unique = true;
  for (const BatchJob& job : jobs) {
    if (auto bad = badJobName(job.name)) {
      diagnostics.push_back(problem(source, job.manifestLine, *bad + "; give the job a name", sourceText));
      unique = false;
      continue;
    }
    const auto [first, inserted] = seen.emplace(job.name, &job);
    if (inserted) continue;
    std::string where = first->second->manifestLine > 0 ? " on line " + std::to_string(first->second->manifestLine)
                                                        : " (" + first->second->program.string() + ")";
    diagnostics.push_back(problem(source, job.manifestLine,
                                  "two jobs are named \"" + job.name + "\" (" + job.program.string() +
                                      " and the job" + where + "); each needs its own output folder, give one a name",
                                  sourceText));
    unique = false;
  }
  return unique;
}

}  // namespace lathesim::batch
