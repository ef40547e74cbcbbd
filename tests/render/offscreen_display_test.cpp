#include "render/offscreen_display.hpp"

#include <cerrno>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

namespace lathesim::render {
namespace {

TEST(XvfbServer, MissingProgramSaysToInstallXvfb) {
  try {
    XvfbServer::start("lathesim-no-such-xvfb");
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("install the `xvfb` package"), std::string::npos)
        << e.what();
  }
}

TEST(XvfbServer, ProgramThatExitsAtOnceIsReported) {
  try {
    XvfbServer::start("false");
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("exited before reporting a display"), std::string::npos)
        << e.what();
  }
}

TEST(XvfbServer, StartsReachableAndIsGoneAfterDestruction) {
  pid_t pid = 0;
  {
    auto server = XvfbServer::start();
    ASSERT_EQ(server->display().front(), ':');
    EXPECT_TRUE(displayIsReachable(server->display()));
    pid = server->pid();
    EXPECT_EQ(::kill(pid, 0), 0);
  }
  EXPECT_EQ(::kill(pid, 0), -1);
  EXPECT_EQ(errno, ESRCH);
}

TEST(XvfbServer, NotRunningOnceKilled) {
  auto server = XvfbServer::start();
  EXPECT_TRUE(server->running());
  ASSERT_EQ(::kill(server->pid(), SIGKILL), 0);
  bool ended = false;
  for (int i = 0; i < 200 && !ended; ++i) {
    ended = !server->running();
    if (!ended) ::usleep(10'000);
  }
  EXPECT_TRUE(ended);
  EXPECT_FALSE(displayIsReachable(server->display()));
}

TEST(EnsureDisplay, ReplacesAnUnreachableDisplay) {
  ::setenv("DISPLAY", ":4711", 1);  // nothing listens there
  ASSERT_FALSE(displayIsReachable(":4711"));
  const std::string display = ensureDisplay();
  EXPECT_NE(display, ":4711");
  EXPECT_EQ(std::getenv("DISPLAY"), display);
  EXPECT_TRUE(displayIsReachable(display));
  // A reachable DISPLAY is kept as it is.
  EXPECT_EQ(ensureDisplay(), display);
}

TEST(EnsureDisplay, WorksWithDisplayUnset) {
  ::unsetenv("DISPLAY");
  const std::string display = ensureDisplay();
  EXPECT_TRUE(displayIsReachable(display));
  ASSERT_NE(std::getenv("DISPLAY"), nullptr);
  EXPECT_EQ(std::getenv("DISPLAY"), display);
}

}  // namespace
}  // namespace lathesim::render
