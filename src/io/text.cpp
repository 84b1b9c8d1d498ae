#include "io/text.hpp"

#include "numerics/error.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace tribolab::io {

std::string_view trim(std::string_view s) {
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

std::optional<double> parse_optional_double(std::string_view text, const std::string& where,
                                            bool decimal_comma) {
  const std::string_view t = trim(text);
  if (t.empty()) return std::nullopt;
  return parse_double(t, where, decimal_comma);
}

double parse_double(std::string_view text, const std::string& where, bool decimal_comma) {
  std::string t(trim(text));
  if (decimal_comma) {
    const auto pos = t.find(',');
    if (pos != std::string::npos && t.find(',', pos + 1) == std::string::npos) t[pos] = '.';
  }
  std::string shown(t.substr(0, 40));
  if (t.empty()) throw InputError(where, "expected a number, found an empty field");
  const char* first = t.data();
  const char* last = t.data() + t.size();
  if (*first == '+') ++first;
  double value = 0;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec == std::errc::result_out_of_range) {
    throw InputError(where, "number out of range: '" + shown + "'");
  }
  if (ec != std::errc() || ptr != last) {
    throw InputError(where, "malformed number '" + shown + "'");
  }
  if (!std::isfinite(value)) throw InputError(where, "number must be finite, got '" + shown + "'");
  return value;
}

std::vector<std::string> split(std::string_view line, char delim) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const auto pos = line.find(delim, start);
    if (pos == std::string_view::npos) {
      out.emplace_back(line.substr(start));
      return out;
    }
    out.emplace_back(line.substr(start, pos - start));
    start = pos + 1;
  }
}

std::string read_file(const std::string& path, std::uint64_t max_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, std::string("cannot open: ") + std::strerror(errno));
  auto too_large = [&] {
    const std::string bound = max_bytes >= (1u << 20) ? std::to_string(max_bytes >> 20) + " MB"
                                                       : std::to_string(max_bytes) + " bytes";
    return InputError(path, "too large: over " + bound + ", the most a text input may hold");
  };
  std::string text;
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);  // a regular file's: read it at once
  if (!ec && size > max_bytes) throw too_large();
  if (!ec) text.reserve(static_cast<std::size_t>(size));
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    if (text.size() + static_cast<std::uint64_t>(in.gcount()) > max_bytes) throw too_large();
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw InputError(path, "read error");
  return text;
}

double check_track_value(double v, double max, const std::string& where, std::string_view what) {
  if (std::abs(v) <= max) return v;
  throw InputError(where, std::string(what) + " = " + format_number(v) + " is beyond +-" + format_number(max) +
                              " (the file's units): no tracked run has it (a typo, a lost decimal point, a "
                              "glitch?), and the fits cannot carry it");
}

std::string name_text_problem(std::string_view s) {
  auto byte_at = [&](std::size_t i, const char* what) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s (byte 0x%02x at character %zu)", what,
                  static_cast<unsigned>(static_cast<unsigned char>(s[i])), i + 1);
    return std::string(buf);
  };
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c == 0x7f) return byte_at(i, "contains a control character");
    // UTF-8 (RFC 3629): lead byte, then 0-3 continuation bytes 10xxxxxx; no overlong forms,
    // no surrogates, nothing above U+10FFFF.
    std::size_t n = 0;
    unsigned lo = 0x80, hi = 0xbf;  // allowed range of the first continuation byte
    if (c < 0x80) n = 0;
    else if (c >= 0xc2 && c <= 0xdf) n = 1;
    else if (c >= 0xe0 && c <= 0xef) { n = 2; if (c == 0xe0) lo = 0xa0; if (c == 0xed) hi = 0x9f; }
    else if (c >= 0xf0 && c <= 0xf4) { n = 3; if (c == 0xf0) lo = 0x90; if (c == 0xf4) hi = 0x8f; }
    else return byte_at(i, "is not valid UTF-8");
    for (std::size_t k = 1; k <= n; ++k) {
      if (i + k >= s.size()) return byte_at(i, "is not valid UTF-8");
      const auto d = static_cast<unsigned char>(s[i + k]);
      if (d < (k == 1 ? lo : 0x80) || d > (k == 1 ? hi : 0xbf)) return byte_at(i + k, "is not valid UTF-8");
    }
    i += n + 1;
  }
  return {};
}

std::string format_number(double v) {
  if (!std::isfinite(v)) return "";
  char buf[64];
  auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 12);
  return std::string(buf, ptr);
}

std::string csv_quote(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string o = "\"";
  for (char c : s) {
    if (c == '"') o += '"';
    o += c;
  }
  return o + "\"";
}

std::string csv_number(double v) {
  if (!std::isfinite(v)) return {};
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

}  // namespace tribolab::io
