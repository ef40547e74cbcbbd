#include "app/staged_output.hpp"

#include <unistd.h>

#include <stdexcept>

namespace lathesim::app {

StagedOutput::StagedOutput(std::filesystem::path folder) : folder_(std::move(folder)) {}

StagedOutput::~StagedOutput() {
  std::error_code ignored;
  for (const auto& [temp, final] : staged_) std::filesystem::remove(temp, ignored);
  // A run that failed after its first file (ffmpeg missing, a disk full) leaves no empty folder.
  if (madeFolder_ && std::filesystem::is_empty(folder_, ignored)) std::filesystem::remove(folder_, ignored);
}

std::filesystem::path StagedOutput::stage(const std::string& name) {
  // At the first file: a run that fails before writes nothing.
  if (!std::filesystem::exists(folder_)) madeFolder_ = std::filesystem::create_directories(folder_);
  // The temporary keeps the real extension: some writers choose their format by it.
  const auto temp = folder_ / (".tmp-" + std::to_string(getpid()) + "-" + name);
  staged_.emplace_back(temp, folder_ / name);
  return temp;
}

std::filesystem::path StagedOutput::staged(const std::string& name) const {
  for (const auto& [temp, final] : staged_)
    if (final.filename() == name) return temp;
  throw std::out_of_range(name + " was not staged");
}

void StagedOutput::commit() {
  for (const auto& [temp, final] : staged_) std::filesystem::rename(temp, final);
  staged_.clear();
}

}  // namespace lathesim::app
