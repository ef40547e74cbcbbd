#pragma once
// A job's lathesim process: started in a process group of its own, so that a time limit can
// kill it with everything it started, and tied to the batch, so that it dies with it.

#include <sys/types.h>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lathesim::batch {

/// lathesim's command line run in this process (main's body): the arguments after the program name.
using InProcessMain = std::function<int(const std::vector<std::string>& args)>;

class ChildProcess {
 public:
  /// Starts `binary` with `args`: stdin from /dev/null, stdout and stderr appended to
  /// `logFile`, no other descriptor inherited, signals unblocked and at their defaults, in a
  /// new process group, killed (SIGKILL) if the thread that started it ends. Throws
  /// std::runtime_error if it cannot be started; a binary that cannot be executed exits 127.
  static ChildProcess start(const std::filesystem::path& binary, const std::vector<std::string>& args,
                            const std::filesystem::path& logFile);

  /// The same, but the child is a fork of this process that runs `main(args)` and exits with
  /// what it returns, without exec: no program start, dynamic linking or static
  /// initialisation to pay again (about 0.06 s of CPU a job). The child runs ordinary code
  /// after fork, in which only the calling thread goes on: fork only while no other thread
  /// can be holding a lock the child needs (see threadCount()).
  static ChildProcess fork(const InProcessMain& main, const std::vector<std::string>& args,
                           const std::filesystem::path& logFile);

  ChildProcess(ChildProcess&& other) noexcept : pid_(other.pid_) { other.pid_ = -1; }
  ChildProcess& operator=(ChildProcess&& other) noexcept;
  ~ChildProcess();  // kills and reaps a process still running
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }
  /// The wait status (as waitpid gives it) if the process has ended, reaping it; else nullopt.
  std::optional<int> poll();
  /// Waits for the process to end; its wait status.
  int wait();
  /// Sends SIGKILL to the process's whole group.
  void killGroup();

 private:
  explicit ChildProcess(pid_t pid) : pid_(pid) {}
  pid_t pid_ = -1;  // -1 once reaped
};

/// The threads this process has now (0 if that cannot be read).
int threadCount();

}  // namespace lathesim::batch
