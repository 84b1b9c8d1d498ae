// The studio's requests and answers as plain values (docs/design.md#studio): the request
// handler (handler.hpp) is a function from a Request to a Response, so every rule of the
// server is tested and fuzzed without a socket; cpp-httplib (server.cpp) only copies bytes in
// and out.
#pragma once

#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tribolab::studio {

struct Request {
  std::string method;  ///< "GET", "POST", ...
  std::string target;  ///< path and query as sent, percent-encoded: "/api/frame?i=3&token=..."
  std::vector<std::pair<std::string, std::string>> headers;  ///< as received, names in any case
  std::string body;
  /// The body still to be read, when the server did not read it into `body`: calls `piece`
  /// with each piece as it arrives, in order, until the end (true) or until `piece` returns
  /// false or the connection fails (false). The handler reads it with the limit of the route
  /// (an upload is written to disk piece by piece, any other body is at most
  /// AccessRules::max_body_bytes). Unset (tests, the fuzzer): the body is `body`.
  std::function<bool(const std::function<bool(std::string_view piece)>& piece)> read_body;
  /// The first header named `name` (case-insensitive), or nullopt.
  std::optional<std::string> header(std::string_view name) const;
};

struct Response {
  int status = 200;
  std::string content_type = "application/json";
  std::string body;
};

/// {"error": message} with a 4xx/5xx status.
Response json_error(int status, const std::string& message);
/// A JSON answer with status 200.
Response json_ok(const nlohmann::json& value);

/// The target split into its decoded path and decoded query parameters; nullopt for a
/// malformed percent escape or a target not starting with '/'.
struct Target {
  std::string path;
  std::vector<std::pair<std::string, std::string>> query;
  /// The first query parameter `name`, or nullopt.
  std::optional<std::string> param(std::string_view name) const;
};
std::optional<Target> parse_target(std::string_view target);

}  // namespace tribolab::studio
