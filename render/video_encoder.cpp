#include "render/video_encoder.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace lathesim::render {
namespace {

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

/// A file for the child's error output, in the system's temporary folder (TMPDIR).
std::filesystem::path logFile() {
  std::string name = (std::filesystem::temp_directory_path() / "lathesim-ffmpeg-XXXXXX").string();
  const int fd = ::mkstemp(name.data());
  if (fd < 0) throw std::runtime_error(std::string("cannot make a temporary file: ") + std::strerror(errno));
  ::close(fd);
  return name;
}

std::string readAndRemove(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  std::error_code ignored;
  std::filesystem::remove(file, ignored);
  std::string s = text.str();
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
  return s;
}

/// Starts ffmpeg with `args`, stdin from `stdinFd` (or /dev/null when −1), stderr to `log`.
pid_t spawnFfmpeg(const std::vector<std::string>& args, int stdinFd, const std::filesystem::path& log) {
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>("ffmpeg"));
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (stdinFd >= 0) posix_spawn_file_actions_adddup2(&actions, stdinFd, STDIN_FILENO);
  else posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(), O_WRONLY | O_TRUNC, 0);
  pid_t pid = -1;
  const int failed = posix_spawnp(&pid, "ffmpeg", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (failed)
    throw std::runtime_error(std::string("cannot start ffmpeg (") + std::strerror(failed) +
                             "): install the ffmpeg package (scripts/setup.sh does)");
  return pid;
}

/// Waits for `pid`; throws with what it wrote to `log` unless it exited 0.
void awaitFfmpeg(pid_t pid, const std::filesystem::path& log, const std::string& what) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const std::string message = readAndRemove(log);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
    throw std::runtime_error("ffmpeg is not installed: install the ffmpeg package (scripts/setup.sh does)");
  throw std::runtime_error("ffmpeg could not " + what + (message.empty() ? "" : ": " + message));
}

}  // namespace

VideoEncoder::VideoEncoder(int widthPx, int heightPx, double framesPerSecond, const std::filesystem::path& mp4)
    : log_(logFile()), frameBytes_(static_cast<std::size_t>(widthPx) * heightPx * 3) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
  const std::vector<std::string> args{"-hide_banner", "-loglevel", "error", "-y", "-f", "rawvideo", "-pixel_format", "rgb24",
                                      "-video_size", std::to_string(widthPx) + "x" + std::to_string(heightPx),
                                      "-framerate", number(framesPerSecond), "-i", "pipe:0", "-c:v", "libx264",
                                      "-preset", "veryfast", "-crf", "18", "-pix_fmt", "yuv420p", "-movflags",
                                      "+faststart", "-f", "mp4", mp4.string()};
  try {
    pid_ = spawnFfmpeg(args, fds[0], log_);
  } catch (...) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw;
  }
  ::close(fds[0]);
  input_ = fds[1];
}

VideoEncoder::~VideoEncoder() {
  if (input_ >= 0) ::close(input_);
  if (pid_ > 0) {
    ::kill(pid_, SIGTERM);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    std::error_code ignored;
    std::filesystem::remove(log_, ignored);
  }
}

void VideoEncoder::write(const std::vector<unsigned char>& rgb) {
  if (rgb.size() != frameBytes_) throw std::logic_error("video frame of the wrong size");
  // A dead ffmpeg must give an error here, not SIGPIPE: block it for this thread while writing.
  sigset_t pipeSignal, previous;
  sigemptyset(&pipeSignal);
  sigaddset(&pipeSignal, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipeSignal, &previous);
  std::size_t done = 0;
  int error = 0;
  while (done < rgb.size()) {
    const ssize_t n = ::write(input_, rgb.data() + done, rgb.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      error = errno;
      break;
    }
    done += static_cast<std::size_t>(n);
  }
  if (error == EPIPE) {
    const timespec none{0, 0};
    sigtimedwait(&pipeSignal, nullptr, &none);  // the SIGPIPE that write raised
  }
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  if (error) {
    ::close(input_);
    input_ = -1;
    const pid_t pid = pid_;
    pid_ = -1;
    awaitFfmpeg(pid, log_, "encode the video");
    throw std::runtime_error(std::string("cannot send a frame to ffmpeg: ") + std::strerror(error));
  }
}

void VideoEncoder::finish() {
  ::close(input_);
  input_ = -1;
  const pid_t pid = pid_;
  pid_ = -1;
  awaitFfmpeg(pid, log_, "encode the video");
}

void writeGifFromVideo(const std::filesystem::path& mp4, const std::filesystem::path& gif, int widthPx,
                       double framesPerSecond) {
  const std::filesystem::path log = logFile();
  const std::string filter = "fps=" + number(framesPerSecond) + ",scale=" + std::to_string(widthPx) +
                             ":-1:flags=lanczos,split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=bayer:bayer_scale=4";
  const pid_t pid = spawnFfmpeg({"-hide_banner", "-loglevel", "error", "-y", "-i", mp4.string(), "-filter_complex", filter,
                                 "-f", "gif", gif.string()},
                                -1, log);
  awaitFfmpeg(pid, log, "make the GIF");
}

}  // namespace lathesim::render
