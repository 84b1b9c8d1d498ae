#include "studio/server.hpp"

#include "numerics/error.hpp"

#include <httplib.h>

#include <algorithm>
#include <cstdint>

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
  const AccessRules& rules = impl_->handler->rules();
  // Every body reaches the handler unread (the content-reader routes below), which reads it
  // with its route's limit; cpp-httplib refuses (413) a body declared longer than both.
  impl_->http.set_payload_max_length(
      static_cast<std::size_t>(std::max<std::uint64_t>({max_body_bytes, rules.max_body_bytes, rules.max_upload_bytes})));
  const auto answer = [](const Response& from, httplib::Response& out) {
    out.status = from.status;
    out.set_header("Cache-Control", "no-store");
    out.set_header("X-Content-Type-Options", "nosniff");
    // The page loads nothing but what this server serves.
    out.set_header("Content-Security-Policy",
                   "default-src 'self'; script-src 'self' 'unsafe-inline' 'unsafe-eval'; style-src 'self' 'unsafe-inline'; "
                   "img-src 'self' blob: data:; connect-src 'self'");
    out.set_content(from.body, from.content_type.c_str());
  };
  const auto request = [](const httplib::Request& in) {
    Request r;
    r.method = in.method;
    r.target = in.target;
    for (const auto& [k, v] : in.headers) r.headers.emplace_back(k, v);
    return r;
  };
  // A request without a body (GET, OPTIONS: cpp-httplib reads none).
  const auto serve = [this, answer, request](const httplib::Request& in, httplib::Response& out) {
    Request r = request(in);
    r.body = in.body;
    answer(impl_->handler->handle(r), out);
  };
  // A request with a body: the handler reads it piece by piece as it arrives (an upload goes
  // to disk, never whole into memory). A body the handler left unread (a request refused
  // before its body) is read and dropped up to the upload limit, so that the client, still
  // sending, receives the answer rather than a reset connection.
  const auto serve_body = [this, answer, request](const httplib::Request& in, httplib::Response& out,
                                                  const httplib::ContentReader& reader) {
    Request r = request(in);
    bool read = false;
    // A form's parts arrive through the multipart reader (the plain one would not be called).
    const bool form = in.is_multipart_form_data();
    const auto read_with = [&](const httplib::ContentReceiver& receiver) {
      read = true;
      return form ? reader([](const httplib::MultipartFormData&) { return true; }, receiver) : reader(receiver);
    };
    r.read_body = [&](const std::function<bool(std::string_view)>& piece) {
      if (read) return false;  // the body is read once
      return read_with([&](const char* data, std::size_t n) { return piece(std::string_view(data, n)); });
    };
    const Response a = impl_->handler->handle(r);
    const std::uint64_t limit = impl_->handler->rules().max_upload_bytes;
    const std::uint64_t declared = in.get_header_value<std::uint64_t>("Content-Length");
    if (!read && declared <= limit) {
      std::uint64_t dropped = 0;
      read_with([&](const char*, std::size_t n) { return (dropped += n) <= limit; });
    }
    answer(a, out);  // after reading: a failed read sets cpp-httplib's status, the answer's own replaces it
  };
  impl_->http.Get(".*", serve).Options(".*", serve);
  impl_->http.Post(".*", serve_body).Put(".*", serve_body).Patch(".*", serve_body).Delete(".*", serve_body);
}

Server::~Server() { stop(); }

void Server::run() { impl_->http.listen_after_bind(); }

void Server::stop() { impl_->http.stop(); }

}  // namespace tribolab::studio
