#include "batch/input_stamp.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "batch/content_hash.hpp"
#include "interp/text/program_library.hpp"

namespace lathesim::batch {

std::string InputStamper::stampOf(const BatchJob& job) {
  ContentHash hash;
  hash.add(buildId_);
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
  std::vector<std::filesystem::path> folders{job.program.parent_path().empty() ? "." : job.program.parent_path()};
  for (const auto& folder : optionValues(job.settings.options, "--programs")) folders.emplace_back(folder);
  for (const auto& folder : folders) hash.add(programFilesHash(folder));
  return hash.hex();
}

const std::string& InputStamper::programFilesHash(const std::filesystem::path& folder) {
  const std::filesystem::path key = folder.lexically_normal();
  if (const auto known = folderHashes_.find(key); known != folderHashes_.end()) return known->second;
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(key, ec))
    if (entry.is_regular_file(ec) && interp::isProgramFileName(entry.path().filename().string()))
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  ContentHash hash;
  for (const auto& file : files) {
    hash.add(file.filename().string());
    hash.addFile(file);
  }
  return folderHashes_[key] = hash.hex();
}

void writeStamp(const std::filesystem::path& folder, const std::string& inputs, const JobResult& result) {
  nlohmann::ordered_json stamp;
  stamp["inputs"] = inputs;
  stamp["result"] = toJson(result);
  const auto temporary = folder / (std::string(kStampFileName) + ".tmp");
  {
    std::ofstream out(temporary);
    out << stamp.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << '\n';
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
