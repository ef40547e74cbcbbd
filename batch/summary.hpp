#pragma once
// A batch's summary: one row per job (job_result.hpp), written as summary.json (everything),
// summary.csv (one line per job, for spreadsheets) and summary.html (summary_html.hpp). A
// shard writes summary-I-of-N.*; `lathesim batch merge` joins the shards' JSON into one.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "batch/job_result.hpp"
#include "batch/shard.hpp"
#include "setup/exit_status.hpp"

namespace lathesim::batch {

// The batch's exit status: every job passed; some failed (or timed out, crashed, did not
// run) — this wins over —; some programs collided (kExitCrash) — which wins over —; some parts
// were out of tolerance.
inline constexpr int kExitAllPassed = setup::kExitOk;
inline constexpr int kExitSomeFailed = setup::kExitBadInput;
using setup::kExitOutOfTolerance;
using setup::kExitCrash;

struct BatchSummary {
  std::string version;  // lathesim's version and build ID
  std::string buildId;
  std::string source;    // the manifest or folder, as given
  std::string jobsHash;  // identifies the batch's job list: shards of one batch share it
  int jobsInBatch = 0;   // in the whole manifest, every shard's
  Shard shard;           // 1/1 for a whole batch (also after a merge)
  std::vector<JobResult> jobs;  // in manifest order

  int exitStatus() const;
  int count(JobStatus status) const;
  /// "18 ok, 1 failed, 1 out of tolerance" (statuses with no job left out).
  std::string countsText() const;
};

nlohmann::ordered_json toJson(const BatchSummary& summary);
/// Throws nlohmann::json::exception if `json` is not a summary toJson wrote.
BatchSummary summaryFromJson(const nlohmann::json& json);

void writeSummaryCsv(const BatchSummary& summary, std::ostream& out);

/// The file names of a summary: "summary" for a whole batch, "summary-I-of-N" for a shard.
std::string summaryStem(const Shard& shard);

/// Writes STEM.json, STEM.csv and STEM.html into `folder`, each whole or not at all (a
/// temporary renamed into place). The HTML reads each job's thumbnail from its folder.
void writeSummaryFiles(const BatchSummary& summary, const std::filesystem::path& folder);

}  // namespace lathesim::batch
