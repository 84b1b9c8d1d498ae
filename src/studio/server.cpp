#include "studio/server.hpp"

#include "numerics/error.hpp"

#include <httplib.h>

namespace tribolab::studio {

struct Server::Impl {
  httplib::Server http;
  std::unique_ptr<Handler> handler;
};

Server::Server(int port, std::size_t max_body_bytes, const std::function<std::unique_ptr<Handler>(int)>& make_handler)
    : impl_(std::make_unique<Impl>()) {
  const char* host = "127.0.0.1";  // loopback only: never reachable from another machine
  port_ = port == 0 ? impl_->http.bind_to_any_port(host) : (impl_->http.bind_to_port(host, port) ? port : -1);
  if (port_ <= 0) throw InputError(field("port"), "127.0.0.1:" + std::to_string(port) + " cannot be listened on (taken?)");
  impl_->handler = make_handler(port_);
  // cpp-httplib answers a body over this size 413 itself, before reading it.
  impl_->http.set_payload_max_length(max_body_bytes);
  // Every method and path goes to the handler (which answers 404/405 itself), after the body is
  // read (a pre-routing handler would run before it).
  const auto serve = [this](const httplib::Request& in, httplib::Response& out) {
    Request r;
    r.method = in.method;
    r.target = in.target;
    r.body = in.body;
    for (const auto& [k, v] : in.headers) r.headers.emplace_back(k, v);
    const Response answer = impl_->handler->handle(r);
    out.status = answer.status;
    out.set_header("Cache-Control", "no-store");
    out.set_header("X-Content-Type-Options", "nosniff");
    // The page loads nothing but what this server serves.
    out.set_header("Content-Security-Policy",
                   "default-src 'self'; script-src 'self' 'unsafe-inline' 'unsafe-eval'; style-src 'self' 'unsafe-inline'; "
                   "img-src 'self' blob: data:; connect-src 'self'");
    out.set_content(answer.body, answer.content_type.c_str());
  };
  impl_->http.Get(".*", serve).Post(".*", serve).Put(".*", serve).Delete(".*", serve).Patch(".*", serve).Options(".*", serve);
}

Server::~Server() { stop(); }

void Server::run() { impl_->http.listen_after_bind(); }

void Server::stop() { impl_->http.stop(); }

}  // namespace tribolab::studio
