// `lathesim watch` as a user meets it: the page's address on 127.0.0.1, a run again on each save,
// a failed save shown with its diagnostics while the last good part stays, only the output
// folder served, Ctrl-C stopping it with 130.

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <thread>

#include "tests/support/lathesim_process.hpp"
#include "tests/support/processes.hpp"

namespace lathesim::test {
namespace {

using Clock = std::chrono::steady_clock;

const std::string kWatchedProgram = readFile(fs::path(LATHESIM_PARTS_DIR) / "g71-g70-shaft" / "program.nc");

/// The raw answer to `request` from 127.0.0.1:`port` (headers and body).
std::string ask(int port, const std::string& request) {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<uint16_t>(port));
  std::string answer;
  if (::connect(s, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) {
    ::send(s, request.data(), request.size(), MSG_NOSIGNAL);
    char chunk[65536];
    for (ssize_t got; (got = ::recv(s, chunk, sizeof chunk, 0)) > 0;) answer.append(chunk, static_cast<std::size_t>(got));
  }
  ::close(s);
  return answer;
}

std::string get(int port, const std::string& path) { return ask(port, "GET " + path + " HTTP/1.0\r\n\r\n"); }

std::string bodyOf(const std::string& answer) {
  const auto end = answer.find("\r\n\r\n");
  return end == std::string::npos ? std::string() : answer.substr(end + 4);
}

int statusOf(const std::string& answer) {  // "HTTP/1.0 404 Not Found" → 404
  return answer.size() > 12 ? std::stoi(answer.substr(9, 3)) : 0;
}

/// `lathesim watch ARGS` in `folder`, its first line (the address) read from its stdout.
class Watch {
 public:
  Watch(const fs::path& folder, const std::vector<std::string>& args) {
    int out[2];
    EXPECT_EQ(::pipe(out), 0);
    std::vector<std::string> words{LATHESIM_BINARY, "watch"};
    words.insert(words.end(), args.begin(), args.end());
    const std::string errFile = (folder / "watch-stderr.txt").string();
    pid_ = ::fork();
    if (pid_ == 0) {
      std::vector<char*> argv;
      for (auto& word : words) argv.push_back(word.data());
      argv.push_back(nullptr);
      const int err = ::open(errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (::chdir(folder.c_str()) < 0 || ::dup2(out[1], 1) < 0 || ::dup2(err, 2) < 0) ::_exit(126);
      ::execv(LATHESIM_BINARY, argv.data());
      ::_exit(127);
    }
    ::close(out[1]);
    stdout_ = ::fdopen(out[0], "r");
    char line[4096] = {};
    if (std::fgets(line, sizeof line, stdout_)) firstLine_ = line;
    std::smatch port;
    if (std::regex_search(firstLine_, port, std::regex(R"(http://127\.0\.0\.1:(\d+)/)"))) port_ = std::stoi(port[1]);
  }
  ~Watch() {  // stopped as a user stops it, so that its run under way ends too
    if (pid_ > 0 && !exited_) {
      ::kill(pid_, SIGINT);
      if (exitStatus(20) == -1 && !exited_) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, nullptr, 0);
      }
    }
    if (stdout_) std::fclose(stdout_);
  }
  int port() const { return port_; }
  pid_t pid() const { return pid_; }
  const std::string& firstLine() const { return firstLine_; }

