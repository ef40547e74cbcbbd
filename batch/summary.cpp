#include "batch/summary.hpp"

#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>

#include "batch/number_text.hpp"
#include "batch/summary_html.hpp"

namespace lathesim::batch {
namespace {

using Ordered = nlohmann::ordered_json;

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string csvNumber(std::optional<double> value) { return value ? shortestText(*value) : std::string(); }

std::string csvInt(std::optional<int> value) { return value ? std::to_string(*value) : std::string(); }

/// Writes `file` through a temporary renamed into place, with what `write` puts out.
void writeWhole(const std::filesystem::path& file, const std::function<void(std::ostream&)>& write) {
  auto temporary = file;
  temporary += ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    write(out);
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  std::filesystem::rename(temporary, file);
}

}  // namespace

int BatchSummary::exitStatus() const {
  bool outOfTolerance = false, collision = false;
  for (const auto& job : jobs) {
    if (job.status == JobStatus::OutOfTolerance) outOfTolerance = true;
    else if (job.status == JobStatus::Collision) collision = true;
    else if (job.status != JobStatus::Ok) return kExitSomeFailed;
  }
  if (collision) return kExitCrash;
  return outOfTolerance ? kExitOutOfTolerance : kExitAllPassed;
}

int BatchSummary::count(JobStatus status) const {
  int n = 0;
  for (const auto& job : jobs) n += job.status == status ? 1 : 0;
  return n;
}

std::string BatchSummary::countsText() const {
  std::string text;
  for (JobStatus status : {JobStatus::Ok, JobStatus::OutOfTolerance, JobStatus::Collision, JobStatus::Failed, JobStatus::Timeout,
                           JobStatus::Crashed, JobStatus::NotRun}) {
    const int n = count(status);
    if (n == 0) continue;
    std::string name(statusName(status));
    for (char& c : name) c = c == '_' ? ' ' : c;
    text += (text.empty() ? "" : ", ") + std::to_string(n) + " " + name;
  }
  return text.empty() ? "no jobs" : text;
}

Ordered toJson(const BatchSummary& s) {
  Ordered json;
  json["lathesim"] = {{"version", s.version}, {"build_id", s.buildId}};
  json["source"] = s.source;
  json["jobs_hash"] = s.jobsHash;
  json["jobs_in_batch"] = s.jobsInBatch;
  json["shard"] = {{"index", s.shard.index}, {"count", s.shard.count}};
  auto& counts = json["counts"] = Ordered::object();
  for (JobStatus status : {JobStatus::Ok, JobStatus::OutOfTolerance, JobStatus::Collision, JobStatus::Failed, JobStatus::Timeout,
                           JobStatus::Crashed, JobStatus::NotRun})
    counts[std::string(statusName(status))] = s.count(status);
  json["exit_status"] = s.exitStatus();
  auto& jobs = json["jobs"] = Ordered::array();
  for (const auto& job : s.jobs) jobs.push_back(toJson(job));
  return json;
}

BatchSummary summaryFromJson(const nlohmann::json& json) {
  BatchSummary s;
  s.version = json.at("lathesim").at("version").get<std::string>();
  s.buildId = json.at("lathesim").at("build_id").get<std::string>();
  s.source = json.at("source").get<std::string>();
  s.jobsHash = json.at("jobs_hash").get<std::string>();
  s.jobsInBatch = json.at("jobs_in_batch").get<int>();
  s.shard = {json.at("shard").at("index").get<int>(), json.at("shard").at("count").get<int>()};
  for (const auto& row : json.at("jobs")) s.jobs.push_back(resultFromJson(row));
  return s;
}

void writeSummaryCsv(const BatchSummary& s, std::ostream& out) {
  out << "index,name,status,exit_code,program,command,message_kind,message_file,message_line,message_column,message,"
         "warnings,stock_volume_mm3,final_volume_mm3,removed_volume_mm3,cycle_time_s,moves,collisions,"
         "first_collision_line,first_collision_kind,tolerance_mm,within_tolerance,max_gouge_mm,max_excess_mm,"
         "peak_memory_mb,elapsed_s,folder,parted_off_line,parted_off_z,parted_off_volume_mm3\n";
  for (const auto& r : s.jobs) {
    const JobMessage* m = r.message ? &*r.message : nullptr;
    const CheckFigures* c = r.check ? &*r.check : nullptr;
    const Collision* first = r.collisions.empty() ? nullptr : &r.collisions.front();
    out << r.index + 1 << ',' << csvField(r.name) << ',' << statusName(r.status) << ',' << csvInt(r.exitCode) << ','
        << csvField(r.program) << ',' << r.command << ',' << (m ? m->kind : "") << ',' << csvField(m ? m->file : "")
        << ',' << (m && m->line ? std::to_string(m->line) : "") << ',' << (m && m->column ? std::to_string(m->column) : "")
        << ',' << csvField(m ? m->text : "") << ',' << r.warnings << ',' << csvNumber(r.stockVolumeMm3) << ','
        << csvNumber(r.finalVolumeMm3) << ',' << csvNumber(r.removedVolumeMm3) << ',' << csvNumber(r.cycleTimeS) << ','
        << csvInt(r.moves) << ',' << r.collisions.size() << ',' << (first ? std::to_string(first->line) : "") << ','
        << (first ? first->kind : "") << ',' << (c ? csvNumber(c->toleranceMm) : "") << ','
        << (c ? (c->withinTolerance ? "true" : "false") : "") << ',' << (c ? csvNumber(c->maxGougeMm) : "") << ','
        << (c ? csvNumber(c->maxExcessMm) : "") << ',' << csvNumber(r.peakMemoryMb) << ',' << csvNumber(r.elapsedS)
        << ',' << csvField(r.folder) << ',' << (r.partedOff ? std::to_string(r.partedOff->line) : "") << ','
        << (r.partedOff ? csvNumber(r.partedOff->zMm) : "") << ','
        << (r.partedOff ? csvNumber(r.partedOff->volumeMm3) : "") << '\n';
  }
}

std::string summaryStem(const Shard& shard) { return shard.whole() ? "summary" : "summary-" + shard.tag(); }

void writeSummaryFiles(const BatchSummary& summary, const std::filesystem::path& folder) {
  const std::string stem = summaryStem(summary.shard);
  // A job's message quotes its program, which need not be UTF-8: such bytes become U+FFFD.
  const std::string json = toJson(summary).dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
  writeWhole(folder / (stem + ".json"), [&](std::ostream& out) { out << json << '\n'; });
  writeWhole(folder / (stem + ".csv"), [&](std::ostream& out) { writeSummaryCsv(summary, out); });
  writeWhole(folder / (stem + ".html"), [&](std::ostream& out) { writeSummaryHtml(summary, folder, out); });
}

}  // namespace lathesim::batch
