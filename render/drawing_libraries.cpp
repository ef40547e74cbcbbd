#include "render/drawing_libraries.hpp"

#include <dlfcn.h>
#include <fcntl.h>
#include <link.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

namespace lathesim::render {
namespace {

/// The shared libraries loaded in this process, by path, in the order they were loaded.
std::vector<std::string> loadedLibraries() {
  std::vector<std::string> paths;
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void* data) {
        // The program itself has no name and the vDSO no path: neither can be loaded.
        if (info->dlpi_name != nullptr && info->dlpi_name[0] == '/')
          static_cast<std::vector<std::string>*>(data)->emplace_back(info->dlpi_name);
        return 0;
      },
      &paths);
  return paths;
}

/// In the child: draws an empty 1×1 picture, writes the libraries loaded then to `fd`, one a
/// line, and ends without running the parent's exit handlers (its Xvfb is the parent's).
/// The list (some 100 paths) fits in the pipe: the child never waits for the parent.
[[noreturn]] void drawAndListLibraries(int fd) {
  const int null = ::open("/dev/null", O_WRONLY);
  ::dup2(null, STDOUT_FILENO);  // VTK's warnings are not the batch's to print
  ::dup2(null, STDERR_FILENO);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(1, 1);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->Render();
  // Listed while the window lives: closing it unloads the driver again.
  std::string list;
  for (const std::string& path : loadedLibraries()) list += path + '\n';
  for (std::size_t written = 0; written < list.size();) {
    const ssize_t n = ::write(fd, list.data() + written, list.size() - written);
    if (n <= 0) ::_exit(1);
    written += static_cast<std::size_t>(n);
  }
  ::_exit(0);
}

/// Everything left to read from `fd` (non-blocking, its writer gone).
std::string readAll(int fd) {
  std::string text;
  char buffer[4096];
  for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
  }
  return text;
}

/// dlopens each path of `list` that this process has not loaded; returns how many it loaded.
int loadMissing(const std::string& list) {
  const std::vector<std::string> have = loadedLibraries();
  const std::set<std::string> loaded(have.begin(), have.end());
  std::istringstream paths(list);
  int count = 0;
  // In the child's order: a library before those it loaded. RTLD_NOW: the relocations are
  // the cost. Never closed: they stay for the forks.
  for (std::string path; std::getline(paths, path);)
    if (!loaded.count(path) && ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL) != nullptr) ++count;
  return count;
}

}  // namespace

DrawingLibrariesPreload::DrawingLibrariesPreload() {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC | O_NONBLOCK) != 0) return;
  // What this process has buffered would otherwise be written by the child too.
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  pid_ = ::fork();
  if (pid_ == 0) {
    ::close(fds[0]);
    drawAndListLibraries(fds[1]);
  }
  ::close(fds[1]);
  if (pid_ < 0) {
    ::close(fds[0]);
    return;
  }
  listFd_ = fds[0];
}

DrawingLibrariesPreload::~DrawingLibrariesPreload() {
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    while (::waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
  if (listFd_ >= 0) ::close(listFd_);
}

std::optional<int> DrawingLibrariesPreload::loadIfDone() {
  if (pid_ <= 0) return 0;
  int status = 0;
  const pid_t ended = ::waitpid(pid_, &status, WNOHANG);
  if (ended == 0) return std::nullopt;
  pid_ = -1;
  const std::string list = readAll(listFd_);
  ::close(listFd_);
  listFd_ = -1;
  if (ended < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return 0;
  return loadMissing(list);
}

}  // namespace lathesim::render
