#include "app/progress.hpp"

#include <unistd.h>

#include <cstdio>

#include "interp/base/printable_text.hpp"

namespace lathesim::app {

Progress::Progress(std::string what)
    : what_(interp::printable(what)), start_(std::chrono::steady_clock::now()), lastShown_(start_),
      enabled_(isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() { finish(); }

void Progress::finish() {
  if (shown_) std::fputc('\n', stderr);
  shown_ = false;
}

void Progress::update(int done, int total) {
  show("blocks " + std::to_string(done) + "/" + std::to_string(total), done >= total);
}

void Progress::stage(const std::string& name) { show(name, true); }

void Progress::show(const std::string& state, bool force) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < 1.0 || (!force && now - lastShown_ < std::chrono::milliseconds(100))) return;
  lastShown_ = now;
  shown_ = true;
  // \33[K clears what a longer previous state left on the line.
  std::fprintf(stderr, "\r%s: %s, %.1f s\33[K", what_.c_str(), state.c_str(), elapsed);
  std::fflush(stderr);
}

}  // namespace lathesim::app