  /// The watcher's state once it has finished `generation` runs (nullopt after a minute).
  std::optional<nlohmann::json> stateAfter(int generation) const {
    const auto deadline = Clock::now() + std::chrono::seconds(60);
    while (Clock::now() < deadline) {
      const std::string body = bodyOf(get(port_, "/watch/state"));
      if (!body.empty()) {
        const auto state = nlohmann::json::parse(body);
        if (state["generation"].get<int>() >= generation && !state["running"].get<bool>()) return state;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return std::nullopt;
  }

  /// Its exit status once it ends (-1 if it does not within `seconds`).
  int exitStatus(int seconds) {
    const auto deadline = Clock::now() + std::chrono::seconds(seconds);
    int status = 0;
    while (Clock::now() < deadline) {
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        exited_ = true;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return -1;
  }

 private:
  pid_t pid_ = -1;
  FILE* stdout_ = nullptr;
  std::string firstLine_;
  int port_ = 0;
  bool exited_ = false;
};

/// Saves `text` as an editor does: a new file renamed over the old one.
void save(const fs::path& file, const std::string& text) {
  writeFile(file.string() + ".swp", text);
  fs::rename(file.string() + ".swp", file);
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(WatchCommand, FollowsEachSaveAndKeepsTheLastGoodPartThroughAFailedOne) {
  ScratchDir scratch("watch");
  writeFile(scratch.path() / "shaft.nc", kWatchedProgram);
  Watch watch(scratch.path(), {"shaft.nc", "--stock", "D52xL100", "--outputs", "report,html", "--out", "out"});
  ASSERT_GT(watch.port(), 0) << watch.firstLine();
  EXPECT_NE(watch.firstLine().find("shaft.nc"), std::string::npos) << "names what it watches";

  const auto first = watch.stateAfter(1);
  ASSERT_TRUE(first) << readFile(scratch.path() / "watch-stderr.txt");
  EXPECT_EQ((*first)["status"], 0);
  EXPECT_EQ((*first)["good_generation"], 1);
  const auto firstReport = nlohmann::json::parse(readFile(scratch.path() / "out" / "report.json"));
  const std::string page = get(watch.port(), "/report.html");
  EXPECT_EQ(statusOf(page), 200);
  EXPECT_NE(page.find("const shown = 1;"), std::string::npos) << "the page knows which run it shows";
  EXPECT_NE(page.find("watch/state"), std::string::npos);

  // A slip: the page's state carries the located error; the outputs stay the last good run's.
  save(scratch.path() / "shaft.nc", replaced(kWatchedProgram, "N20 G01 Z-15.0", "N20 G01 Q Z-15.0"));
  const auto failed = watch.stateAfter(2);
  ASSERT_TRUE(failed);
  EXPECT_EQ((*failed)["status"], 1);
  EXPECT_EQ((*failed)["good_generation"], 1);
  EXPECT_NE((*failed)["error"].get<std::string>().find("shaft.nc:8:9: error: Q has no number"), std::string::npos)
      << (*failed)["error"];
  EXPECT_EQ(nlohmann::json::parse(readFile(scratch.path() / "out" / "report.json")), firstReport);
  EXPECT_NE(get(watch.port(), "/report.html").find("const shown = 1;"), std::string::npos);

  // The cure, with the first diameter 2 mm larger: a new part, 2 mm more in diameter over 15 mm
  // of length, so (π/4)(22² − 20²)·15 = 989.6 mm³ more material left.
  save(scratch.path() / "shaft.nc", replaced(kWatchedProgram, "N10 G00 X20.0", "N10 G00 X22.0"));
  const auto cured = watch.stateAfter(3);
  ASSERT_TRUE(cured);
  EXPECT_EQ((*cured)["status"], 0);
  EXPECT_EQ((*cured)["good_generation"], 3);
  EXPECT_EQ((*cured)["error"], "");
  const auto curedReport = nlohmann::json::parse(readFile(scratch.path() / "out" / "report.json"));
  const double more = curedReport["final_volume_mm3"].get<double>() - firstReport["final_volume_mm3"].get<double>();
  EXPECT_NEAR(more, 3.14159265 / 4 * (22 * 22 - 20 * 20) * 15, 0.1 * 989.6);

  ::kill(watch.pid(), SIGINT);
  EXPECT_EQ(watch.exitStatus(20), 130);
  EXPECT_TRUE(processesMentioning(scratch.path().string()).empty());
}

TEST(WatchCommand, ListensOnTheLoopbackInterfaceOnly) {
  ScratchDir scratch("watch-loopback");
  writeFile(scratch.path() / "shaft.nc", kWatchedProgram);
  Watch watch(scratch.path(), {"shaft.nc", "--stock", "D52xL100", "--outputs", "report", "--out", "out"});
  ASSERT_GT(watch.port(), 0) << watch.firstLine();
  char hexPort[8];
  std::snprintf(hexPort, sizeof hexPort, "%04X", watch.port());
  const std::string tcp = readFile("/proc/net/tcp"), tcp6 = readFile("/proc/net/tcp6");
  // Listening sockets are state 0A; the watcher's is bound to 127.0.0.1 (0100007F) and no other.
  EXPECT_NE(tcp.find("0100007F:" + std::string(hexPort) + " 00000000:0000 0A"), std::string::npos) << tcp;
  EXPECT_EQ(tcp.find("00000000:" + std::string(hexPort) + " 00000000:0000 0A"), std::string::npos);
  EXPECT_EQ(tcp6.find(":" + std::string(hexPort) + " 00000000000000000000000000000000:0000 0A"), std::string::npos);
}

TEST(WatchCommand, ServesTheOutputFolderAndNothingElse) {
  ScratchDir scratch("watch-paths");
  writeFile(scratch.path() / "shaft.nc", kWatchedProgram);
  writeFile(scratch.path() / "secret.txt", "not for the browser");
  Watch watch(scratch.path(), {"shaft.nc", "--stock", "D52xL100", "--outputs", "report", "--out", "out"});
  ASSERT_GT(watch.port(), 0) << watch.firstLine();
  ASSERT_TRUE(watch.stateAfter(1));
  fs::create_symlink(scratch.path() / "secret.txt", scratch.path() / "out" / "link.txt");
  EXPECT_EQ(statusOf(get(watch.port(), "/link.txt")), 404) << "a link out of the folder";
  EXPECT_EQ(statusOf(get(watch.port(), "/report.json")), 200);
  for (const std::string path : {"/../secret.txt", "/out/../secret.txt", "/..%2fsecret.txt", "/.", "/nothing.png",
                                 "/../shaft.nc", "//etc/passwd"})
    EXPECT_EQ(statusOf(get(watch.port(), path)), 404) << path;
  EXPECT_EQ(statusOf(ask(watch.port(), "POST /report.json HTTP/1.0\r\n\r\n")), 405);
  EXPECT_EQ(ask(watch.port(), "GET /" + std::string(9000, 'a') + " HTTP/1.0\r\n\r\n"), "") << "too long: dropped";
  EXPECT_EQ(statusOf(ask(watch.port(), "nonsense\r\n\r\n")), 400);
  EXPECT_EQ(statusOf(get(watch.port(), "/report.json")), 200) << "still serving after bad requests";
}

TEST(WatchCommand, ABadCommandLineOrABusyPortStopsItAtOnce) {
  ScratchDir scratch("watch-bad");
  writeFile(scratch.path() / "shaft.nc", kWatchedProgram);
  {
    Watch watch(scratch.path(), {"shaft.nc", "--voxel", "-1"});
    EXPECT_EQ(watch.exitStatus(30), 2) << "no save can cure a bad command line";
  }
  const auto none = runProcess(LATHESIM_BINARY, {"watch"}, scratch.path());
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("give the program"), std::string::npos) << none.err;

  Watch first(scratch.path(), {"shaft.nc", "--stock", "D52xL100", "--outputs", "report", "--out", "out"});
  ASSERT_GT(first.port(), 0);
  const auto busy = runProcess(LATHESIM_BINARY, {"watch", "--port", std::to_string(first.port()), "shaft.nc"},
                               scratch.path());
  EXPECT_EQ(busy.status, 1);
  EXPECT_NE(busy.err.find("127.0.0.1:" + std::to_string(first.port()) + ": the port is in use"), std::string::npos)
      << busy.err;
}

}  // namespace
}  // namespace lathesim::test
