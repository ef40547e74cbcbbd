#include "render/offscreen_display.hpp"

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

// Last: Xlib defines macros (None, Bool, Status) that clash with everything else.
#include <X11/Xlib.h>

namespace lathesim::render {
namespace {

const char* const kInstallHint =
    "no X display is reachable and a private Xvfb server could not be started; "
    "install the `xvfb` package (e.g. `sudo apt-get install xvfb`)";

std::runtime_error xvfbError(const std::string& why) {
  return std::runtime_error(std::string(kInstallHint) + ": " + why);
}

/// The executable `program` resolves to through PATH, or "" if none.
std::string findExecutable(const std::string& program) {
  if (program.find('/') != std::string::npos) {
    return ::access(program.c_str(), X_OK) == 0 ? program : std::string{};
  }
  const char* pathEnv = std::getenv("PATH");
  const std::string path = pathEnv ? pathEnv : "/usr/local/bin:/usr/bin:/bin";
  std::size_t begin = 0;
  while (begin <= path.size()) {
    std::size_t end = path.find(':', begin);
    if (end == std::string::npos) end = path.size();
    // An empty PATH entry means the current directory. (Built without assigning a literal to
    // a string: gcc 12 warns falsely, -Wrestrict, on `dir = "."`.)
    std::string candidate = end > begin ? path.substr(begin, end - begin) : std::string(1, '.');
    candidate += '/';
    candidate += program;
    struct stat st {};
    if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
        ::access(candidate.c_str(), X_OK) == 0) {
      return candidate;
    }
    begin = end + 1;
  }
  return {};
}

/// Moves `fd` above the standard streams (which the child overwrites), close-on-exec.
int aboveStdStreams(int fd) {
  if (fd > STDERR_FILENO) return fd;
  const int moved = ::fcntl(fd, F_DUPFD_CLOEXEC, STDERR_FILENO + 1);
  ::close(fd);
  if (moved < 0) throw std::runtime_error(std::string("fcntl: ") + std::strerror(errno));
  return moved;
}

/// Waits up to `timeout` for `pid` to exit; true if it did (and was reaped).
bool reapWithin(pid_t pid, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    int status = 0;
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid || (r < 0 && errno == ECHILD)) return true;
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

}  // namespace

bool displayIsReachable(const std::string& display) {
  if (display.empty()) return false;
  Display* connection = XOpenDisplay(display.c_str());
  if (connection == nullptr) return false;
  XCloseDisplay(connection);
  return true;
}

std::unique_ptr<XvfbServer> XvfbServer::start(const std::string& program, double timeoutSeconds) {
  const std::string executable = findExecutable(program);
  if (executable.empty()) throw xvfbError("`" + program + "` not found in PATH");

  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw xvfbError(std::string("pipe: ") + std::strerror(errno));
  // With stdin closed, pipe() may hand out fd 0; the child's dup2 onto 0–2 would clobber it.
  const int readFd = aboveStdStreams(fds[0]);
  const int writeFd = aboveStdStreams(fds[1]);
  const int devNull = aboveStdStreams(::open("/dev/null", O_RDWR | O_CLOEXEC));

  // Everything the child needs is prepared before fork: after it, only async-signal-safe calls.
  const std::string fdArg = std::to_string(writeFd);
  std::vector<std::string> args = {executable, "-displayfd", fdArg, "-screen", "0",
                                   "1600x1200x24", "-nolisten", "tcp", "-noreset"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t parent = ::getpid();

  const pid_t pid = ::fork();
  if (pid < 0) {
    const int err = errno;
    ::close(readFd), ::close(writeFd), ::close(devNull);
    throw xvfbError(std::string("fork: ") + std::strerror(err));
  }
  if (pid == 0) {
    // Child. Die with the parent, even if it is killed or aborts (no destructors run then).
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::_exit(126);
    // Own process group: a Ctrl-C at the terminal goes to lathesim, which then cleans up.
    ::setpgid(0, 0);
    ::dup2(devNull, STDIN_FILENO);
    ::dup2(devNull, STDOUT_FILENO);
    ::dup2(devNull, STDERR_FILENO);
    ::fcntl(writeFd, F_SETFD, 0);  // the one descriptor Xvfb inherits
    ::execv(executable.c_str(), argv.data());
    ::_exit(127);
  }
  ::close(writeFd);
  ::close(devNull);

  // Xvfb writes "<display number>\n" once it accepts connections.
  std::string answer;
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
  std::string failure;
  while (answer.find('\n') == std::string::npos) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      failure = "`" + executable + "` did not report a display within " +
                std::to_string(timeoutSeconds) + " s";
      break;
    }
    pollfd p{readFd, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) {
      failure = std::string("poll: ") + std::strerror(errno);
      break;
    }
    if (ready == 0) continue;  // deadline check above
    char buffer[64];
    const ssize_t n = ::read(readFd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      failure = "`" + executable + "` exited before reporting a display";
      break;
    }
    answer.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(readFd);

  if (failure.empty()) {
    const std::string number = answer.substr(0, answer.find('\n'));
    if (number.empty() || number.find_first_not_of("0123456789") != std::string::npos) {
      failure = "`" + executable + "` reported an unreadable display \"" + number + "\"";
    } else {
      return std::unique_ptr<XvfbServer>(new XvfbServer(pid, ":" + number));
    }
  }
  ::kill(pid, SIGKILL);
  reapWithin(pid, std::chrono::seconds(2));
  throw xvfbError(failure);
}

bool XvfbServer::running() {
  if (pid_ <= 0) return false;
  int status = 0;
  const pid_t r = ::waitpid(pid_, &status, WNOHANG);
  if (r == pid_) {
    pid_ = -1;  // reaped: nothing left to stop
    return false;
  }
  return r == 0 || ::kill(pid_, 0) == 0;  // not our child (a fork's copy of the object): is it alive?
}

XvfbServer::~XvfbServer() {
  if (pid_ <= 0) return;
  ::kill(pid_, SIGTERM);
  if (!reapWithin(pid_, std::chrono::seconds(2))) {
    ::kill(pid_, SIGKILL);
    reapWithin(pid_, std::chrono::seconds(2));
  }
}

std::string ensureDisplay() {
  static std::mutex mutex;
  // Function-local static: destroyed (server terminated) at normal process exit, after
  // everything constructed later — VTK windows are gone by then.
  static std::unique_ptr<XvfbServer> ownServer;
  // The display last found reachable: a run asks before each picture, and connecting to ask
  // costs a round trip to the server (a batch's forked jobs inherit the answer). Our own
  // server is asked again only if its process has gone.
  static std::string reached;
  const std::lock_guard<std::mutex> lock(mutex);

  const char* current = std::getenv("DISPLAY");
  const bool ownGone = ownServer && ownServer->display() == reached && !ownServer->running();
  if (current != nullptr && current == reached && !ownGone) return reached;
  if (current != nullptr && displayIsReachable(current)) return reached = current;
  if (!ownServer || !displayIsReachable(ownServer->display())) {
    ownServer.reset();
    ownServer = XvfbServer::start();
    if (!displayIsReachable(ownServer->display())) {
      throw xvfbError("the Xvfb server on " + ownServer->display() + " refuses connections");
    }
  }
  ::setenv("DISPLAY", ownServer->display().c_str(), 1);
  return reached = ownServer->display();
}

}  // namespace lathesim::render
