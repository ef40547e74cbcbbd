#include "app/watch/watch_command.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "app/watch/file_watch.hpp"
#include "app/watch/loopback_server.hpp"
#include "app/watch/watch_page.hpp"
#include "batch/html_text.hpp"
#include "setup/exit_status.hpp"

namespace lathesim::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// A save is often several writes (a temporary file, a rename): runs start after this much quiet.
constexpr auto kSettle = std::chrono::milliseconds(200);

int signalPipe[2] = {-1, -1};

void onSignal(int signal) {
  const unsigned char number = static_cast<unsigned char>(signal);
  [[maybe_unused]] const ssize_t ignored = ::write(signalPipe[1], &number, 1);
}

void catchStopSignals() {
  if (::pipe2(signalPipe, O_CLOEXEC | O_NONBLOCK) < 0) throw std::runtime_error("cannot make a pipe");
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(signal, &action, nullptr);
}

/// The value of option `name` in `arguments` (`--out DIR` or `--out=DIR`).
std::optional<std::string> optionValue(const std::vector<std::string>& arguments, const std::string& name) {
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    if (arguments[i] == name && i + 1 < arguments.size()) return arguments[i + 1];
    if (arguments[i].rfind(name + "=", 0) == 0) return arguments[i].substr(name.size() + 1);
  }
  return std::nullopt;
}

bool hasOption(const std::vector<std::string>& arguments, const std::string& name) {
  return std::any_of(arguments.begin(), arguments.end(),
                     [&](const std::string& a) { return a == name || a.rfind(name + "=", 0) == 0; });
}

/// The files and folders the run reads: every argument (or option value) naming one, but the
/// output folder.
std::vector<fs::path> inputsOf(const std::vector<std::string>& arguments, const fs::path& out) {
  std::vector<fs::path> inputs;
  for (const auto& argument : arguments) {
    const auto equals = argument.rfind("--", 0) == 0 ? argument.find('=') : std::string::npos;
    const fs::path path = equals == std::string::npos ? argument : argument.substr(equals + 1);
    std::error_code error;
    if (!fs::exists(path, error) || fs::equivalent(path, out, error)) continue;
    inputs.push_back(path);
  }
  return inputs;
}

std::string contentTypeOf(const fs::path& file) {
  const std::string extension = file.extension().string();
  if (extension == ".html") return "text/html; charset=utf-8";
  if (extension == ".json") return "application/json";
  if (extension == ".png") return "image/png";
  if (extension == ".gif") return "image/gif";
  if (extension == ".mp4") return "video/mp4";
  if (extension == ".csv" || extension == ".txt") return "text/plain; charset=utf-8";
  if (extension == ".gltf") return "model/gltf+json";
  if (extension == ".glb") return "model/gltf-binary";
  return "application/octet-stream";
}

/// A file of the output folder named by a request path, or nullopt when the path leaves the
/// folder (.., a hidden name, a link out of it) or names no file.
std::optional<fs::path> outputFile(const fs::path& out, const std::string& requested) {
  const fs::path relative = fs::path(requested).relative_path();
  if (relative.empty()) return std::nullopt;
  for (const auto& part : relative)
    if (part.empty() || part.string().front() == '.') return std::nullopt;  // "..", ".hidden"
  std::error_code error;
  const fs::path file = fs::weakly_canonical(out / relative, error);
  const fs::path folder = fs::weakly_canonical(out, error);
  if (error || !fs::is_regular_file(file, error)) return std::nullopt;
  const auto [end, _] = std::mismatch(folder.begin(), folder.end(), file.begin(), file.end());
  if (end != folder.end()) return std::nullopt;
  return file;
}

/// One run of the program, as a child process whose diagnostics come through a pipe.
struct Run {
  pid_t pid = -1;
  int diagnostics = -1;  // the read end of its stderr
  std::string text;      // what it printed there
};

