#include "app/interrupts.hpp"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <climits>
#include <cstring>
#include <stdexcept>

#include "setup/exit_status.hpp"

namespace lathesim::app {
namespace {

// Fixed storage: the handler may not allocate. A run stages fewer than a dozen files.
constexpr int kSlots = 32;
enum SlotState : int { kFree, kFilling, kFile, kFolder };
struct Slot {
  std::atomic<int> state{kFree};
  long order = 0;  // registration order: folders are removed newest (innermost) first
  char path[PATH_MAX] = {};
};
Slot slots[kSlots];
std::atomic<long> registered{0};
std::atomic<bool> committing{false};
std::atomic<bool> handling{false};  // a handler is deciding: with `committing`, a Dekker pair
std::atomic<int> deferredSignal{0};
bool stderrIsTerminal = false;

void add(const std::filesystem::path& path, SlotState kind) {
  const std::string text = path.string();
  if (text.size() >= PATH_MAX) throw std::runtime_error("output path too long: " + text);
  for (Slot& slot : slots) {
    int expected = kFree;
    if (!slot.state.compare_exchange_strong(expected, kFilling)) continue;
    std::memcpy(slot.path, text.c_str(), text.size() + 1);
    slot.order = registered.fetch_add(1);
    slot.state.store(kind, std::memory_order_release);
    return;
  }
  throw std::logic_error("more than 32 outputs staged at once");
}

void writeText(const char* text) {
  for (std::size_t left = std::strlen(text); left > 0;) {
    const ssize_t written = ::write(STDERR_FILENO, text, left);
    if (written <= 0) return;
    text += written;
    left -= static_cast<std::size_t>(written);
  }
}

// Async-signal-safe from here on: unlink, rmdir, write, _exit.
[[noreturn]] void removeAndExit(int signal) {
  for (Slot& slot : slots)
    if (slot.state.load(std::memory_order_acquire) == kFile) ::unlink(slot.path);
  for (;;) {  // folders, newest first: an inner folder before the one that holds it
    Slot* newest = nullptr;
    for (Slot& slot : slots)
      if (slot.state.load(std::memory_order_acquire) == kFolder && (!newest || slot.order > newest->order)) newest = &slot;
    if (!newest) break;
    ::rmdir(newest->path);
    newest->state.store(kFree);
  }
  if (stderrIsTerminal) writeText("\r\33[K");  // over a progress line
  writeText(signal == SIGINT    ? "lathesim: stopped by SIGINT (Ctrl-C); unfinished outputs removed\n"
            : signal == SIGTERM ? "lathesim: stopped by SIGTERM; unfinished outputs removed\n"
                                : "lathesim: stopped by SIGHUP; unfinished outputs removed\n");
  ::_exit(setup::exitOnSignal(signal));
}

extern "C" void onSignal(int signal) {
  handling.store(true);
  if (committing.load()) {
    deferredSignal.store(signal);
    handling.store(false);
    return;
  }
  removeAndExit(signal);
}

}  // namespace

void removeOutputsOnInterrupt() {
  stderrIsTerminal = ::isatty(STDERR_FILENO) == 1;
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&action.sa_mask, signal);
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction previous {};
    sigaction(signal, nullptr, &previous);
    if (previous.sa_handler == SIG_IGN) continue;  // nohup and the like: stay ignored
    sigaction(signal, &action, nullptr);
  }
}

void InterruptCleanup::addFile(const std::filesystem::path& file) { add(file, kFile); }
void InterruptCleanup::addFolder(const std::filesystem::path& folder) { add(folder, kFolder); }

void InterruptCleanup::forget(const std::filesystem::path& path) {
  const std::string text = path.string();
  for (Slot& slot : slots) {
    const int state = slot.state.load(std::memory_order_acquire);
    if ((state == kFile || state == kFolder) && text == slot.path) slot.state.store(kFree);
  }
}

void InterruptCleanup::beginCommit() {
  committing.store(true);
  // A handler that began before it saw `committing` is removing the files: it ends the
  // process, and no file may be renamed under it meanwhile.
  while (handling.load()) ::usleep(1000);
}

void InterruptCleanup::endCommit() {
  committing.store(false);
  if (const int signal = deferredSignal.exchange(0)) removeAndExit(signal);
}

}  // namespace lathesim::app
