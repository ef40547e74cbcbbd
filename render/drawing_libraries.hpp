#pragma once
// The shared libraries a process loads only when it first draws, loaded ahead into a process
// that forks many others (batch/), so that each fork finds them loaded.
//
// A picture's first window makes GLX load the vendor library and the Mesa driver, and LLVM
// under it: about 30 libraries, 26 ms of CPU a forked job spent linking them (relocations,
// LLVM's static constructors) before drawing anything. OpenGL itself cannot be started
// before a fork: a context starts the driver's threads, and a process with threads must not
// fork. Loading the libraries starts none.

#include <optional>

#include <sys/types.h>

namespace lathesim::render {

/// Learns in a child process which libraries drawing loads, and loads them here.
class DrawingLibrariesPreload {
 public:
  /// Forks a child that draws a 1×1 picture and lists the libraries it has loaded then. Needs
  /// a reachable DISPLAY (ensureDisplay); the child costs about 0.1 s of CPU. Starts no thread.
  DrawingLibrariesPreload();
  ~DrawingLibrariesPreload();  // kills and reaps the child if it still runs
  DrawingLibrariesPreload(const DrawingLibrariesPreload&) = delete;
  DrawingLibrariesPreload& operator=(const DrawingLibrariesPreload&) = delete;

  /// Without waiting: nullopt while the child runs; once it has ended, loads into this
  /// process, for good, every library it listed that this process has not, and returns how
  /// many (0, and nothing loaded, if the child could not draw). Called again: 0.
  std::optional<int> loadIfDone();

 private:
  pid_t pid_ = -1;
  int listFd_ = -1;  // the child's list comes through this pipe
};

}  // namespace lathesim::render