Run startRun(const std::string& command, const std::vector<std::string>& arguments) {
  int pipe[2];
  if (::pipe2(pipe, O_CLOEXEC) < 0) throw std::runtime_error("cannot make a pipe");
  std::vector<std::string> words{"lathesim", command};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("cannot start a run (fork)");
  if (pid == 0) {  // only async-signal-safe calls until exec
    struct sigaction initial {};
    initial.sa_handler = SIG_DFL;
    for (int signal : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(signal, &initial, nullptr);
    if (::dup2(pipe[1], 2) < 0) ::_exit(126);
    ::execv("/proc/self/exe", argv.data());
    ::_exit(127);
  }
  ::close(pipe[1]);
  return Run{pid, pipe[0], {}};
}

int exitStatusOf(int waited) {
  if (WIFEXITED(waited)) return WEXITSTATUS(waited);
  return 128 + (WIFSIGNALED(waited) ? WTERMSIG(waited) : 0);
}

bool wroteOutputs(int status) {
  return status == setup::kExitOk || status == setup::kExitOutOfTolerance || status == setup::kExitCrash;
}

class Watcher {
 public:
  Watcher(const WatchOptions& options)
      : arguments_(options.arguments),
        command_(hasOption(arguments_, "--target") || hasOption(arguments_, "--target-program") ? "check" : "run"),
        out_(optionValue(arguments_, "--out").value_or("out")),
        inputs_(inputsOf(arguments_, out_)),
        files_(inputs_),
        server_(options.port) {}

  int run() {
    std::string names;
    for (const auto& input : inputs_) names += (names.empty() ? "" : ", ") + input.string();
    std::cout << "lathesim watch: http://127.0.0.1:" << server_.port() << "/ shows " << (out_ / "report.html").string()
              << "; `lathesim " << command_ << "` runs again whenever " << (names.empty() ? "an input" : names)
              << " is saved. Ctrl-C stops." << std::endl;
    pendingSince_ = Clock::now() - kSettle;  // the first run at once
    for (;;) {
      if (pendingSince_ && !run_ && Clock::now() - *pendingSince_ >= kSettle) {
        pendingSince_.reset();
        run_ = startRun(command_, arguments_);
        state_.running = true;
      }
      pollfd ready[4] = {{signalPipe[0], POLLIN, 0}, {server_.fd(), POLLIN, 0}, {files_.fd(), POLLIN, 0},
                         {run_ ? run_->diagnostics : -1, POLLIN, 0}};
      if (::poll(ready, 4, pendingSince_ ? 50 : -1) < 0 && errno != EINTR) return setup::kExitBadInput;
      if (ready[0].revents) return stop();
      if (ready[2].revents && files_.changed()) pendingSince_ = Clock::now();
      if (ready[3].revents && !readDiagnostics()) {
        const int status = finishRun();
        if (status == setup::kExitBadCommandLine && state_.generation == 1) return status;  // no save cures it
      }
      if (ready[1].revents) server_.serveOne([this](const std::string& path) { return respond(path); });
    }
  }

 private:
  /// Reads what the run printed and passes it on; false at its end.
  bool readDiagnostics() {
    char chunk[4096];
    const ssize_t got = ::read(run_->diagnostics, chunk, sizeof chunk);
    if (got <= 0) return false;
    run_->text.append(chunk, static_cast<std::size_t>(got));
    std::cerr.write(chunk, got).flush();
    return true;
  }

  int finishRun() {
    int waited = 0;
    ::waitpid(run_->pid, &waited, 0);
    ::close(run_->diagnostics);
    const int status = exitStatusOf(waited);
    ++state_.generation;
    state_.running = false;
    state_.status = status;
    state_.error = wroteOutputs(status) ? std::string() : run_->text;
    if (wroteOutputs(status)) state_.goodGeneration = state_.generation;
    run_.reset();
    return status;
  }

  int stop() {
    unsigned char signal = SIGINT;
    [[maybe_unused]] const ssize_t ignored = ::read(signalPipe[0], &signal, 1);
    if (run_) {
      ::kill(run_->pid, signal);  // it cleans up as any interrupted run does
      while (readDiagnostics()) {
      }
      finishRun();
    }
    std::cerr << "lathesim watch: stopped\n";
    return 128 + signal;
  }

  HttpResponse respond(const std::string& path) {
    if (path == "/watch/state") return {200, "application/json", stateJson(state_)};
    if (path == "/" || path == "/report.html") {
      const fs::path report = out_ / "report.html";
      if (state_.goodGeneration == 0 || !fs::exists(report)) return {200, "text/html; charset=utf-8", waitingPage(state_)};
      return {200, "text/html; charset=utf-8", withWatchScript(batch::fileBytes(report), state_)};
    }
    const auto file = outputFile(out_, path);
    if (!file) return {404, "text/plain; charset=utf-8", "no such output: " + path + "\n"};
    return {200, contentTypeOf(*file), batch::fileBytes(*file)};
  }

  std::vector<std::string> arguments_;
  std::string command_;
  fs::path out_;
  std::vector<fs::path> inputs_;
  FileWatch files_;
  LoopbackServer server_;
  WatchState state_;
  std::optional<Run> run_;
  std::optional<Clock::time_point> pendingSince_;
};

}  // namespace

int watchCommand(const WatchOptions& options) {
  catchStopSignals();
  Watcher watcher(options);
  return watcher.run();
}

}  // namespace lathesim::app
