#include "batch/child_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <stdexcept>

namespace lathesim::batch {
namespace {

std::runtime_error failure(const std::string& what) {
  return std::runtime_error("cannot start a job: " + what + ": " + std::strerror(errno));
}

/// In the child, right after fork: its own process group, tied to the batch, signals at their
/// defaults, stdin from /dev/null, stdout and stderr to the log, no other descriptor.
/// Everything here is async-signal-safe.
void prepareJob(int logFd, int nullFd, pid_t batch) {
  ::setpgid(0, 0);
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != batch) ::_exit(126);  // the batch is already gone
  sigset_t none;
  sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGCHLD}) ::signal(sig, SIG_DFL);
  ::dup2(nullFd, STDIN_FILENO);
  ::dup2(logFd, STDOUT_FILENO);
  ::dup2(logFd, STDERR_FILENO);
  // Nothing else of the batch's: a held descriptor (a pipe of the caller's) could keep a
  // reader waiting long after the batch ended.
  if (::syscall(SYS_close_range, 3U, ~0U, 0U) != 0)
    for (int fd = 3; fd < 1024; ++fd) ::close(fd);
}

/// Opens the log (appended) and /dev/null, forks, and runs `job` in the child (which must
/// not return); the parent gets the child's pid.
template <class Job>
pid_t forkJob(const std::filesystem::path& logFile, const Job& job) {
  const int logFd = ::open(logFile.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (logFd < 0) throw failure("cannot open " + logFile.string());
  const int nullFd = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  if (nullFd < 0) {
    ::close(logFd);
    throw failure("cannot open /dev/null");
  }
  const pid_t batch = ::getpid();
  const pid_t pid = ::fork();
  if (pid == 0) {
    prepareJob(logFd, nullFd, batch);
    job();
  }
  const int forkErrno = errno;
  ::close(logFd);
  ::close(nullFd);
  if (pid < 0) {
    errno = forkErrno;
    throw failure("fork");
  }
  ::setpgid(pid, pid);  // also here: a kill right after start must find the group
  return pid;
}

}  // namespace

ChildProcess ChildProcess::start(const std::filesystem::path& binary, const std::vector<std::string>& args,
                                 const std::filesystem::path& logFile) {
  // Prepared before fork: after it, only async-signal-safe calls.
  const std::string program = binary.string();
  std::vector<std::string> words{program};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  return ChildProcess(forkJob(logFile, [&] {
    ::execv(program.c_str(), argv.data());
    ::_exit(127);
  }));
}

ChildProcess ChildProcess::fork(const InProcessMain& main, const std::vector<std::string>& args,
                                const std::filesystem::path& logFile) {
  // What the batch has buffered would otherwise be written by the child too, into the job's log.
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  return ChildProcess(forkJob(logFile, [&] {
    int status = 70;  // EX_SOFTWARE, should anything escape main
    try {
      status = main(args);
    } catch (const std::exception& e) {
      std::cerr << "lathesim: internal error: " << e.what() << '\n';
    } catch (...) {
      std::cerr << "lathesim: internal error\n";
    }
    // _exit, not exit: the batch's static objects (its Xvfb among them) are the batch's to end.
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    ::_exit(status);
  }));
}

int threadCount() {
  std::error_code ec;
  int threads = 0;
  for (auto it = std::filesystem::directory_iterator("/proc/self/task", ec); !ec && it != std::filesystem::directory_iterator();
       it.increment(ec))
    ++threads;
  return ec ? 0 : threads;
}

ChildProcess& ChildProcess::operator=(ChildProcess&& other) noexcept {
  if (this != &other) {
    if (pid_ > 0) {
      killGroup();
      wait();
    }
    pid_ = other.pid_;
    other.pid_ = -1;
  }
  return *this;
}

ChildProcess::~ChildProcess() {
  if (pid_ <= 0) return;
  killGroup();
  wait();
}

std::optional<int> ChildProcess::poll() {
  if (pid_ <= 0) return std::nullopt;
  int status = 0;
  const pid_t r = ::waitpid(pid_, &status, WNOHANG);
  if (r != pid_) return std::nullopt;
  pid_ = -1;
  return status;
}

int ChildProcess::wait() {
  int status = 0;
  while (pid_ > 0) {
    const pid_t r = ::waitpid(pid_, &status, 0);
    if (r == pid_ || (r < 0 && errno != EINTR)) pid_ = -1;
  }
  return status;
}

void ChildProcess::killGroup() {
  if (pid_ > 0) ::kill(-pid_, SIGKILL);
}

}  // namespace lathesim::batch
