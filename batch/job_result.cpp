#include "batch/job_result.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <regex>
#include <sstream>

#include "batch/number_text.hpp"
#include "setup/exit_status.hpp"

namespace lathesim::batch {
namespace {

using Json = nlohmann::json;

constexpr std::array<std::pair<JobStatus, std::string_view>, 7> kStatusNames{{{JobStatus::Ok, "ok"},
                                                                              {JobStatus::OutOfTolerance, "out_of_tolerance"},
                                                                              {JobStatus::Collision, "collision"},
                                                                              {JobStatus::Failed, "failed"},
                                                                              {JobStatus::Timeout, "timeout"},
                                                                              {JobStatus::Crashed, "crashed"},
                                                                              {JobStatus::NotRun, "not_run"}}};

template <class T>
std::optional<T> optionalAt(const Json& object, const char* key) {
  const auto found = object.find(key);
  if (found == object.end() || found->is_null()) return std::nullopt;
  return found->get<T>();
}

/// The figures a report.json gives; missing keys stay unset.
void readReport(const Json& report, JobResult& result) {
  result.stockVolumeMm3 = optionalAt<double>(report, "stock_volume_mm3");
  result.finalVolumeMm3 = optionalAt<double>(report, "final_volume_mm3");
  result.removedVolumeMm3 = optionalAt<double>(report, "removed_volume_mm3");
  result.cycleTimeS = optionalAt<double>(report, "cycle_time_s");
  result.peakMemoryMb = optionalAt<double>(report, "peak_memory_mb");
  result.moves = optionalAt<int>(report, "moves");
  if (const auto c = report.find("collisions"); c != report.end() && c->is_array())
    for (const auto& collision : *c)
      result.collisions.push_back({collision.value("line", 0), collision.value("column", 0),
                                   collision.value("kind", ""), collision.value("volume_mm3", 0.0)});
  if (const auto p = report.find("parted_off"); p != report.end() && p->is_object())
    result.partedOff = PartedOff{p->value("line", 0), p->value("column", 0), p->value("z", 0.0),
                                 p->value("volume_mm3", 0.0), p->value("stub_volume_mm3", 0.0)};
  if (const auto w = report.find("warnings"); w != report.end() && w->is_array()) {
    result.warnings = static_cast<int>(w->size());
    if (!w->empty())
      result.message = JobMessage{"warning", report.value("program", ""), w->front().value("line", 0),
                                  w->front().value("column", 0), w->front().value("message", "")};
  }
  // The command's own time: its total, or (from a report that has none) its steps added up.
  if (const auto t = report.find("timing_s"); t != report.end() && t->is_object()) {
    if (const auto total = t->find("total"); total != t->end() && total->is_number()) {
      result.pipelineS = total->get<double>();
    } else {
      double sum = 0;
      for (const auto& [step, seconds] : t->items())
        if (seconds.is_number()) sum += seconds.get<double>();
      result.pipelineS = sum;
    }
  }
  if (const auto c = report.find("check"); c != report.end() && c->is_object())
    result.check = CheckFigures{c->value("tolerance_mm", 0.0), c->value("within_tolerance", true),
                                c->value("max_gouge_mm", 0.0), c->value("max_excess_mm", 0.0)};
}

std::string signalText(int signal) {
  const char* name = strsignal(signal);
  return "signal " + std::to_string(signal) + (name ? std::string(" (") + name + ")" : std::string());
}

JobResult blankResult(const BatchJob& job, const std::string& folder) {
  JobResult result;
  result.index = job.index;
  result.name = job.name;
  result.program = job.program.string();
  result.command = job.checksDrawing() ? "check" : "run";
  result.folder = folder;
  result.timeLimitS = job.settings.timeLimitS;
  return result;
}

}  // namespace

std::string_view statusName(JobStatus status) {
  for (const auto& [s, name] : kStatusNames)
    if (s == status) return name;
  return "not_run";
}

std::optional<JobStatus> statusNamed(std::string_view name) {
  for (const auto& [s, n] : kStatusNames)
    if (n == name) return s;
  return std::nullopt;
}

std::optional<JobMessage> firstError(const std::string& logText) {
  static const std::regex located(R"(^(.+?):(\d+):(\d+): error: (.*)$)");
  static const std::regex filed(R"(^(.+?): error: (.*)$)");
  std::istringstream lines(logText);
  std::optional<JobMessage> firstLine;
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::smatch m;
    if (std::regex_match(line, m, located))
      return JobMessage{"error", m[1], std::stoi(m[2]), std::stoi(m[3]), m[4]};
    if (std::regex_match(line, m, filed)) {
      const std::string who = m[1];
      return JobMessage{"error", who.starts_with("lathesim") ? std::string() : who, 0, 0, m[2]};
    }
    if (!firstLine && line.find_first_not_of(" \t") != std::string::npos) firstLine = JobMessage{"error", "", 0, 0, line};
  }
  return firstLine;
}

