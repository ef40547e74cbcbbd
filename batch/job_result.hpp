#pragma once
// What became of one job: a row of the batch's summary, made from the child process's exit,
// its log and the report.json it wrote; kept in the job's stamp file and read back to
// resume or merge.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "batch/batch_job.hpp"

namespace lathesim::batch {

enum class JobStatus {
  Ok,              // ran (and, when checked, within tolerance)
  OutOfTolerance,  // `check` exited 3
  Collision,       // `run` or `check` exited 4: the program crashes (its outputs are written)
  Failed,          // any other non-zero exit: bad input, outputs not written, …
  Timeout,         // killed at its time limit
  Crashed,         // ended by a signal the batch did not send
  NotRun,          // the batch was interrupted before the job finished
};

// "ok", "out_of_tolerance", "collision", "failed", "timeout", "crashed" (ended by a signal), "not_run"
std::string_view statusName(JobStatus status);
std::optional<JobStatus> statusNamed(std::string_view name);

/// How the child process ended, as the batch saw it.
struct ChildOutcome {
  std::optional<int> exitCode;  // when it exited
  std::optional<int> signal;    // when a signal ended it
  bool timedOut = false;        // the batch killed it at its time limit
  double elapsedS = 0;
};

/// The error a job stopped at, or its first warning: "the error or first warning with its line".
struct JobMessage {
  std::string kind;  // "error" or "warning"
  std::string file;  // empty when the message is not about a file
  int line = 0;      // 0 when not about a line
  int column = 0;
  std::string text;
};

struct Collision {
  int line = 0;
  int column = 0;
  std::string kind;
  double volumeMm3 = 0;
};

/// report.json's `parted_off`: the block whose cut parted the bar, the Z of that cut's deepest
/// point, and the level-set volumes of the piece that fell and of the stub.
struct PartedOff {
  int line = 0;
  int column = 0;
  double zMm = 0;
  double volumeMm3 = 0;
  double stubVolumeMm3 = 0;
};

struct CheckFigures {
  double toleranceMm = 0;
  bool withinTolerance = true;
  double maxGougeMm = 0;
  double maxExcessMm = 0;
};

struct JobResult {
  int index = 0;
  std::string name;
  std::string program;
  std::string command;  // "run" or "check"
  std::string folder;   // the job's output folder, relative to the summary's
  JobStatus status = JobStatus::NotRun;
  std::optional<int> exitCode;
  std::optional<int> signal;
  std::optional<JobMessage> message;
  int warnings = 0;
  // From report.json, when the job wrote one.
  std::optional<double> stockVolumeMm3, finalVolumeMm3, removedVolumeMm3, cycleTimeS, peakMemoryMb;
  std::optional<int> moves;
  std::vector<Collision> collisions;
  std::optional<PartedOff> partedOff;  // none: nothing parted off (or no report)
  std::optional<CheckFigures> check;
  double elapsedS = 0;              // the job's wall time in the batch: start to result written
  std::optional<double> pipelineS;  // of which the command's own steps (report.json timing_s.total)
  std::optional<double> timeLimitS;
  std::optional<std::string> thumbnail;  // file name in the job's folder
  bool resumed = false;                  // taken from an earlier run's stamp, not run again

  bool passed() const { return status == JobStatus::Ok; }
};

/// The result of a job whose process ended as `outcome`, from its log text and the
/// report.json it wrote (nullopt if none).
JobResult resultOf(const BatchJob& job, const std::string& folder, const ChildOutcome& outcome,
                   const std::string& logText, const std::optional<nlohmann::json>& report);

/// A result for a job that did not run to its end (the batch was interrupted).
JobResult notRun(const BatchJob& job, const std::string& folder);

/// The first error in a command's log: `FILE:LINE:COL: error: …`, `…: error: …`, else the
/// first line that is not blank; nullopt for an empty log.
std::optional<JobMessage> firstError(const std::string& logText);

nlohmann::ordered_json toJson(const JobResult& result);
/// Throws nlohmann::json::exception on a row that is not one toJson wrote.
JobResult resultFromJson(const nlohmann::json& row);

}  // namespace lathesim::batch
