#include "studio/guard.hpp"

#include <algorithm>
#include <cstdint>
#include <random>

namespace tribolab::studio {

namespace {

/// Compares without stopping at the first difference, so the time taken does not tell how
/// much of a guessed token was right.
bool same_secret(std::string_view a, std::string_view b) {
  unsigned char diff = a.size() == b.size() ? 0 : 1;
  const std::size_t n = std::min(a.size(), b.size());
  for (std::size_t i = 0; i < n; ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  return diff == 0;
}

}  // namespace

std::string make_token() {
  std::random_device device;
  static constexpr char kHex[] = "0123456789abcdef";
  std::string token;
  for (int word = 0; word < 8; ++word) {  // 8 x 32 bits
    std::uint32_t v = device();
    for (int nibble = 0; nibble < 8; ++nibble, v >>= 4) token += kHex[v & 0xf];
  }
  return token;
}

std::optional<Response> refuse(const Request& request, const Target& target, const AccessRules& rules) {
  const std::string port = std::to_string(rules.port);
  const auto host = request.header("Host");
  if (!host || (*host != "127.0.0.1:" + port && *host != "localhost:" + port))
    return json_error(403, "the Host header must be 127.0.0.1:" + port + " or localhost:" + port +
                               " (got '" + host.value_or("") + "')");
  if (const auto origin = request.header("Origin")) {
    if (*origin != "http://127.0.0.1:" + port && *origin != "http://localhost:" + port)
      return json_error(403, "requests from the page of another site are refused (Origin '" + *origin + "')");
  }
  const auto token = request.header(kTokenHeader) ? request.header(kTokenHeader) : target.param("token");
  if (!token) return json_error(403, "the token is missing: open the URL the studio printed");
  if (!same_secret(*token, rules.token)) return json_error(403, "the token is wrong: open the URL the studio printed");
  return std::nullopt;
}

Confined confine(const std::filesystem::path& root, std::string_view relative) {
  namespace fs = std::filesystem;
  if (relative.empty()) return {{}, "no file named"};
  if (relative.find('\0') != std::string_view::npos) return {{}, "the file name holds a NUL byte"};
  const fs::path rel(relative);
  if (rel.is_absolute() || rel.has_root_name() || rel.has_root_directory())
    return {{}, "'" + std::string(relative) + "' is not a path inside the studio's folder"};
  for (const fs::path& part : rel)
    if (part == "..") return {{}, "'" + std::string(relative) + "' leaves the studio's folder (..)"};
  std::error_code ec;
  // weakly_canonical keeps a symlink whose target does not exist as it is (it resolves only the
  // existing part), and writing to it would create its target wherever it points: refused.
  fs::path walk = root;
  for (const fs::path& part : rel) {
    walk /= part;
    if (fs::is_symlink(fs::symlink_status(walk, ec)) && !fs::exists(walk, ec))
      return {{}, "'" + std::string(relative) + "' passes through a symlink to a missing target"};
  }
  const fs::path resolved = fs::weakly_canonical(root / rel, ec);
  if (ec) return {{}, "'" + std::string(relative) + "' cannot be resolved: " + ec.message()};
  // Inside when root's components are a prefix of the resolved path's components.
  auto r = root.begin(), p = resolved.begin();
  for (; r != root.end(); ++r, ++p)
    if (p == resolved.end() || *p != *r) return {{}, "'" + std::string(relative) + "' lies outside the studio's folder"};
  return {resolved, ""};
}

}  // namespace tribolab::studio
