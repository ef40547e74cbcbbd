// A TOML manifest: [defaults] and [[job]] tables (keys in manifest_fields.hpp).

#include <fstream>
#include <sstream>

#include <toml++/toml.h>

#include "batch/manifest.hpp"
#include "batch/manifest_fields.hpp"

namespace lathesim::batch {
namespace {

class TomlReporter {
 public:
  TomlReporter(std::string text, std::string fileName) : text_(std::move(text)), fileName_(std::move(fileName)) {}

  void at(const toml::source_region& where, std::string message) {
    interp::Diagnostic d;
    d.file = fileName_;
    d.line = static_cast<int>(where.begin.line);
    d.column = static_cast<int>(where.begin.column);
    d.message = std::move(message);
    d.sourceLine = interp::lineOf(text_, d.line);
    diagnostics.push_back(std::move(d));
  }

  const std::string& text() const { return text_; }
  std::vector<interp::Diagnostic> diagnostics;

 private:
  std::string text_;
  std::string fileName_;
};

std::string expectedOf(FieldKind kind) {
  switch (kind) {
    case FieldKind::Text: return "a string";
    case FieldKind::Number: return "a number";
    case FieldKind::Words: return "a list of strings";
  }
  return "";
}

std::optional<FieldValue> fieldValue(const toml::node& node, FieldKind kind) {
  switch (kind) {
    case FieldKind::Text:
      if (const auto* s = node.as_string()) return FieldValue(s->get());
      return std::nullopt;
    case FieldKind::Number:
      if (const auto* i = node.as_integer()) return FieldValue(static_cast<double>(i->get()));
      if (const auto* f = node.as_floating_point()) return FieldValue(f->get());
      return std::nullopt;
    case FieldKind::Words: {
      const auto* array = node.as_array();
      if (!array) return std::nullopt;
      std::vector<std::string> words;
      for (const auto& element : *array) {
        const auto* s = element.as_string();
        if (!s) return std::nullopt;
        words.push_back(s->get());
      }
      return FieldValue(std::move(words));
    }
  }
  return std::nullopt;
}

std::string knownKeys() {
  std::string text;
  for (auto name : manifestKeyNames()) text += (text.empty() ? "" : ", ") + std::string(name);
  return text;
}

/// One [defaults] or [[job]] table; nullopt after reporting its problems.
std::optional<JobEntry> readEntry(const toml::table& table, bool isDefaults, const std::filesystem::path& baseDir,
                                  TomlReporter& report) {
  JobEntry entry;
  bool ok = true;
  for (auto&& [key, node] : table) {
    const auto known = manifestKeyNamed(key.str());
    if (!known) {
      report.at(key.source(), "unknown key '" + std::string(key.str()) + "' (expected " + knownKeys() + ")");
      ok = false;
      continue;
    }
    const auto value = fieldValue(node, kindOf(*known));
    if (!value) {
      report.at(node.source(), std::string(key.str()) + " must be " + expectedOf(kindOf(*known)));
      ok = false;
      continue;
    }
    if (auto problem = setField(*known, *value, baseDir, entry)) {
      report.at(node.source(), *problem);
      ok = false;
    }
  }
  if (!ok) return std::nullopt;
  if (auto problem = entryProblem(entry, isDefaults)) {
    report.at(table.source(), *problem);
    return std::nullopt;
  }
  return entry;
}

}  // namespace

JobList readTomlManifest(const std::filesystem::path& file, const JobSettings& defaults) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  TomlReporter report(text.str(), file.string());
  if (!in) {
    report.diagnostics.push_back({interp::Severity::Error, file.string(), 0, 0, "cannot read the manifest", ""});
    return {std::nullopt, std::move(report.diagnostics)};
  }
  toml::table root;
  try {
    root = toml::parse(report.text(), file.string());
  } catch (const toml::parse_error& error) {
    report.at(error.source(), "TOML syntax error: " + std::string(error.description()));
    return {std::nullopt, std::move(report.diagnostics)};
  }
  const std::filesystem::path baseDir = file.parent_path();
  JobSettings layered = defaults;
  const toml::array* jobTables = nullptr;
  for (auto&& [key, node] : root) {
    if (key.str() == "defaults" && node.is_table()) {
      if (auto entry = readEntry(*node.as_table(), true, baseDir, report)) layered = entry->settings.over(defaults);
    } else if (key.str() == "job" && node.is_array_of_tables()) {
      jobTables = node.as_array();
    } else {
      report.at(key.source(), key.str() == "defaults" || key.str() == "job"
                                  ? std::string(key.str()) + " must be written " + (key.str() == "job" ? "[[job]]" : "[defaults]")
                                  : "unknown key '" + std::string(key.str()) + "' (expected [defaults] and [[job]] tables)");
    }
  }
  if (!jobTables && report.diagnostics.empty())
    report.diagnostics.push_back({interp::Severity::Error, file.string(), 0, 0, "the manifest lists no [[job]]", ""});
  std::vector<BatchJob> jobs;
  if (jobTables)
    for (const auto& node : *jobTables) {
      const toml::table& table = *node.as_table();
      if (auto entry = readEntry(table, false, baseDir, report))
        jobs.push_back(jobOf(*entry, layered, static_cast<int>(jobs.size()), static_cast<int>(table.source().begin.line)));
    }
  if (!report.diagnostics.empty() || !checkNamesUnique(jobs, file, report.text(), report.diagnostics))
    return {std::nullopt, std::move(report.diagnostics)};
  return {std::move(jobs), {}};
}

}  // namespace lathesim::batch
