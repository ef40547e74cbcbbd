// Outputs appear whole or not at all, whatever stops the run: SIGINT or SIGTERM while it
// simulates or while it writes (exit 130 / 143), an --out that takes no files, a file system
// that fills up, a file size limit. The command runs as a process, as a user runs it.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "batch/child_process.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using test::readFile;

using test::kBinary;
using test::kPartsDir;
const std::set<std::string> kRunOutputs{"part.stl", "part.png", "toolpath.csv", "toolpath.vtp", "stock.vdb",
                                        "report.json", "report.html"};

std::vector<std::string> runArgs(const std::string& part, const fs::path& out, const std::string& voxel) {
  return {"run", (kPartsDir / part / "program.nc").string(), "--setup", (kPartsDir / part / "setup.toml").string(),
          "--out", out.string(), "--voxel", voxel};
}

std::set<std::string> namesIn(const fs::path& folder) {
  std::set<std::string> names;
  std::error_code ignored;
  if (fs::is_directory(folder, ignored))
    for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}

bool holdsStagedFile(const fs::path& folder) {
  for (const auto& name : namesIn(folder))
    if (name.rfind(".tmp-", 0) == 0 && name.find("probe") == std::string::npos) return true;
  return false;
}

struct Ended {
  int exitStatus = -1;  // -1: ended by a signal it did not catch
  std::string log;
};

// Starts a run of `part` at `voxel`, waits until `ready` says so, sends `signal` and waits for
// the end.
template <class Ready>
Ended interruptRun(const fs::path& scratch, const std::string& part, const std::string& voxel, const fs::path& out,
                   int signal, Ready ready) {
  const fs::path log = scratch / "run.log";
  fs::remove(log);
  batch::ChildProcess run = batch::ChildProcess::start(kBinary, runArgs(part, out, voxel), log);
  const auto deadline = Clock::now() + std::chrono::seconds(60);
  while (!ready() && Clock::now() < deadline) std::this_thread::sleep_for(std::chrono::microseconds(200));
  ::kill(run.pid(), signal);
  const int status = run.wait();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readFile(log)};
}

TEST(InterruptedRun, SigintWhileSimulatingExits130AndWritesNothing) {
  test::ScratchDir scratch("sigint");
  const fs::path out = scratch.path() / "nested" / "out";
  // The run makes --out (its signal handlers already set) just before it simulates, which at
  // 0.1 mm takes seconds: a fixed delay instead let a loaded machine's signal land while the
  // process was still loading its libraries.
  std::optional<Clock::time_point> outMade;
  const Ended ended = interruptRun(scratch.path(), "seed000-face-taper", "0.1", out, SIGINT, [&] {
    if (!outMade && fs::exists(out)) outMade = Clock::now();
    return outMade && Clock::now() - *outMade > std::chrono::milliseconds(200);
  });
  EXPECT_EQ(ended.exitStatus, 130) << ended.log;
  EXPECT_NE(ended.log.find("stopped by SIGINT"), std::string::npos) << ended.log;
  EXPECT_FALSE(fs::exists(scratch.path() / "nested")) << "the folders the run made are removed";
}

// The signal lands while the output files are being written (the first staged file is seen;
// the render and four more files are still to come): the staged ones are removed, and no
// final name was ever given to a partial file.
TEST(InterruptedRun, SigtermWhileWritingExits143AndLeavesNoFile) {
  test::ScratchDir scratch("sigterm");
  const fs::path out = scratch.path() / "out";
  Ended ended;
  for (int attempt = 0; attempt < 3; ++attempt) {  // a run that finished first proves nothing
    fs::remove_all(out);
    fs::create_directories(out);
    ended = interruptRun(scratch.path(), "seed001-taper-r24", "0.25", out, SIGTERM, [&] { return holdsStagedFile(out); });
    ASSERT_TRUE(ended.exitStatus == 143 || ended.exitStatus == 0) << ended.log;
    if (ended.exitStatus == 0) EXPECT_EQ(namesIn(out), kRunOutputs);  // then everything is there
    else break;
  }
  ASSERT_EQ(ended.exitStatus, 143) << ended.log;
  EXPECT_NE(ended.log.find("stopped by SIGTERM"), std::string::npos) << ended.log;
  EXPECT_TRUE(namesIn(out).empty()) << "left: " << *namesIn(out).begin();
  EXPECT_TRUE(fs::exists(out)) << "a folder the user made stays";
}

