#include "app/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace lathesim::app {

Progress::Progress(std::string what)
    : what_(std::move(what)), start_(std::chrono::steady_clock::now()), lastShown_(start_),
      enabled_(isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() {
  if (shown_) std::fputc('\n', stderr);
}

void Progress::update(int done, int total) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const bool finished = done >= total;
  if (elapsed < 1.0 || (!finished && now - lastShown_ < std::chrono::milliseconds(100))) return;
  lastShown_ = now;
  shown_ = true;
  std::fprintf(stderr, "\r%s: blocks %d/%d, %.1f s", what_.c_str(), done, total, elapsed);
  std::fflush(stderr);
}

}  // namespace lathesim::app
