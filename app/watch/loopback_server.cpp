#include "app/watch/loopback_server.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>

namespace lathesim::app {
namespace {

constexpr std::size_t kMaxRequestBytes = 8192;
constexpr int kRequestTimeoutMs = 2000;

const char* reason(int status) {
  switch (status) {
    case 200: return "OK";
    case 400: return "Bad Request";
    case 404: return "Not Found";
    case 405: return "Method Not Allowed";
    default: return "Error";
  }
}

/// The request's head (up to the blank line), or empty when it does not come whole in time.
std::string readHead(int connection) {
  std::string head;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(kRequestTimeoutMs);
  char chunk[1024];
  while (head.find("\r\n\r\n") == std::string::npos && head.find("\n\n") == std::string::npos) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    pollfd ready{connection, POLLIN, 0};
    if (left.count() <= 0 || ::poll(&ready, 1, static_cast<int>(left.count())) <= 0) return {};
    const ssize_t got = ::recv(connection, chunk, sizeof chunk, 0);
    if (got <= 0) return {};
    head.append(chunk, static_cast<std::size_t>(got));
    if (head.size() > kMaxRequestBytes) return {};
  }
  return head;
}

void sendAll(int connection, const std::string& bytes) {
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = ::send(connection, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the browser went away, or stalled past the send timeout
    sent += static_cast<std::size_t>(n);
  }
}

void answer(int connection, const HttpResponse& response, bool withBody) {
  std::string head = "HTTP/1.0 " + std::to_string(response.status) + " " + reason(response.status) + "\r\n" +
                     "Content-Type: " + response.contentType + "\r\n" +
                     "Content-Length: " + std::to_string(response.body.size()) + "\r\n" +
                     "Cache-Control: no-store\r\nConnection: close\r\n\r\n";
  sendAll(connection, withBody ? head + response.body : head);
}

}  // namespace

LoopbackServer::LoopbackServer(int port) {
  socket_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (socket_ < 0) throw std::runtime_error(std::string("cannot open a socket: ") + std::strerror(errno));
  const int yes = 1;
  ::setsockopt(socket_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);  // never beyond this machine
  address.sin_port = htons(static_cast<uint16_t>(port));
  if (::bind(socket_, reinterpret_cast<sockaddr*>(&address), sizeof address) < 0 || ::listen(socket_, 16) < 0) {
    const int error = errno;
    ::close(socket_);
    throw std::runtime_error("cannot listen on 127.0.0.1:" + std::to_string(port) + ": " +
                             (error == EADDRINUSE ? std::string("the port is in use; give another with --port, or 0 for any free one")
                                                  : std::string(std::strerror(error))));
  }
  socklen_t length = sizeof address;
  ::getsockname(socket_, reinterpret_cast<sockaddr*>(&address), &length);
  port_ = ntohs(address.sin_port);
}

LoopbackServer::~LoopbackServer() {
  if (socket_ >= 0) ::close(socket_);
}

void LoopbackServer::serveOne(const std::function<HttpResponse(const std::string& path)>& respond) const {
  const int connection = ::accept4(socket_, nullptr, nullptr, SOCK_CLOEXEC);
  if (connection < 0) return;
  const timeval sendTimeout{5, 0};
  ::setsockopt(connection, SOL_SOCKET, SO_SNDTIMEO, &sendTimeout, sizeof sendTimeout);
  const std::string head = readHead(connection);
  const auto lineEnd = head.find_first_of("\r\n");
  const std::string line = head.substr(0, lineEnd);
  const auto firstSpace = line.find(' ');
  const auto secondSpace = firstSpace == std::string::npos ? std::string::npos : line.find(' ', firstSpace + 1);
  if (head.empty() || secondSpace == std::string::npos) {
    if (!head.empty()) answer(connection, {400, "text/plain; charset=utf-8", "bad request\n"}, true);
  } else {
    const std::string method = line.substr(0, firstSpace);
    std::string target = line.substr(firstSpace + 1, secondSpace - firstSpace - 1);
    target = target.substr(0, target.find_first_of("?#"));
    if (method != "GET" && method != "HEAD")
      answer(connection, {405, "text/plain; charset=utf-8", "only GET and HEAD\n"}, true);
    else
      answer(connection, respond(target), method == "GET");
  }
  ::close(connection);
}

}  // namespace lathesim::app
