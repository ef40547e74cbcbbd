// A job's process: its exit status and output, its own process group (a kill takes what it
// started too), and nothing of the batch's it should not have.

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>

#include <atomic>
#include <chrono>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "batch/child_process.hpp"
#include "tests/support/lathesim_process.hpp"
#include "tests/support/processes.hpp"

namespace lathesim::batch {
namespace {

namespace fs = std::filesystem;
using test::readFile;
using test::ScratchDir;

bool goneWithin(pid_t pid, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (test::alive(pid)) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

TEST(ChildProcess, ExitStatusAndOutputInItsLog) {
  ScratchDir dir("child");
  const fs::path log = dir.path() / "log.txt";
  ChildProcess child = ChildProcess::start("/bin/sh", {"-c", "echo out; echo err >&2; exit 7"}, log);
  const int status = child.wait();
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 7);
  EXPECT_EQ(readFile(log), "out\nerr\n");
  EXPECT_FALSE(child.poll());  // reaped once
}

TEST(ChildProcess, OwnGroupStdinClosedSignalsAtDefaultNoInheritedDescriptors) {
  ScratchDir dir("child-env");
  const fs::path log = dir.path() / "log.txt";
  // The batch blocks these while it waits; a job must not inherit that.
  sigset_t blocked, previous;
  sigemptyset(&blocked);
  sigaddset(&blocked, SIGINT);
  sigaddset(&blocked, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &blocked, &previous);
  const int held = ::open("/dev/null", O_RDONLY);  // not close-on-exec: must still not reach the job
  ChildProcess child = ChildProcess::start(
      "/bin/sh",
      {"-c", "cut -d' ' -f5 /proc/$$/stat; grep SigBlk /proc/self/status; ls /proc/self/fd | sort -n | tr '\\n' ' '; "
             "read x; echo \"read:$?\""},
      log);
  ::close(held);
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  const pid_t pid = child.pid();
  child.wait();
  const std::string text = readFile(log);
  EXPECT_EQ(text.substr(0, text.find('\n')), std::to_string(pid));  // group = its own pid
  EXPECT_NE(text.find("SigBlk:\t0000000000000000"), std::string::npos) << text;
  // Descriptors 0–2 and ls's own directory (3) only; then `read` meets the end of stdin.
  EXPECT_NE(text.find("\n0 1 2 3 read:1\n"), std::string::npos) << text;
}

TEST(ChildProcess, KillingTheGroupTakesWhatTheJobStarted) {
  ScratchDir dir("child-kill");
  const fs::path log = dir.path() / "log.txt";
  ChildProcess child = ChildProcess::start("/bin/sh", {"-c", "sleep 60 & echo $!; wait"}, log);
  pid_t grandchild = 0;
  for (int i = 0; i < 500 && grandchild == 0; ++i) {
    const std::string text = readFile(log);
    if (!text.empty() && text.back() == '\n') grandchild = std::stoi(text);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_GT(grandchild, 0);
  ASSERT_TRUE(test::alive(grandchild));
  child.killGroup();
  const int status = child.wait();
  EXPECT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGKILL);
  EXPECT_TRUE(goneWithin(grandchild, std::chrono::seconds(5)));
}

TEST(ChildProcess, ASignalThatEndsItIsReported) {
  ScratchDir dir("child-crash");
  ChildProcess child = ChildProcess::start("/bin/sh", {"-c", "kill -SEGV $$"}, dir.path() / "log.txt");
  const int status = child.wait();
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGSEGV);
}

TEST(ChildProcess, AMissingBinaryExits127AndADroppedChildIsKilled) {
  ScratchDir dir("child-missing");
  ChildProcess missing = ChildProcess::start(dir.path() / "no-such-binary", {}, dir.path() / "log.txt");
  const int status = missing.wait();
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 127);
  pid_t pid = 0;
  {
    ChildProcess sleeper = ChildProcess::start("/bin/sleep", {"60"}, dir.path() / "log.txt");
    pid = sleeper.pid();
    EXPECT_TRUE(test::alive(pid));
  }
  EXPECT_FALSE(test::alive(pid));  // killed and reaped by the destructor
}

// A job forked from the batch runs the given main with its arguments, in a process of its own.
TEST(ChildProcessForked, RunsMainWithItsArgumentsOutputInItsLogExitsWithItsStatus) {
  ScratchDir dir("fork");
  const fs::path log = dir.path() / "log.txt";
  const pid_t batch = ::getpid();
  int touchedInChild = 0;
  ChildProcess child = ChildProcess::fork(
      [&](const std::vector<std::string>& args) {
        touchedInChild = 1;  // the child's copy: the batch's stays 0
        std::cout << "args:";
        for (const auto& a : args) std::cout << ' ' << a;
        std::cout << '\n';
        std::cerr << "pid differs: " << (::getpid() != batch) << ", own group: " << (::getpgrp() == ::getpid());
        return 5;
      },
      {"run", "p.nc", "--out", "o"}, log);
  const int status = child.wait();
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 5);
  EXPECT_EQ(readFile(log), "args: run p.nc --out o\npid differs: 1, own group: 1");
  EXPECT_EQ(touchedInChild, 0);
}

TEST(ChildProcessForked, ACrashOrAnEscapedExceptionEndsOnlyTheJob) {
  ScratchDir dir("fork-crash");
  ChildProcess crash = ChildProcess::fork([](const std::vector<std::string>&) -> int { std::abort(); }, {},
                                          dir.path() / "log.txt");
  const int crashed = crash.wait();
  ASSERT_TRUE(WIFSIGNALED(crashed));
  EXPECT_EQ(WTERMSIG(crashed), SIGABRT);
  ChildProcess thrower = ChildProcess::fork(
      [](const std::vector<std::string>&) -> int { throw std::runtime_error("escaped"); }, {}, dir.path() / "log.txt");
  const int threw = thrower.wait();
  ASSERT_TRUE(WIFEXITED(threw));
  EXPECT_EQ(WEXITSTATUS(threw), 70);
  EXPECT_EQ(readFile(dir.path() / "log.txt"), "lathesim: internal error: escaped\n");
  // The batch goes on starting jobs.
  ChildProcess after = ChildProcess::fork([](const std::vector<std::string>&) { return 0; }, {}, dir.path() / "log.txt");
  EXPECT_EQ(after.wait(), 0);
}

TEST(ChildProcessForked, AForkedJobIsKilledWithItsGroupAtItsTimeLimit) {
  ScratchDir dir("fork-kill");
  ChildProcess child = ChildProcess::fork(
      [](const std::vector<std::string>&) {
        for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
        return 0;
      },
      {}, dir.path() / "log.txt");
  const pid_t pid = child.pid();
  EXPECT_TRUE(test::alive(pid));
  child.killGroup();
  const int status = child.wait();
  EXPECT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGKILL);
}

TEST(ThreadCount, CountsAThreadWhileItRuns) {
  const int before = threadCount();
  ASSERT_GE(before, 1);
  std::atomic<bool> stop{false};
  std::thread other([&] {
    while (!stop) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  });
  EXPECT_EQ(threadCount(), before + 1);
  stop = true;
  other.join();
  EXPECT_EQ(threadCount(), before);
}

}  // namespace
}  // namespace lathesim::batch