JobResult resultOf(const BatchJob& job, const std::string& folder, const ChildOutcome& outcome,
                   const std::string& logText, const std::optional<Json>& report) {
  JobResult result = blankResult(job, folder);
  result.exitCode = outcome.exitCode;
  result.signal = outcome.signal;
  result.elapsedS = outcome.elapsedS;
  if (report) readReport(*report, result);
  if (outcome.timedOut) {
    result.status = JobStatus::Timeout;
    result.message = JobMessage{"error", "", 0, 0,
                                "stopped at the time limit of " + shortestText(job.settings.timeLimitS.value_or(0)) + " s"};
    return result;
  }
  if (outcome.signal) {
    result.status = JobStatus::Crashed;
    result.message = JobMessage{"error", "", 0, 0, "lathesim was ended by " + signalText(*outcome.signal)};
    return result;
  }
  const int code = outcome.exitCode.value_or(-1);
  if (code == 0 && report) {
    result.status = JobStatus::Ok;
  } else if (code == setup::kExitOutOfTolerance && result.check && !result.check->withinTolerance) {
    result.status = JobStatus::OutOfTolerance;
  } else if (code == setup::kExitCrash && report && !result.collisions.empty()) {
    result.status = JobStatus::Collision;
    if (auto error = firstError(logText)) result.message = error;
  } else {
    result.status = JobStatus::Failed;
    if (auto error = firstError(logText))
      result.message = error;
    else if (code == 0)
      result.message = JobMessage{"error", "", 0, 0, "lathesim wrote no report.json"};
    else if (!result.message)
      result.message = JobMessage{"error", "", 0, 0, "lathesim exited with status " + std::to_string(code)};
  }
  return result;
}

JobResult notRun(const BatchJob& job, const std::string& folder) {
  JobResult result = blankResult(job, folder);
  result.status = JobStatus::NotRun;
  result.message = JobMessage{"error", "", 0, 0, "not run: the batch was stopped first"};
  return result;
}

