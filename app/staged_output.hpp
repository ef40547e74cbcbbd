#pragma once
// Output files appear whole or not at all: each is written under a temporary name in the
// output folder and renamed into place only when every file of the run is complete. A
// failed write, an exception or an interrupt (app/interrupts.hpp) leaves nothing behind:
// not the temporaries, nor the folders made for them.
// The folder holds one run: at the commit, the files a previous run wrote there
// (app/output_names.hpp) that this run does not write are removed. Anything else in it is
// left alone, and listed (foreignFiles) for a warning.

#include <filesystem>
#include <functional>
#include <future>
#include <mutex>
#include <ostream>
#include <string>
#include <vector>

namespace lathesim::app {

class StagedOutput {
 public:
  /// Makes the folder (and its missing parents) and checks that a file can be made in it;
  /// throws std::runtime_error saying why not ("cannot write the outputs into …").
  explicit StagedOutput(std::filesystem::path folder);
  ~StagedOutput();  // removes whatever was staged but not committed, and the folders made
  StagedOutput(const StagedOutput&) = delete;
  StagedOutput& operator=(const StagedOutput&) = delete;

  /// Writes `folder/name` through `writer`, given the temporary path, and returns that path
  /// (several threads may write at once, each its own file); the writer's failure (an
  /// exception, a full disk) throws std::runtime_error naming the final file. The file is
  /// synced to the disk in the background: syncWritten() and commit() wait for it.
  std::filesystem::path write(const std::string& name, const std::function<void(const std::filesystem::path&)>& writer);
  /// Where to write the file that will become `folder/name`, for a writer that another
  /// process runs (ffmpeg); write() when lathesim writes it.
  std::filesystem::path stage(const std::string& name);
  /// Waits until every file written so far is on the disk. A file that could not be synced
  /// (a full disk found at write-back, a quota) throws std::runtime_error naming it.
  void syncWritten();
  /// syncWritten(), then renames every staged file into place (nothing, if a sync failed), and
  /// removes the previous run's outputs that this run did not write.
  void commit();
  /// What the folder held that lathesim does not write, as found when it was opened (sorted):
  /// the user's files, left alone.
  const std::vector<std::string>& foreignFiles() const { return foreign_; }

 private:
  std::filesystem::path folder_;
  std::vector<std::filesystem::path> madeFolders_;  // outermost first
  std::mutex stagedMutex_;  // over staged_ and syncs_: files are written from several threads
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>> staged_;  // temp, final
  struct Sync {
    std::filesystem::path final, temp;
    std::future<void> done;
  };
  std::vector<Sync> syncs_;  // of the files write() wrote
  std::vector<std::string> previous_;  // the output files the folder held when opened
  std::vector<std::string> foreign_;   // the other files and folders it held
};

/// Writes `file` through a stream; throws std::runtime_error with the system's reason (a
/// full disk: "No space left on device") if any of it could not be written.
void writeTextFile(const std::filesystem::path& file, const std::function<void(std::ostream&)>& write);

}  // namespace lathesim::app
