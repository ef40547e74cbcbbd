#include "batch/batch_runner.hpp"

#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <list>
#include <sstream>

#include "batch/build_id.hpp"
#include "batch/child_process.hpp"
#include "batch/content_hash.hpp"
#include "batch/input_stamp.hpp"
#include "batch/manifest.hpp"
#include "batch/resources.hpp"
#include "batch/summary.hpp"

namespace lathesim::batch {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr const char* kLogFileName = kJobLogFileName;
constexpr const char* kThumbnailFileName = "thumbnail.png";
constexpr int kThumbnailWidthPx = 240;
constexpr double kMemoryShare = 0.8;  // of the memory free at the start, for the jobs together

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::string readText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::optional<nlohmann::json> readReport(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

/// Identifies a batch's job list, so that merge joins only shards of one batch.
std::string jobsHash(const std::vector<BatchJob>& jobs) {
  ContentHash hash;
  for (const auto& job : jobs) hash.add(job.name).add(job.program.string());
  return hash.hex();
}

/// Empties a job's folder for a fresh run. A folder the batch did not make (no log, no
/// stamp) and holding something is left alone: false.
bool prepareFolder(const fs::path& folder) {
  std::error_code ec;
  if (fs::exists(folder, ec)) {
    const bool ours = fs::exists(folder / kLogFileName, ec) || fs::exists(folder / kStampFileName, ec);
    if (!ours && !fs::is_empty(folder, ec)) return false;
    fs::remove_all(folder);
  }
  fs::create_directories(folder);
  return true;
}

/// After a kill: the log stays, anything half-written goes.
void removeAllButLog(const fs::path& folder) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec))
    if (entry.path().filename() != kLogFileName) fs::remove_all(entry.path(), ec);
}

struct RunningJob {
  const BatchJob* job;
  std::string inputs;
  std::uint64_t bytes;
  ChildProcess process;
  Clock::time_point start;
  std::optional<Clock::time_point> deadline;
  bool timedOut = false;
};

class BatchRun {
 public:
  BatchRun(const BatchOptions& options, BatchSummary& summary) : options_(options), summary_(summary) {}

  /// Runs `pending` (with their input stamps); returns the signal that stopped the batch, or 0.
  int run(std::vector<std::pair<const BatchJob*, std::string>> pending, int alreadyDone) {
    done_ = alreadyDone;
    total_ = alreadyDone + static_cast<int>(pending.size());
    slots_ = std::max(1, options_.jobs.value_or(availableCpus()));
    // Jobs are forked from the batch only while it runs no thread of its own. The libraries
    // start some when they are loaded (log4cplus, under OpenVDB, a pool that stays idle):
    // those were there before the batch began, and a job does not use them.
    inProcess_ = options_.jobMain && threadCount() > 0 && threadCount() == options_.threadsAtStart;
    if (inProcess_ && options_.preparation.forForks) forkPreparation_ = options_.preparation.forForks();  // while the first jobs run
    if (options_.memoryBytes) {
      budget_ = options_.memoryBytes;
    } else if (auto free = availableMemoryBytes()) {
      budget_ = static_cast<std::uint64_t>(kMemoryShare * static_cast<double>(*free));
    }
    for (auto& [job, inputs] : pending) queue_.push_back({job, std::move(inputs), estimatedJobBytes(*job)});
    // Largest first: the long jobs start early and the short ones fill in around them.
    queue_.sort([](const Queued& a, const Queued& b) { return a.bytes > b.bytes; });  // stable

    sigset_t watched, previous;
    sigemptyset(&watched);
    for (int sig : {SIGCHLD, SIGINT, SIGTERM, SIGHUP}) sigaddset(&watched, sig);
    pthread_sigmask(SIG_BLOCK, &watched, &previous);
    int stoppedBy = 0;
    while (!queue_.empty() || !running_.empty()) {
      startWhatFits();
      siginfo_t info;
      const timespec wait = waitTime();
      const int sig = sigtimedwait(&watched, &info, &wait);
      if (sig == SIGINT || sig == SIGTERM || sig == SIGHUP) {
        stoppedBy = sig;
        break;
      }
      killOverdue();
      std::vector<Ended> ended = reapEnded();
      finishForkPreparation();
      startWhatFits();  // before the stamps: no CPU waits on the batch's own work
      for (const Ended& e : ended) finish(e.job, e.waitStatus);
    }
    if (stoppedBy) stopAll();
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    return stoppedBy;
  }