// An --out where no file can be made is said before the simulation, and names the folder.
TEST(OutputFolder, UnwritableOutIsAClearErrorBeforeTheRun) {
  test::ScratchDir scratch("unwritable");
  const fs::path file = scratch.path() / "a-file";
  test::writeFile(file, "not a folder");
  std::vector<fs::path> outs = {file / "out"};
  if (::geteuid() != 0) {  // permissions bind everyone but root
    const fs::path locked = scratch.path() / "locked";
    fs::create_directories(locked);
    fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
    outs.push_back(locked);
  }
  for (const fs::path& out : outs) {
    SCOPED_TRACE(out.string());
    const auto start = Clock::now();
    const auto outcome = test::runProcess(kBinary, runArgs("seed000-face-taper", out, "0.1"), scratch.path());
    EXPECT_EQ(outcome.status, 1) << outcome.err;
    EXPECT_NE(outcome.err.find("lathesim: error: cannot write the outputs into '" + out.string() + "'"),
              std::string::npos)
        << outcome.err;
    EXPECT_LT(Clock::now() - start, std::chrono::seconds(3)) << "refused before simulating";
  }
  EXPECT_EQ(readFile(file), "not a folder");
}

// A file size limit (ulimit -f, with SIGXFSZ ignored, so that write() fails with EFBIG as a
// full disk fails with ENOSPC) below the size of stock.vdb, the first file written (while the
// part is meshed): the writer's failure is caught, named,
// and leaves nothing, not even the folder the run made. Needs no privilege.
TEST(OutputFailure, FileSizeLimitIsAClearErrorAndLeavesNothing) {
  test::ScratchDir scratch("fsize");
  const fs::path out = scratch.path() / "made" / "out";
  std::string command = "ulimit -f 64; trap '' XFSZ; exec '" + kBinary.string() + "'";
  for (const auto& arg : runArgs("seed001-taper-r24", out, "0.5")) command += " '" + arg + "'";
  const auto outcome = test::runProcess("/bin/bash", {"-c", command}, scratch.path());
  EXPECT_EQ(outcome.status, 1) << outcome.err;
  EXPECT_NE(outcome.err.find("lathesim: error: cannot write " + (out / "stock.vdb").string() +
                             ": File too large; no output was written"),
            std::string::npos)
      << outcome.err;
  EXPECT_FALSE(fs::exists(scratch.path() / "made"));
}

// A real full disk: a tmpfs in a mount namespace of the test's own (root only; skipped where
// mounting is not allowed), sized so that each output in turn is the one that finds it full
// (the files before it fit, it does not). Every writer's failure is caught and named, and the
// disk is left empty.
TEST(OutputFailure, FullDiskStopsEveryWriterAndLeavesNothing) {
  test::ScratchDir scratch("fulldisk");
  const fs::path whole = scratch.path() / "whole";
  const auto full = test::runProcess(kBinary, runArgs("seed001-taper-r24", whole, "0.5"), scratch.path());
  ASSERT_EQ(full.status, 0) << full.err;
  constexpr std::uintmax_t kPage = 4096;  // tmpfs gives files whole pages
  // stock.vdb first: it is written while the part is meshed.
  const std::vector<std::string> writeOrder = {"stock.vdb", "part.stl", "toolpath.csv", "toolpath.vtp", "part.png",
                                               "report.json", "report.html"};
  const fs::path disk = scratch.path() / "disk";
  fs::create_directories(disk);
  std::string script;
  std::uintmax_t before = 0;  // pages the files written before this one take
  for (const auto& name : writeOrder) {
    const std::uintmax_t pages = (fs::file_size(whole / name) + kPage - 1) / kPage;
    const std::uintmax_t size = (before + pages - 1) * kPage;  // one page short of holding it
    script += "mount -t tmpfs -o size=" + std::to_string(size == 0 ? kPage : size) + " tmpfs '" + disk.string() +
              "' || exit 77; '" + kBinary.string() + "'";
    for (const auto& arg : runArgs("seed001-taper-r24", disk / "out", "0.5")) script += " '" + arg + "'";
    script += " 2>&1 | grep 'lathesim: error'; echo \"left: $(ls -A '" + disk.string() + "')\"; umount '" +
              disk.string() + "'; ";
    before += pages;
  }
  const auto outcome = test::runProcess("/usr/bin/unshare", {"-m", "/bin/sh", "-c", script}, scratch.path());
  if (outcome.status != 0) GTEST_SKIP() << "cannot mount a tmpfs here: " << outcome.err;
  std::set<std::string> stopped;
  for (const auto& name : writeOrder) {
    const std::string message = "lathesim: error: cannot write " + (disk / "out" / name).string() +
                                ": No space left on device; no output was written";
    if (outcome.out.find(message) != std::string::npos) stopped.insert(name);
  }
  EXPECT_EQ(stopped, kRunOutputs) << outcome.out;
  std::size_t lines = 0;
  for (std::size_t at = 0; (at = outcome.out.find("left: \n", at)) != std::string::npos; ++at) ++lines;
  EXPECT_EQ(lines, writeOrder.size()) << outcome.out;
}

}  // namespace
}  // namespace lathesim::app
