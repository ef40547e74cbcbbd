#pragma once
// Running the lathesim command as a process from a test, in a temporary folder of its own.

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/files.hpp"

namespace lathesim::test {

namespace fs = std::filesystem;


/// A fresh folder under the system's temporary directory, removed with everything in it.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& tag) {
    static int counter = 0;
    path_ = fs::temp_directory_path() /
            ("lathesim-" + tag + "-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

struct ProcessOutcome {
  int status = -1;  // the exit status, or -1 if the process did not exit normally
  std::string out;
  std::string err;
};

/// Runs `binary` with `args`, capturing stdout and stderr through files in `scratch`.
inline ProcessOutcome runProcess(const fs::path& binary, const std::vector<std::string>& args, const fs::path& scratch) {
  const auto quoted = [](const std::string& arg) {
    std::string q = "'";
    for (char c : arg) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  };
  const fs::path outFile = scratch / "stdout.txt";
  const fs::path errFile = scratch / "stderr.txt";
  std::string command = quoted(binary.string());
  for (const auto& arg : args) command.append(" ").append(quoted(arg));
  command.append(" >").append(quoted(outFile.string())).append(" 2>").append(quoted(errFile.string()));
  const int raw = std::system(command.c_str());
  ProcessOutcome outcome;
  if (raw != -1 && WIFEXITED(raw)) outcome.status = WEXITSTATUS(raw);
  outcome.out = readFile(outFile);
  outcome.err = readFile(errFile);
  fs::remove(outFile);
  fs::remove(errFile);
  return outcome;
}

#ifdef LATHESIM_BINARY
/// The lathesim command the tests were built with.
inline const fs::path kBinary = LATHESIM_BINARY;

/// Runs the lathesim command the tests were built with (the target's LATHESIM_BINARY) with
/// `args`, capturing stdout and stderr through files in `scratch`.
inline ProcessOutcome lathesim(const std::vector<std::string>& args, const fs::path& scratch) {
  return runProcess(LATHESIM_BINARY, args, scratch);
}
#endif

#ifdef LATHESIM_PARTS_DIR
/// The bundled parts (parts/ in the source tree).
inline const fs::path kPartsDir = LATHESIM_PARTS_DIR;

/// A bundled part's file, e.g. partFile("seed001-taper-r20", "setup.toml").
inline std::string partFile(const std::string& name, const std::string& file) { return (kPartsDir / name / file).string(); }
#endif

/// Nothing was written: the folder does not exist, or it is empty.
inline bool noOutputs(const fs::path& folder) { return !fs::exists(folder) || fs::is_empty(folder); }

/// Whether ffmpeg (which writes cut.mp4) is on this machine.
inline bool ffmpegInstalled() { return std::system("ffmpeg -version >/dev/null 2>&1") == 0; }

struct MeasuredOutcome {
  int status = -1;     // the exit status, or -1 if the process did not exit normally
  double peakMb = 0;   // its peak resident memory, as the kernel counted it (wait4's ru_maxrss)
  std::string err;
};

/// Runs `binary` with `args` (stdout thrown away, stderr captured through a file in `scratch`)
/// and measures its peak memory from outside: the whole process, whatever it notes itself, and
/// the children it waited for (the larger counts).
inline MeasuredOutcome runMeasured(const fs::path& binary, const std::vector<std::string>& args, const fs::path& scratch) {
  const std::string errFile = (scratch / "stderr.txt").string(), program = binary.string();
  std::vector<char*> argv{const_cast<char*>(program.c_str())};
  for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  MeasuredOutcome outcome;
  const pid_t pid = ::fork();
  if (pid < 0) return outcome;
  if (pid == 0) {  // only async-signal-safe calls until exec
    const int out = ::open("/dev/null", O_WRONLY), err = ::open(errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0 || ::dup2(out, 1) < 0 || ::dup2(err, 2) < 0) ::_exit(126);
    ::execv(program.c_str(), argv.data());
    ::_exit(127);
  }
  int status = 0;
  rusage usage{};
  if (::wait4(pid, &status, 0, &usage) != pid) return outcome;
  if (WIFEXITED(status)) outcome.status = WEXITSTATUS(status);
  outcome.peakMb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // KiB on Linux
  outcome.err = readFile(errFile);
  fs::remove(errFile);
  return outcome;
}

}  // namespace lathesim::test
