// The parts/ batch on a real one-node Slurm cluster started on this machine from Debian's
// packages (scripts/slurm/local-cluster.sh): a job array of three shards
// (scripts/slurm/batch.sbatch), merged by its last task, must give the summary of the same
// batch run on one machine; and stopping the cluster must leave no process behind.

#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>

#include "tests/support/lathesim_process.hpp"
#include "tests/support/processes.hpp"

namespace lathesim::batch {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using test::readFile;
using test::ScratchDir;

const fs::path kBinary = LATHESIM_BINARY;
const fs::path kPartsDir = LATHESIM_PARTS_DIR;
const fs::path kScripts = LATHESIM_SOURCE_DIR "/scripts/slurm";

test::ProcessOutcome shell(const fs::path& scratch, const std::string& command) {
  return test::runProcess("/bin/sh", {"-c", command}, scratch);
}

std::string quoted(const fs::path& path) {
  std::string text(1, '\'');
  text += path.string();
  text += '\'';
  return text;
}

bool onPath(const std::string& program) {
  return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

/// Whether sinfo's long state (idle, mixed, allocated, completing, or drained, draining,
/// down, fail, failing; `*` appended when slurmd stops answering) says it takes no more jobs.
/// A letter test would not do: "idle" and "allocated" hold a d.
bool nodeIsOutOfService(const std::string& state) {
  for (const char* out : {"drain", "down", "fail", "*"})
    if (state.find(out) != std::string::npos) return true;
  return false;
}

/// The cluster for the test's lifetime: stopped however the test ends.
class LocalCluster {
 public:
  explicit LocalCluster(const fs::path& dir) : dir_(dir) {
    const auto started = shell(dir, clusterCommand("start"));
    started_ = started.status == 0;
    problem_ = started.out + started.err;
    if (started_) ::setenv("SLURM_CONF", (dir / "cluster" / "slurm.conf").c_str(), 1);
  }
  ~LocalCluster() { stop(); }
  bool started() const { return started_; }
  const std::string& problem() const { return problem_; }
  test::ProcessOutcome stop() {
    if (stopped_) return {};
    stopped_ = true;
    auto outcome = shell(dir_, clusterCommand("stop"));
    ::unsetenv("SLURM_CONF");
    return outcome;
  }
  std::string clusterCommand(const std::string& action) const {
    return quoted(kScripts / "local-cluster.sh") + " " + action + " " + quoted(dir_ / "cluster");
  }
  std::string logs() const {
    std::string text;
    for (const char* log : {"slurmctld.log", "slurmd.log"}) text += readFile(dir_ / "cluster" / "log" / log);
    return text;
  }

 private:
  fs::path dir_;
  bool started_ = false, stopped_ = false;
  std::string problem_;
};

/// Rows equal but for what differs from run to run: how long a job took and its memory
/// peak, and whether it was resumed. Numbers to 1e-9 relative (volumes are sums over
/// threads, in no fixed order).
void expectSameRows(const Json& cluster, const Json& local, const std::string& where = "") {
  static const std::set<std::string> kVarying{"elapsed_s", "pipeline_s", "peak_memory_mb", "resumed"};
  if (local.is_number() && cluster.is_number()) {
    const double a = cluster.get<double>(), b = local.get<double>();
    EXPECT_NEAR(a, b, 1e-9 * std::max(1.0, std::abs(b))) << where;
    return;
  }
  ASSERT_EQ(cluster.type(), local.type()) << where << ": " << cluster << " against " << local;
  if (local.is_object()) {
    std::set<std::string> keys;
    for (const auto& [key, value] : local.items()) keys.insert(key);
    for (const auto& [key, value] : cluster.items()) keys.insert(key);
    for (const auto& key : keys) {
      if (kVarying.count(key)) continue;
      ASSERT_TRUE(cluster.contains(key) && local.contains(key)) << where << "." << key;
      expectSameRows(cluster.at(key), local.at(key), where + "." + key);
    }
  } else if (local.is_array()) {
    ASSERT_EQ(cluster.size(), local.size()) << where;
    for (std::size_t i = 0; i < local.size(); ++i) expectSameRows(cluster[i], local[i], where + "[" + std::to_string(i) + "]");
  } else {
    EXPECT_EQ(cluster, local) << where;
  }
}

TEST(SlurmCluster, PartsBatchAsAJobArrayEqualsTheOneMachineBatch) {
  const bool root = ::geteuid() == 0;
  std::string missing;
  for (const char* program : {"munged", "mungekey", "slurmctld", "slurmd", "sbatch", "squeue", "sinfo"})
    if (!onPath(program)) missing += std::string(missing.empty() ? "" : ", ") + program;
  if (!root) GTEST_SKIP() << "a local Slurm cluster needs root (slurmd starts jobs as their user)";
  ASSERT_TRUE(missing.empty()) << "not installed: " << missing << " — scripts/setup.sh installs slurm-wlm and munge";

  ScratchDir dir("slurm");
  const fs::path local = dir.path() / "local", cluster = dir.path() / "cluster-out";

  LocalCluster slurm(dir.path());
  ASSERT_TRUE(slurm.started()) << slurm.problem();
  const std::string submit = "LATHESIM=" + quoted(kBinary) + " sbatch --parsable --array=1-3 -o " +
                             quoted(dir.path() / "task-%A_%a.out") + " " + quoted(kScripts / "batch.sbatch") + " " +
                             quoted(kPartsDir) + " " + quoted(cluster) + " --voxel 0.5";
  const test::ProcessOutcome submitted = shell(dir.path(), submit);
  ASSERT_EQ(submitted.status, 0) << submitted.out << submitted.err;
  const std::string jobId = submitted.out.substr(0, submitted.out.find_first_of(";\n"));

  // The same batch on this machine, while the array waits for its first CPU.
  const test::ProcessOutcome oneMachine =
      test::runProcess(kBinary, {"batch", kPartsDir.string(), "--out", local.string(), "--voxel", "0.5"}, dir.path());
  EXPECT_EQ(oneMachine.status, 1) << oneMachine.out << oneMachine.err;  // seed004-o0006 alarms

  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(240);
  for (;;) {
    const std::string active = shell(dir.path(), "squeue -h -t PD,R,CG -j " + jobId + " -o %i").out;
    if (active.empty()) break;
    const std::string node = shell(dir.path(), "sinfo -h -N -o %T").out;
    ASSERT_FALSE(nodeIsOutOfService(node)) << "the node is " << node << slurm.logs();
    ASSERT_LT(std::chrono::steady_clock::now(), deadline) << "the array did not finish:\n" << active;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  // Each task ended of itself, with its shard's exit status (0, 1 or 3); none was lost.
  const std::string tasks = shell(dir.path(), "squeue -h -t all -j " + jobId + " -o '%K %T'").out;
  std::istringstream lines(tasks);
  int ended = 0;
  for (std::string task, state; lines >> task >> state; ++ended)
    EXPECT_TRUE(state == "COMPLETED" || state == "FAILED") << task << " " << state;
  EXPECT_EQ(ended, 3) << tasks;

  ASSERT_TRUE(fs::exists(cluster / "summary.json")) << readFile(dir.path() / ("task-" + jobId + "_3.out"));
  const Json merged = Json::parse(readFile(cluster / "summary.json"));
  const Json whole = Json::parse(readFile(local / "summary.json"));
  EXPECT_EQ(merged.at("shard"), whole.at("shard"));
  EXPECT_EQ(merged.at("jobs_hash"), whole.at("jobs_hash"));
  EXPECT_EQ(merged.at("counts"), whole.at("counts"));
  EXPECT_EQ(merged.at("exit_status"), 1);
  std::size_t programs = 0;  // every part's program.nc (a new part is picked up)
  for (const auto& entry : fs::directory_iterator(kPartsDir)) programs += fs::exists(entry.path() / "program.nc") ? 1 : 0;
  EXPECT_EQ(merged.at("jobs").size(), programs);
  expectSameRows(merged.at("jobs"), whole.at("jobs"), "jobs");
  for (int shard = 1; shard <= 3; ++shard) {
    const Json part = Json::parse(readFile(cluster / ("summary-" + std::to_string(shard) + "-of-3.json")));
    for (const auto& row : part.at("jobs")) EXPECT_EQ((row.at("index").get<int>() - 1) % 3, shard - 1);
  }

  const test::ProcessOutcome stopped = slurm.stop();
  EXPECT_EQ(stopped.status, 0) << stopped.out << stopped.err;
  // No daemon, job step or lathesim of the test's is left (zombies awaiting PID 1 aside).
  EXPECT_EQ(test::processesLeftMentioning(dir.path().string(), std::chrono::seconds(10)), std::vector<std::string>{});
  EXPECT_EQ(test::processesMentioning("slurmstepd"), std::vector<std::string>{});
}

}  // namespace
}  // namespace lathesim::batch
