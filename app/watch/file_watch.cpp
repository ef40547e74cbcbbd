#include "app/watch/file_watch.hpp"

#include <sys/inotify.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace lathesim::app {

FileWatch::FileWatch(const std::vector<std::filesystem::path>& inputs) {
  inotify_ = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (inotify_ < 0) throw std::runtime_error(std::string("cannot watch files (inotify): ") + std::strerror(errno));
  constexpr uint32_t kSaved = IN_CLOSE_WRITE | IN_MOVED_TO | IN_CREATE | IN_DELETE | IN_MOVED_FROM;
  for (const auto& input : inputs) {
    const auto absolute = std::filesystem::absolute(input).lexically_normal();
    const bool folder = std::filesystem::is_directory(absolute);
    const auto where = folder ? absolute : absolute.parent_path();
    const int watch = ::inotify_add_watch(inotify_, where.c_str(), kSaved);
    if (watch < 0) throw std::runtime_error("cannot watch " + where.string() + ": " + std::strerror(errno));
    auto same = std::find_if(watched_.begin(), watched_.end(), [&](const Watched& w) { return w.watch == watch; });
    if (same == watched_.end()) same = watched_.insert(watched_.end(), Watched{watch, false, {}});
    if (folder) same->wholeFolder = true;
    else same->names.push_back(absolute.filename());
  }
}

FileWatch::~FileWatch() {
  if (inotify_ >= 0) ::close(inotify_);
}

bool FileWatch::changed() {
  bool any = false;
  alignas(inotify_event) char buffer[16 * (sizeof(inotify_event) + 256)];
  for (;;) {
    const ssize_t got = ::read(inotify_, buffer, sizeof buffer);
    if (got <= 0) return any;  // EAGAIN: nothing more waits
    for (ssize_t at = 0; at < got;) {
      const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
      at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
      const auto w = std::find_if(watched_.begin(), watched_.end(), [&](const Watched& x) { return x.watch == event->wd; });
      if (w == watched_.end()) continue;
      const std::string name = event->len ? event->name : "";
      if (w->wholeFolder || std::find(w->names.begin(), w->names.end(), name) != w->names.end()) any = true;
    }
  }
}

}  // namespace lathesim::app
