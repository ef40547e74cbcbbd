#include "batch/merge.hpp"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>

#include "batch/summary.hpp"

namespace lathesim::batch {
namespace {

namespace fs = std::filesystem;

std::optional<BatchSummary> readSummary(const fs::path& file) {
  std::ifstream in(file);
  if (!in) {
    std::cerr << file.string() << ": error: cannot read the summary\n";
    return std::nullopt;
  }
  try {
    return summaryFromJson(nlohmann::json::parse(in));
  } catch (const nlohmann::json::exception& e) {
    std::cerr << file.string() << ": error: not a lathesim batch summary (" << e.what() << ")\n";
    return std::nullopt;
  }
}

/// `folder`, relative to `from`, made relative to `to`.
std::string rebased(const std::string& folder, const fs::path& from, const fs::path& to) {
  return fs::absolute(from / folder).lexically_normal().lexically_relative(fs::absolute(to).lexically_normal()).generic_string();
}

}  // namespace

int mergeSummaries(const std::vector<fs::path>& files, const std::optional<fs::path>& out) {
  if (files.empty()) {
    std::cerr << "lathesim batch merge: error: give the shards' summary files (summary-I-of-N.json)\n";
    return kExitSomeFailed;
  }
  const fs::path folder = out.value_or(files.front().parent_path().empty() ? fs::path(".") : files.front().parent_path());
  std::optional<BatchSummary> merged;
  std::map<int, fs::path> shardFiles;
  bool ok = true;
  for (const fs::path& file : files) {
    std::optional<BatchSummary> part = readSummary(file);
    if (!part) {
      ok = false;
      continue;
    }
    if (merged && (part->jobsHash != merged->jobsHash || part->shard.count != merged->shard.count)) {
      std::cerr << file.string() << ": error: a shard of another batch (" << part->source << ", "
                << part->shard.count << " shards) than " << files.front().string() << " (" << merged->source << ", "
                << merged->shard.count << " shards)\n";
      ok = false;
      continue;
    }
    if (merged && part->buildId != merged->buildId)
      std::cerr << file.string() << ": warning: run by another lathesim build (" << part->buildId << ") than "
                << files.front().string() << " (" << merged->buildId << ")\n";
    const auto [previous, added] = shardFiles.emplace(part->shard.index, file);
    if (!added) {
      std::cerr << file.string() << ": error: shard " << part->shard.tag() << " is also " << previous->second.string()
                << '\n';
      ok = false;
      continue;
    }
    for (JobResult& job : part->jobs) job.folder = rebased(job.folder, file.parent_path(), folder);
    if (!merged) {
      merged = std::move(part);
    } else {
      for (auto& job : part->jobs) merged->jobs.push_back(std::move(job));
    }
  }
  if (!merged) return kExitSomeFailed;
  for (int i = 1; i <= merged->shard.count; ++i)
    if (!shardFiles.count(i)) {
      std::cerr << "lathesim batch merge: error: shard " << i << "-of-" << merged->shard.count
                << " is missing (its summary-" << i << "-of-" << merged->shard.count << ".json)\n";
      ok = false;
    }
  if (!ok) return kExitSomeFailed;
  if (static_cast<int>(merged->jobs.size()) != merged->jobsInBatch) {
    std::cerr << "lathesim batch merge: error: the shards hold " << merged->jobs.size() << " jobs, the batch "
              << merged->jobsInBatch << '\n';
    return kExitSomeFailed;
  }
  std::sort(merged->jobs.begin(), merged->jobs.end(),
            [](const JobResult& a, const JobResult& b) { return a.index < b.index; });
  merged->shard = Shard{};
  fs::create_directories(folder);
  writeSummaryFiles(*merged, folder);
  std::cout << "batch merge: " << merged->countsText() << "; summary in " << (folder / "summary.html").string() << '\n';
  return merged->exitStatus();
}

}  // namespace lathesim::batch