 private:
  struct Queued {
    const BatchJob* job;
    std::string inputs;
    std::uint64_t bytes;
  };

  void startWhatFits() {
    for (auto it = queue_.begin(); it != queue_.end();) {
      if (!mayStart(static_cast<int>(running_.size()), runningBytes_, it->bytes, slots_, budget_)) {
        if (static_cast<int>(running_.size()) >= slots_) return;
        ++it;
        continue;
      }
      start(*it);
      it = queue_.erase(it);
    }
  }

  void start(const Queued& queued) {
    const BatchJob& job = *queued.job;
    const fs::path folder = options_.out / job.name;
    if (!prepareFolder(folder)) {
      ChildOutcome refused;
      JobResult result = resultOf(job, job.name, refused, "", std::nullopt);
      result.status = JobStatus::Failed;
      result.message = JobMessage{"error", folder.string(), 0, 0,
                                  "the job's output folder exists and was not made by lathesim batch; "
                                  "move it away or choose another --out"};
      record(std::move(result));
      return;
    }
    // The job stages its own thumbnail from its picture in memory, with its other files.
    std::vector<std::string> args = commandArguments(job, folder);
    args.insert(args.end(), {"--thumbnail", std::to_string(kThumbnailWidthPx)});
    const fs::path log = folder / kLogFileName;
    RunningJob running{&job, queued.inputs, queued.bytes,
                       inProcess_ ? ChildProcess::fork(options_.jobMain, args, log) : ChildProcess::start(options_.binary, args, log),
                       Clock::now(), std::nullopt};
    if (job.settings.timeLimitS)
      running.deadline = running.start + std::chrono::duration_cast<Clock::duration>(
                                             std::chrono::duration<double>(*job.settings.timeLimitS));
    runningBytes_ += running.bytes;
    running_.push_back(std::move(running));
  }

  /// Once the preparation for forks is done (the libraries that drawing loads, the GL driver and
  /// LLVM, loaded here), each job forked from then on finds it done. It starts no thread;
  /// should one have, the next jobs are started anew instead.
  void finishForkPreparation() {
    if (!forkPreparation_ || !forkPreparation_()) return;
    forkPreparation_ = nullptr;
    inProcess_ = threadCount() == options_.threadsAtStart;
  }

  /// Until the next deadline, and at most half a second (a missed wake-up costs no more).
  timespec waitTime() const {
    auto wait = std::chrono::duration<double>(0.5);
    for (const auto& r : running_)
      if (r.deadline) wait = std::min(wait, std::chrono::duration<double>(*r.deadline - Clock::now()));
    const double seconds = std::max(0.0, wait.count());
    timespec t;
    t.tv_sec = static_cast<time_t>(seconds);
    t.tv_nsec = static_cast<long>((seconds - static_cast<double>(t.tv_sec)) * 1e9);
    return t;
  }

  void killOverdue() {
    const auto now = Clock::now();
    for (auto& r : running_)
      if (r.deadline && now >= *r.deadline && !r.timedOut) {
        r.timedOut = true;
        r.process.killGroup();
      }
  }

  struct Ended {
    RunningJob job;
    int waitStatus;
  };

  /// The jobs whose process has ended, reaped, their slots and memory freed.
  std::vector<Ended> reapEnded() {
    std::vector<Ended> ended;
    for (auto it = running_.begin(); it != running_.end();) {
      const std::optional<int> status = it->process.poll();
      if (!status) {
        ++it;
        continue;
      }
      runningBytes_ -= it->bytes;
      ended.push_back({std::move(*it), *status});
      it = running_.erase(it);
    }
    return ended;
  }

  void finish(const RunningJob& r, int waitStatus) {
    const BatchJob& job = *r.job;
    const fs::path folder = options_.out / job.name;
    ChildOutcome outcome;
    if (WIFEXITED(waitStatus)) outcome.exitCode = WEXITSTATUS(waitStatus);
    if (WIFSIGNALED(waitStatus)) outcome.signal = WTERMSIG(waitStatus);
    outcome.timedOut = r.timedOut;
    JobResult result = resultOf(job, job.name, outcome, readText(folder / kLogFileName), readReport(folder / "report.json"));
    if (outcome.signal) removeAllButLog(folder);
    std::error_code ec;
    if (fs::exists(folder / kThumbnailFileName, ec)) result.thumbnail = kThumbnailFileName;
    result.elapsedS = secondsSince(r.start);
    writeStamp(folder, r.inputs, result);
    record(std::move(result));
  }

