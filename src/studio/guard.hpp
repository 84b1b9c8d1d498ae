// The studio's security rules (docs/design.md#studio), each a pure function of the request:
// a secret token on every request (as Jupyter does), the Host and Origin of the server's own
// address only (DNS rebinding, cross-site requests), bounded bodies, and every file inside
// the folder the studio was started on.
#pragma once

#include "studio/http.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace tribolab::studio {

struct AccessRules {
  std::string token;                     ///< the secret every request carries (make_token())
  int port = 0;                          ///< the port the server listens on (Host/Origin must name it)
  std::size_t max_body_bytes = 1 << 20;  ///< largest request body but an upload, bytes (the page sends small JSON)
  /// Requests answered per second on average, and in a burst (a token bucket over every
  /// request): beyond, 429. The page scrubbing frames sends some tens per second.
  double requests_per_second = 200;
  double request_burst = 400;
  /// Largest file uploaded (POST /api/upload), bytes: 2 GiB, a few minutes of 1080p phone
  /// video (streamed to disk, never held in memory; the frames kept are bounded apart).
  std::uint64_t max_upload_bytes = std::uint64_t{2} << 30;
};

/// The header a script sends the token in (a link or an <img> sends it as ?token=).
inline constexpr std::string_view kTokenHeader = "X-Tribolab-Token";

/// 256 random bits from std::random_device as 64 lower-case hex digits.
std::string make_token();

/// The answer refusing `request` (403 token missing or wrong, Host not 127.0.0.1:PORT or
/// localhost:PORT, Origin not http://127.0.0.1:PORT or http://localhost:PORT), or nullopt when
/// every rule holds. (The body's size is checked by the handler as it reads it: the limit
/// depends on the route.)
std::optional<Response> refuse(const Request& request, const Target& target, const AccessRules& rules);

/// Where a path given by the page lies inside `root` (an absolute, canonical folder).
struct Confined {
  std::filesystem::path path;  ///< absolute, symlinks resolved; empty when refused
  std::string problem;         ///< why refused ("" when accepted)
};

/// `relative` resolved inside `root`: refused when empty, absolute, holding a NUL or a ".."
/// component, when it passes through a symlink whose target is missing (writing would create
/// the target, wherever it is), or when it (after resolving every symlink:
/// std::filesystem::weakly_canonical) lies outside `root`.
Confined confine(const std::filesystem::path& root, std::string_view relative);

}  // namespace tribolab::studio
