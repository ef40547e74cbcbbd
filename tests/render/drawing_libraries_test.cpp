// Libraries loaded ahead for forks: a process forked after the preload loads, to draw a
// picture, exactly the libraries preloaded fewer than one forked before it; and the preload
// starts no thread in the process.

#include "render/drawing_libraries.hpp"

#include <gtest/gtest.h>

#include <link.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <optional>

#include "render/offscreen_display.hpp"
#include "render/part_image.hpp"
#include "tests/render/test_meshes.hpp"

namespace lathesim::render {
namespace {

int threadCount() {
  return static_cast<int>(std::distance(std::filesystem::directory_iterator("/proc/self/task"),
                                        std::filesystem::directory_iterator()));
}

/// How many times this process has loaded a shared library (those unloaded since included:
/// closing a window unloads the driver).
unsigned long long libraryLoads() {
  unsigned long long loads = 0;
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void* n) {
        *static_cast<unsigned long long*>(n) = info->dlpi_adds;
        return 1;
      },
      &loads);
  return loads;
}

/// The number of shared libraries a fork of this process loads to draw a part picture
/// (-1 if it could not draw).
int librariesAForkLoadsToDraw() {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const unsigned long long before = libraryLoads();
    partImage(test::cylinder(30.0, 60.0, 48, 4), test::rapidThenFeed(), PartImageOptions{160, 120, "t", {}});
    ::_exit(static_cast<int>(std::min(libraryLoads() - before, 100ULL)));
  }
  int status = 0;
  if (pid < 0 || ::waitpid(pid, &status, 0) != pid || !WIFEXITED(status)) return -1;
  return WEXITSTATUS(status);
}

// Run alone (as ctest runs each test), this process has not drawn: the preload has the GL
// vendor library, the Mesa driver and LLVM to load. (Whatever TBB loads on its first parallel
// loop, a fork loads either way.)
TEST(DrawingLibraries, AForkAfterThePreloadLoadsThePreloadedLibrariesFewer) {
  ::unsetenv("DISPLAY");
  ensureDisplay();
  const int before = librariesAForkLoadsToDraw();
  ASSERT_GE(before, 0);
  const int threads = threadCount();
  DrawingLibrariesPreload preload;
  std::optional<int> preloaded;
  for (int waited = 0; !(preloaded = preload.loadIfDone()) && waited < 3000; ++waited) ::usleep(10'000);
  ASSERT_TRUE(preloaded) << "the drawing child did not end in 30 s";
  EXPECT_EQ(threadCount(), threads);
  EXPECT_EQ(preload.loadIfDone(), 0);  // done once
  EXPECT_GT(*preloaded, 0);
  EXPECT_EQ(librariesAForkLoadsToDraw(), before - *preloaded);
}

}  // namespace
}  // namespace lathesim::render
