#include "report/format.hpp"

#include "numerics/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace tribolab::report {
namespace {

/// Decimal exponent of |v| after rounding to `digits` significant digits (so 0.0996 with 2
/// digits is 1.0e-01, exponent -1). v must be finite and non-zero.
int rounded_exponent(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*e", digits - 1, std::fabs(v));
  const char* e = std::strchr(buf, 'e');
  return std::atoi(e + 1);
}

/// "-0.000" -> "0.000": a value rounded to zero carries no sign.
std::string drop_negative_zero(std::string s) {
  if (s.size() > 1 && s[0] == '-' &&
      std::all_of(s.begin() + 1, s.end(), [](char c) { return c == '0' || c == '.'; })) {
    s.erase(0, 1);
  }
  return s;
}

std::string fixed(double v, int decimals) {
  return drop_negative_zero(fmt::format("{:.{}f}", v, std::max(decimals, 0)));
}

std::string superscript(int n) {
  static const char* const digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string out = n < 0 ? "⁻" : "";
  for (char c : std::to_string(std::abs(n))) out += digits[c - '0'];
  return out;
}

bool starts_with_ci(std::string_view s, std::size_t pos, std::string_view prefix) {
  if (s.size() - pos < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(s[pos + i])) != prefix[i]) return false;
  }
  return true;
}

std::size_t utf8_length(unsigned char lead) {
  if (lead >= 0xF0) return 4;
  if (lead >= 0xE0) return 3;
  if (lead >= 0xC0) return 2;
  return 1;
}

/// One UTF-8 character of `text` at `pos`, escaped; advances pos.
std::string take_char(std::string_view text, std::size_t& pos) {
  const std::size_t n = std::min(utf8_length(static_cast<unsigned char>(text[pos])),
                                 text.size() - pos);
  const std::string out = escape_text(text.substr(pos, n));
  pos += n;
  return out;
}

/// Recursive descent over the notation; stops after a '}' when inside a group.
std::string notation(std::string_view text, std::size_t& pos, bool in_group) {
  std::string out;
  while (pos < text.size()) {
    const char c = text[pos];
    if (c == '}' && in_group) {
      ++pos;
      return out;
    }
    if (c == '\\' && pos + 1 < text.size()) {
      ++pos;
      out += take_char(text, pos);
    } else if ((c == '_' || c == '^') && pos + 1 < text.size()) {
      const char* tag = c == '_' ? "sub" : "sup";
      ++pos;
      std::string inner;
      if (text[pos] == '{') {
        ++pos;
        inner = notation(text, pos, true);
      } else {
        inner = take_char(text, pos);
      }
      out += std::string("<") + tag + ">" + inner + "</" + tag + ">";
    } else {
      out += take_char(text, pos);
    }
  }
  return out;
}

}  // namespace

std::string notation_html(std::string_view text) {
  std::size_t pos = 0;
  return notation(text, pos, false);
}

std::string format_value(double value, int significant) {
  if (!std::isfinite(value)) return "—";
  return fmt::format("{:.{}g}", value, std::clamp(significant, 1, 17));
}

std::string format_uncertain(double value, double sigma) {
  if (!std::isfinite(value)) return "—";
  if (!std::isfinite(sigma) || sigma < 0) return format_value(value, 6);
  if (sigma == 0) return format_value(value, 12) + " ± 0";

  const int e_sigma = rounded_exponent(sigma, 2);  // sigma ~ d.d × 10^e_sigma
  const int last = e_sigma - 1;                    // decimal place of sigma's 2nd digit
  // Exponent of the value once rounded to sigma's last digit (99.96 ± 0.12 -> 100.0: 2).
  int e_value = e_sigma;
  if (value != 0) {
    const int digits = static_cast<int>(std::floor(std::log10(std::fabs(value)))) - last + 1;
    if (digits >= 1) e_value = rounded_exponent(value, digits);
  }
  const int top = std::max(e_sigma, e_value);
  if (top >= 6 || top < -3) {
    const double scale = std::pow(10.0, top);
    return "(" + fixed(value / scale, top - last) + " ± " + fixed(sigma / scale, top - last) +
           ")×10" + superscript(top);
  }
  if (last >= 0) {  // sigma >= 10: round both to a multiple of 10^last, no decimals
    const double unit = std::pow(10.0, last);
    return fixed(std::round(value / unit) * unit, 0) + " ± " +
           fixed(std::round(sigma / unit) * unit, 0);
  }
  return fixed(value, -last) + " ± " + fixed(sigma, -last);
}

