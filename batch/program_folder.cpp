// A folder of programs as a batch (manifest.hpp says which files and how they are named).

#include <algorithm>
#include <array>
#include <cctype>

#include "batch/manifest.hpp"

namespace lathesim::batch {
namespace {

namespace fs = std::filesystem;

bool isProgram(const fs::directory_entry& entry) {
  static const std::array<std::string_view, 5> kExtensions{".nc", ".ngc", ".tap", ".cnc", ".gcode"};
  std::error_code ec;
  if (!entry.is_regular_file(ec)) return false;
  std::string extension = entry.path().extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return std::find(kExtensions.begin(), kExtensions.end(), extension) != kExtensions.end();
}

bool hidden(const fs::path& path) { return path.filename().string().starts_with("."); }

/// The first of `names` that exists beside `program`.
std::optional<fs::path> beside(const fs::path& program, std::initializer_list<const char*> names) {
  std::error_code ec;
  for (const char* name : names) {
    const fs::path candidate = program.parent_path() / name;
    if (fs::is_regular_file(candidate, ec)) return candidate;
  }
  return std::nullopt;
}

/// The job's name: the program's path in the folder without extension, '/' written '-';
/// a program.* file is named after its subfolder.
std::string nameIn(const fs::path& folder, const fs::path& program) {
  fs::path relative = program.lexically_relative(folder);
  if (relative.stem() == "program" && relative.has_parent_path()) return relative.parent_path().string();
  std::string name = relative.parent_path().empty() ? relative.stem().string()
                                                      : (relative.parent_path() / relative.stem()).string();
  std::replace(name.begin(), name.end(), '/', '-');
  return name;
}

}  // namespace

JobList jobsInFolder(const fs::path& folder, const JobSettings& defaults) {
  std::vector<fs::path> programs;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    if (hidden(entry.path())) continue;
    if (isProgram(entry)) programs.push_back(entry.path());
    if (!entry.is_directory(ec)) continue;
    for (const auto& inner : fs::directory_iterator(entry.path(), ec))
      if (!hidden(inner.path()) && isProgram(inner)) programs.push_back(inner.path());
  }
  interp::Diagnostic d;
  d.file = folder.string();
  if (ec) {
    d.message = "cannot read the folder: " + ec.message();
    return {std::nullopt, {d}};
  }
  if (programs.empty()) {
    d.message = "no programs (*.nc, *.ngc, *.tap, *.cnc, *.gcode) in the folder or its subfolders";
    return {std::nullopt, {d}};
  }
  std::sort(programs.begin(), programs.end());
  std::vector<BatchJob> jobs;
  for (const fs::path& program : programs) {
    BatchJob job;
    job.index = static_cast<int>(jobs.size());
    job.program = program.lexically_normal();
    job.name = nameIn(folder, program);
    JobSettings own;
    own.setup = beside(program, {"setup.toml"});
    own.drawing = beside(program, {"drawing.toml", "drawing.stl"});
    job.settings = own.over(defaults);
    jobs.push_back(std::move(job));
  }
  std::vector<interp::Diagnostic> diagnostics;
  if (!checkNamesUnique(jobs, folder, {}, diagnostics)) return {std::nullopt, std::move(diagnostics)};
  return {std::move(jobs), {}};
}

}  // namespace lathesim::batch
