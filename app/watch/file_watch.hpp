#pragma once
// Which of a run's input files were saved: inotify on the folders that hold them, since an
// editor often saves by writing a new file and renaming it over the old one (the old file's own
// watch would then see nothing more). A folder named as an input (--programs) counts as changed
// when any file in it is written, made, renamed or removed.

#include <filesystem>
#include <vector>

namespace lathesim::app {

class FileWatch {
 public:
  /// Watches `inputs` (files and folders that exist); throws std::runtime_error if the
  /// system's inotify cannot be used.
  explicit FileWatch(const std::vector<std::filesystem::path>& inputs);
  ~FileWatch();
  FileWatch(const FileWatch&) = delete;
  FileWatch& operator=(const FileWatch&) = delete;

  int fd() const { return inotify_; }  // readable when events wait

  /// Reads the waiting events; true if one of them concerns an input.
  bool changed();

 private:
  struct Watched {
    int watch = -1;
    bool wholeFolder = false;        // the folder is an input itself
    std::vector<std::string> names;  // the input files in it
  };
  int inotify_ = -1;
  std::vector<Watched> watched_;
};

}  // namespace lathesim::app