nlohmann::ordered_json toJson(const JobResult& r) {
  using Ordered = nlohmann::ordered_json;
  const auto orNull = [](const auto& optional) { return optional ? Ordered(*optional) : Ordered(nullptr); };
  Ordered row;
  row["index"] = r.index + 1;  // the job's place in the manifest, counted from 1
  row["name"] = r.name;
  row["program"] = r.program;
  row["command"] = r.command;
  row["status"] = statusName(r.status);
  row["exit_code"] = orNull(r.exitCode);
  row["signal"] = orNull(r.signal);
  row["message"] = r.message ? Ordered{{"kind", r.message->kind},
                                       {"file", r.message->file},
                                       {"line", r.message->line},
                                       {"column", r.message->column},
                                       {"text", r.message->text}}
                             : Ordered(nullptr);
  row["warnings"] = r.warnings;
  row["stock_volume_mm3"] = orNull(r.stockVolumeMm3);
  row["final_volume_mm3"] = orNull(r.finalVolumeMm3);
  row["removed_volume_mm3"] = orNull(r.removedVolumeMm3);
  row["cycle_time_s"] = orNull(r.cycleTimeS);
  row["moves"] = orNull(r.moves);
  auto& collisions = row["collisions"] = Ordered::array();
  for (const auto& c : r.collisions)
    collisions.push_back({{"line", c.line}, {"column", c.column}, {"kind", c.kind}, {"volume_mm3", c.volumeMm3}});
  row["parted_off"] = r.partedOff ? Ordered{{"line", r.partedOff->line},
                                            {"column", r.partedOff->column},
                                            {"z", r.partedOff->zMm},
                                            {"volume_mm3", r.partedOff->volumeMm3},
                                            {"stub_volume_mm3", r.partedOff->stubVolumeMm3}}
                                  : Ordered(nullptr);
  row["check"] = r.check ? Ordered{{"tolerance_mm", r.check->toleranceMm},
                                   {"within_tolerance", r.check->withinTolerance},
                                   {"max_gouge_mm", r.check->maxGougeMm},
                                   {"max_excess_mm", r.check->maxExcessMm}}
                         : Ordered(nullptr);
  row["peak_memory_mb"] = orNull(r.peakMemoryMb);
  row["elapsed_s"] = r.elapsedS;
  row["pipeline_s"] = orNull(r.pipelineS);
  row["time_limit_s"] = orNull(r.timeLimitS);
  row["folder"] = r.folder;
  row["thumbnail"] = orNull(r.thumbnail);
  row["resumed"] = r.resumed;
  return row;
}

JobResult resultFromJson(const Json& row) {
  JobResult r;
  r.index = row.at("index").get<int>() - 1;
  r.name = row.at("name").get<std::string>();
  r.program = row.at("program").get<std::string>();
  r.command = row.at("command").get<std::string>();
  const auto status = statusNamed(row.at("status").get<std::string>());
  if (!status) throw Json::other_error::create(501, "unknown status " + row.at("status").dump(), &row);
  r.status = *status;
  r.exitCode = optionalAt<int>(row, "exit_code");
  r.signal = optionalAt<int>(row, "signal");
  if (const auto& m = row.at("message"); !m.is_null())
    r.message = JobMessage{m.at("kind"), m.at("file"), m.at("line"), m.at("column"), m.at("text")};
  r.warnings = row.at("warnings").get<int>();
  r.stockVolumeMm3 = optionalAt<double>(row, "stock_volume_mm3");
  r.finalVolumeMm3 = optionalAt<double>(row, "final_volume_mm3");
  r.removedVolumeMm3 = optionalAt<double>(row, "removed_volume_mm3");
  r.cycleTimeS = optionalAt<double>(row, "cycle_time_s");
  r.moves = optionalAt<int>(row, "moves");
  for (const auto& c : row.at("collisions"))
    r.collisions.push_back({c.at("line"), c.at("column"), c.at("kind"), c.at("volume_mm3")});
  // A stamp written before summaries had parted_off has no such key: nothing parted off is known.
  if (const auto p = row.find("parted_off"); p != row.end() && !p->is_null())
    r.partedOff = PartedOff{p->at("line"), p->at("column"), p->at("z"), p->at("volume_mm3"), p->at("stub_volume_mm3")};
  if (const auto& c = row.at("check"); !c.is_null())
    r.check = CheckFigures{c.at("tolerance_mm"), c.at("within_tolerance"), c.at("max_gouge_mm"), c.at("max_excess_mm")};
  r.peakMemoryMb = optionalAt<double>(row, "peak_memory_mb");
  r.elapsedS = row.at("elapsed_s").get<double>();
  r.pipelineS = optionalAt<double>(row, "pipeline_s");
  r.timeLimitS = optionalAt<double>(row, "time_limit_s");
  r.folder = row.at("folder").get<std::string>();
  r.thumbnail = optionalAt<std::string>(row, "thumbnail");
  r.resumed = row.at("resumed").get<bool>();
  return r;
}

}  // namespace lathesim::batch
