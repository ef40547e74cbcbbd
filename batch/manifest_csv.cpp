// A CSV manifest: a header row naming manifest keys (manifest_fields.hpp), then one row per
// job. Fields follow RFC 4180 (commas, "quoted" fields with "" for a quote); blank lines are
// skipped; an empty cell leaves the key to the defaults; options are words split at spaces.

#include <fstream>
#include <sstream>

#include "batch/manifest.hpp"
#include "batch/manifest_fields.hpp"

namespace lathesim::batch {
namespace {

struct Cell {
  std::string text;
  int column = 1;  // 1-based, where the cell starts on its record's first line
};

struct Record {
  int line = 1;
  std::vector<Cell> cells;
};

/// The records of `text`. A quote left open sets `unterminatedQuoteLine` to its record's line.
std::vector<Record> parseCsv(const std::string& text, int& unterminatedQuoteLine) {
  std::vector<Record> records;
  Record record;
  Cell cell;
  int line = 1, column = 1;
  bool quoted = false, inQuotes = false, any = false;
  const auto endCell = [&] {
    record.cells.push_back(std::move(cell));
    cell = Cell{};
    quoted = false;
  };
  const auto endRecord = [&] {
    endCell();
    const bool blank = record.cells.size() == 1 && record.cells[0].text.empty() && !any;
    if (!blank) records.push_back(std::move(record));
    record = Record{};
    any = false;
  };
  record.line = line;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inQuotes) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        cell.text += '"';
        ++i, ++column;
      } else if (c == '"') {
        inQuotes = false;
      } else {
        cell.text += c;
        if (c == '\n') ++line, column = 0;
      }
    } else if (c == '"' && cell.text.empty() && !quoted) {
      inQuotes = quoted = any = true;
    } else if (c == ',') {
      any = true;
      endCell();
      cell.column = column + 1;
    } else if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') {
      // CRLF: the '\n' ends the record
    } else if (c == '\n') {
      endRecord();
      ++line, column = 0;
      record.line = line;
      cell.column = 1;
    } else {
      cell.text += c;
      any = true;
    }
    ++column;
  }
  if (inQuotes) unterminatedQuoteLine = record.line;
  if (any || !record.cells.empty()) endRecord();
  return records;
}

std::vector<std::string> wordsOf(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string word; in >> word;) words.push_back(word);
  return words;
}

/// A cell's text as the key's kind of value, or nullopt if it is not a number where one is due.
std::optional<FieldValue> fieldValue(const std::string& text, FieldKind kind) {
  if (kind == FieldKind::Text) return FieldValue(text);
  if (kind == FieldKind::Words) return FieldValue(wordsOf(text));
  std::size_t used = 0;
  try {
    const double number = std::stod(text, &used);
    if (text.find_first_not_of(" \t", used) != std::string::npos) return std::nullopt;
    return FieldValue(number);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

bool blank(const std::string& text) { return text.find_first_not_of(" \t") == std::string::npos; }

}  // namespace

JobList readCsvManifest(const std::filesystem::path& file, const JobSettings& defaults) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::vector<interp::Diagnostic> diagnostics;
  const auto report = [&](int line, int column, std::string message) {
    diagnostics.push_back({interp::Severity::Error, file.string(), line, column, std::move(message), interp::lineOf(text, line)});
  };
  if (!in) {
    report(0, 0, "cannot read the manifest");
    return {std::nullopt, std::move(diagnostics)};
  }
  int unterminated = 0;
  const std::vector<Record> records = parseCsv(text, unterminated);
  if (unterminated) report(unterminated, 1, "a quoted field is not closed (a \" is missing)");
  if (records.empty()) report(1, 1, "the manifest is empty; its first row names the columns (program, name, setup, …)");
  if (!diagnostics.empty()) return {std::nullopt, std::move(diagnostics)};

  std::vector<std::optional<ManifestKey>> columns;
  bool hasProgram = false;
  for (const Cell& heading : records.front().cells) {
    std::string name = heading.text;
    name.erase(0, name.find_first_not_of(" \t"));
    name.erase(name.find_last_not_of(" \t") + 1);
    columns.push_back(manifestKeyNamed(name));
    if (!columns.back()) {
      std::string known;
      for (auto key : manifestKeyNames()) known += (known.empty() ? "" : ", ") + std::string(key);
      report(records.front().line, heading.column, "unknown column '" + name + "' (expected " + known + ")");
    }
    hasProgram = hasProgram || columns.back() == ManifestKey::Program;
  }
  if (!hasProgram && diagnostics.empty()) report(records.front().line, 1, "the header row has no program column");
  if (!diagnostics.empty()) return {std::nullopt, std::move(diagnostics)};

  const std::filesystem::path baseDir = file.parent_path();
  std::vector<BatchJob> jobs;
  for (std::size_t r = 1; r < records.size(); ++r) {
    const Record& record = records[r];
    if (record.cells.size() > columns.size()) {
      report(record.line, record.cells[columns.size()].column,
             "the row has " + std::to_string(record.cells.size()) + " cells, the header " + std::to_string(columns.size()));
      continue;
    }
    JobEntry entry;
    bool ok = true;
    for (std::size_t c = 0; c < record.cells.size(); ++c) {
      const Cell& cell = record.cells[c];
      if (blank(cell.text)) continue;
      const ManifestKey key = *columns[c];
      const auto value = fieldValue(cell.text, kindOf(key));
      const auto problem = value ? setField(key, *value, baseDir, entry)
                                 : std::optional<std::string>(std::string(nameOf(key)) + " must be a number, got \"" + cell.text + "\"");
      if (problem) {
        report(record.line, cell.column, *problem);
        ok = false;
      }
    }
    if (!ok) continue;
    if (auto problem = entryProblem(entry, false)) {
      report(record.line, 1, *problem);
      continue;
    }
    jobs.push_back(jobOf(entry, defaults, static_cast<int>(jobs.size()), record.line));
  }
  if (jobs.empty() && diagnostics.empty()) report(records.front().line, 1, "the manifest lists no jobs below its header");
  if (!diagnostics.empty() || !checkNamesUnique(jobs, file, text, diagnostics)) return {std::nullopt, std::move(diagnostics)};
  return {std::move(jobs), {}};
}

}  // namespace lathesim::batch