namespace {

std::string escape(std::string_view raw, bool quotes) {
  // A field the core names in a message (field("floor_y"), a warning shown in a report) reads
  // as the command line's flag: the reports print their commands as command lines.
  const std::string text = spell_fields(raw, [](std::string_view name) {
    std::string flag = "--" + std::string(name);
    std::replace(flag.begin(), flag.end(), '_', '-');
    return flag;
  });
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += quotes ? "&quot;" : "\""; break;
      case '\'': out += quotes ? "&#39;" : "'"; break;
      case '\0': out += "\xEF\xBF\xBD"; break;  // U+FFFD: NUL is not allowed in HTML text
      default: out += c;
    }
  }
  return out;
}

}  // namespace

std::string html_escape(std::string_view text) { return escape(text, true); }

std::string escape_text(std::string_view text) { return escape(text, false); }

std::string script_safe(std::string_view js) {
  // In a JS string, template or regex literal "\/", "\x73" and "\x21" mean "/", "s" and "!",
  // so the rewritten text is the same program. These sequences occur only inside literals
  // in minified libraries (checked for Plotly.js: one "<!--" in a regex source string).
  std::string out;
  out.reserve(js.size() + 64);
  for (std::size_t i = 0; i < js.size(); ++i) {
    if (js[i] == '<') {
      if (starts_with_ci(js, i, "</script")) {
        out += "<\\/";
        ++i;  // skip '/', the loop copies the rest
        continue;
      }
      if (starts_with_ci(js, i, "<script")) {
        // "\x73" or "\x53": the same letter, 's' or 'S'.
        out += fmt::format("<\\x{:02x}", static_cast<unsigned char>(js[i + 1]));
        ++i;
        continue;
      }
      if (starts_with_ci(js, i, "<!--")) {
        out += "<\\x21";
        ++i;  // skip '!'
        continue;
      }
    }
    out += js[i];
  }
  return out;
}

std::string json_for_script(const nlohmann::json& j) {
  const std::string raw = j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string out;
  out.reserve(raw.size() + 64);
  for (char c : raw) {
    switch (c) {  // these occur only inside JSON strings, where \uXXXX means the same
      case '<': out += "\\u003c"; break;
      case '>': out += "\\u003e"; break;
      case '&': out += "\\u0026"; break;
      default: out += c;
    }
  }
  return out;
}

std::string base64(std::string_view bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {  // each 3 bytes -> 4 characters of 6 bits
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16 | static_cast<unsigned char>(bytes[i + 1]) << 8 |
                       static_cast<unsigned char>(bytes[i + 2]);
    for (int shift : {18, 12, 6, 0}) out += kAlphabet[(v >> shift) & 63];
  }
  if (const std::size_t rest = bytes.size() - i; rest > 0) {  // 1 or 2 bytes left: pad with '='
    unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    if (rest == 2) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += rest == 2 ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string slugify(std::string_view text, std::string_view fallback) {
  std::string out;
  bool dash = false;
  for (char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 128 && std::isalnum(u)) {
      if (dash && !out.empty()) out += '-';
      out += static_cast<char>(std::tolower(u));
      dash = false;
    } else {
      dash = true;
    }
  }
  return out.empty() ? std::string(fallback) : out;
}

}  // namespace tribolab::report
