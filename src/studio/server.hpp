// The studio's HTTP server: cpp-httplib (Debian's libcpp-httplib-dev; docs/design.md#studio)
// listening on 127.0.0.1 only, every request copied into a studio::Request and answered by
// the Handler. Nothing else happens here.
#pragma once

#include "studio/handler.hpp"

#include <functional>
#include <memory>
#include <string>

namespace tribolab::studio {

class Server {
 public:
  /// Binds 127.0.0.1:`port` (0: a free port). Throws InputError when the port is taken.
  /// `make_handler` is given the bound port (the Host and Origin the handler accepts). Every
  /// body reaches the handler unread (Request::read_body), which applies its rules' limits
  /// (AccessRules::max_body_bytes, max_upload_bytes); cpp-httplib itself refuses a body
  /// declared longer than the largest of those and `max_body_bytes`.
  Server(int port, std::size_t max_body_bytes, const std::function<std::unique_ptr<Handler>(int port)>& make_handler);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;
  int port() const { return port_; }
  /// Serves until stop() (from another thread or a signal handler's thread).
  void run();
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int port_ = 0;
};

}  // namespace tribolab::studio
