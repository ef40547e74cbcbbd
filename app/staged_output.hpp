#pragma once
// Output files appear whole or not at all: each is written under a temporary name in the
// output folder and renamed into place only when every file of the run is complete.

#include <filesystem>
#include <vector>

namespace lathesim::app {

class StagedOutput {
 public:
  explicit StagedOutput(std::filesystem::path folder);
  ~StagedOutput();  // removes whatever was staged but not committed, and the folder if it made it
  StagedOutput(const StagedOutput&) = delete;
  StagedOutput& operator=(const StagedOutput&) = delete;

  /// Where to write the file that will become `folder/name` (the folder is made at the first).
  std::filesystem::path stage(const std::string& name);
  /// Where the file that will become `folder/name` was staged (std::out_of_range if it was not).
  std::filesystem::path staged(const std::string& name) const;
  /// Renames every staged file into place.
  void commit();

 private:
  std::filesystem::path folder_;
  bool madeFolder_ = false;
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>> staged_;  // temp, final
};

}  // namespace lathesim::app
