#pragma once
// A small HTTP/1.0 server for `lathesim watch`: it listens on the loopback interface only
// (127.0.0.1), answers GET and HEAD one connection at a time, and closes each connection after
// its answer. It is driven by the caller's poll loop: fd() becomes readable when a browser
// connects, and serveOne() answers that one request. Nothing it is sent can make it read or
// write beyond its limits: a request line over 8 KiB, or one not finished within two seconds,
// gets 400 or nothing.

#include <functional>
#include <string>

namespace lathesim::app {

struct HttpResponse {
  int status = 200;  // 200, 404 …
  std::string contentType = "text/plain; charset=utf-8";
  std::string body;
};

class LoopbackServer {
 public:
  /// Listens on 127.0.0.1:`port` (0: a free port the system chooses); throws std::runtime_error
  /// saying why it cannot ("port 8080 is in use").
  explicit LoopbackServer(int port);
  ~LoopbackServer();
  LoopbackServer(const LoopbackServer&) = delete;
  LoopbackServer& operator=(const LoopbackServer&) = delete;

  int port() const { return port_; }
  int fd() const { return socket_; }

  /// Accepts the connection waiting on fd() and answers its request with `respond(path)`, the
  /// path being the request's target without its query ("/report.html"). HEAD gets the
  /// headers only; any other method 405.
  void serveOne(const std::function<HttpResponse(const std::string& path)>& respond) const;

 private:
  int socket_ = -1;
  int port_ = 0;
};

}  // namespace lathesim::app
