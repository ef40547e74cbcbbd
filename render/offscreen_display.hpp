#pragma once
// An X display for off-screen rendering, whether or not the user has one.
//
// Debian's VTK 9.1 is built for X11/GLX only: with no reachable X server it aborts the
// process ("bad X server connection"), which cannot be caught. So before any VTK window is
// made, render/ calls ensureDisplay(): it keeps a working DISPLAY, or starts a private Xvfb
// (Mesa llvmpipe renders there) and points DISPLAY at it. Users never type xvfb-run.

#include <memory>
#include <string>
#include <utility>

#include <sys/types.h>

namespace lathesim::render {

/// True if an X client can connect to `display` (e.g. ":0", "localhost:10.0") right now.
bool displayIsReachable(const std::string& display);

/// A private Xvfb server, owned by this object: started by start(), terminated (SIGTERM,
/// then SIGKILL after 2 s) and reaped by the destructor. The server also receives SIGTERM
/// if the thread that started it dies (PR_SET_PDEATHSIG), so a crash leaves no server behind.
class XvfbServer {
 public:
  /// Starts `program` (looked up in PATH unless it contains '/') with
  /// `-displayfd <fd> -screen 0 1600x1200x24 -nolisten tcp -noreset` and waits up to
  /// `timeoutSeconds` for it to report its display number. Works with stdin closed and
  /// without a TTY. Throws std::runtime_error (saying to install the `xvfb` package) if the
  /// program is missing, exits early or does not answer in time.
  static std::unique_ptr<XvfbServer> start(const std::string& program = "Xvfb",
                                           double timeoutSeconds = 10.0);
  ~XvfbServer();
  XvfbServer(const XvfbServer&) = delete;
  XvfbServer& operator=(const XvfbServer&) = delete;

  const std::string& display() const { return display_; }  // ":N"
  /// False once the server's process has ended (reaped here if it is this process's child).
  bool running();
  pid_t pid() const { return pid_; }

 private:
  XvfbServer(pid_t pid, std::string display) : pid_(pid), display_(std::move(display)) {}
  pid_t pid_;
  std::string display_;
};

/// Makes sure DISPLAY names a reachable X server, for the rest of the process: keeps the
/// user's DISPLAY if it can be connected to; otherwise starts one Xvfb for the whole
/// process (kept in a function-local static, killed at exit) and sets DISPLAY to it.
/// A display once found reachable is not asked again (while DISPLAY names it and, if it is
/// ours, its process lives). Thread-safe. Call before creating any VTK render window. Throws std::runtime_error if no
/// display can be had (the message says to install `xvfb`); never lets VTK abort.
/// Returns the display in use.
std::string ensureDisplay();

}  // namespace lathesim::render