  void record(JobResult result) {
    ++done_;
    std::cout << '[' << done_ << '/' << total_ << "] " << result.name << ": " << statusName(result.status);
    if (result.message && result.message->kind == "error") {
      const JobMessage& m = *result.message;
      std::cout << " — ";
      if (!m.file.empty()) std::cout << m.file << ':';
      if (m.line > 0) std::cout << m.line << ':' << m.column << ':';
      std::cout << (m.file.empty() && m.line == 0 ? "" : " ") << m.text;
    }
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, " (%.1f s)", result.elapsedS);
    std::cout << seconds << std::endl;
    summary_.jobs.push_back(std::move(result));
  }

  /// Kills every running job (their partial outputs go) and records them and the queue as not run.
  void stopAll() {
    for (auto& r : running_) {
      r.process.killGroup();
      r.process.wait();
      removeAllButLog(options_.out / r.job->name);
      summary_.jobs.push_back(notRun(*r.job, r.job->name));
    }
    running_.clear();
    for (const auto& q : queue_) summary_.jobs.push_back(notRun(*q.job, q.job->name));
    queue_.clear();
  }

  const BatchOptions& options_;
  BatchSummary& summary_;
  std::list<Queued> queue_;
  std::list<RunningJob> running_;
  std::uint64_t runningBytes_ = 0;
  std::optional<std::uint64_t> budget_;
  int slots_ = 1;
  bool inProcess_ = false;  // jobs forked from the batch (options_.jobMain), not started anew
  std::function<bool()> forkPreparation_;  // until it is done (JobPreparation::forForks)
  int done_ = 0, total_ = 0;
};

}  // namespace

int runBatch(const BatchOptions& options) {
  const JobList list = readJobs(options.source, options.defaults);
  for (const auto& d : list.diagnostics) std::cerr << interp::format(d) << '\n';
  if (!list.jobs) return kExitSomeFailed;
  const std::vector<BatchJob>& jobs = *list.jobs;

  BatchOptions resolved = options;
  if (resolved.binary.empty()) resolved.binary = fs::read_symlink("/proc/self/exe");
  BatchSummary summary;
  summary.version = LATHESIM_VERSION;
  summary.buildId = buildIdOf(resolved.binary);
  summary.source = options.source.string();
  summary.jobsHash = jobsHash(jobs);
  summary.jobsInBatch = static_cast<int>(jobs.size());
  summary.shard = options.shard;
  fs::create_directories(options.out);

  std::vector<std::pair<const BatchJob*, std::string>> pending;
  InputStamper stamper(summary.buildId);
  for (const BatchJob& job : jobs) {
    if (!options.shard.holds(job.index)) continue;
    std::string inputs = stamper.stampOf(job);
    if (auto stamped = stampedResult(options.out / job.name, inputs, job)) {
      stamped->folder = job.name;
      summary.jobs.push_back(std::move(*stamped));
    } else {
      pending.emplace_back(&job, std::move(inputs));
    }
  }
  const int upToDate = static_cast<int>(summary.jobs.size());
  std::cout << "batch: " << upToDate + pending.size() << " jobs"
            << (options.shard.whole() ? "" : " in shard " + options.shard.tag() + " of " + std::to_string(jobs.size()))
            << (upToDate ? ", " + std::to_string(upToDate) + " up to date from an earlier run" : "") << std::endl;

  int stoppedBy = 0;
  if (!pending.empty()) {
    if (options.preparation.beforeJobs) options.preparation.beforeJobs();
    stoppedBy = BatchRun(resolved, summary).run(std::move(pending), upToDate);
  }
  std::sort(summary.jobs.begin(), summary.jobs.end(),
            [](const JobResult& a, const JobResult& b) { return a.index < b.index; });
  writeSummaryFiles(summary, options.out);
  const fs::path html = options.out / (summaryStem(options.shard) + ".html");
  std::cout << "batch: " << summary.countsText() << "; summary in " << html.string() << std::endl;
  if (stoppedBy) {
    std::cout << "batch: stopped by " << strsignal(stoppedBy)
              << "; run the same command again to go on where it stopped" << std::endl;
    return 128 + stoppedBy;
  }
  return summary.exitStatus();
}

}  // namespace lathesim::batch
