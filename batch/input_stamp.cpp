#include "batch/input_stamp.hpp"

#include <fstream>
#include <sstream>

#include "batch/content_hash.hpp"

namespace lathesim::batch {

std::string inputStamp(const BatchJob& job, const std::string& buildId) {
  ContentHash hash;
  hash.add(buildId);
  const std::vector<std::string> args = commandArguments(job, "");
  std::error_code ec;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--out") {
      ++i;  // where the outputs go is not an input
      continue;
    }
    if (!args[i].empty() && std::filesystem::is_regular_file(args[i], ec)) {
      hash.add("file");
      hash.addFile(args[i]);
    } else {
      hash.add(args[i]);
    }
  }
  return hash.hex();
}

void writeStamp(const std::filesystem::path& folder, const std::string& inputs, const JobResult& result) {
  nlohmann::ordered_json stamp;
  stamp["inputs"] = inputs;
  stamp["result"] = toJson(result);
  const auto temporary = folder / (std::string(kStampFileName) + ".tmp");
  {
    std::ofstream out(temporary);
    out << stamp.dump(2) << '\n';
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  std::filesystem::rename(temporary, folder / kStampFileName);
}

std::optional<JobResult> stampedResult(const std::filesystem::path& folder, const std::string& inputs,
                                       const BatchJob& job) {
  std::ifstream in(folder / kStampFileName);
  if (!in) return std::nullopt;
  try {
    const nlohmann::json stamp = nlohmann::json::parse(in);
    if (stamp.at("inputs").get<std::string>() != inputs) return std::nullopt;
    JobResult result = resultFromJson(stamp.at("result"));
    if (result.status == JobStatus::Crashed || result.status == JobStatus::NotRun) return std::nullopt;
    if (result.status == JobStatus::Timeout && result.timeLimitS != job.settings.timeLimitS) return std::nullopt;
    // The manifest may have moved or renamed the job: its place, name and paths are today's.
    result.index = job.index;
    result.name = job.name;
    result.program = job.program.string();
    result.timeLimitS = job.settings.timeLimitS;
    result.resumed = true;
    return result;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;  // a damaged stamp: run the job again
  }
}

}  // namespace lathesim::batch
