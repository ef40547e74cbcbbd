#pragma once
// `lathesim batch merge`: the summaries of a batch's shards joined into the summary of the
// whole batch, as one machine would have written it.

#include <filesystem>
#include <optional>
#include <vector>

namespace lathesim::batch {

/// Reads the shards' summary JSON files (summary-I-of-N.json) and writes summary.json,
/// .csv and .html into `out` (default: the first file's folder), with every job's folder
/// relative to it. Every shard of the batch must be given exactly once. Returns the whole
/// batch's exit status (0, 1 or 3, as `lathesim batch`), or 1 after printing what is wrong.
int mergeSummaries(const std::vector<std::filesystem::path>& files, const std::optional<std::filesystem::path>& out);

}  // namespace lathesim::batch
