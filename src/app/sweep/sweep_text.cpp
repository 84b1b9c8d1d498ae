#include "app/sweep/sweep_text.hpp"

#include <charconv>
#include <vector>

#include "io/text.hpp"
#include "numerics/error.hpp"

namespace tribolab::app {
namespace {

/// "theta_deg: message" (a core validation message) -> "message".
std::string without_quantity_name(const std::string& message) {
  const auto colon = message.find(": ");
  if (colon != std::string::npos && sweep::quantity_from_name(std::string_view(message).substr(0, colon))) {
    return message.substr(colon + 2);
  }
  return message;
}

}  // namespace

sweep::Axis parse_axis(std::string_view text, sweep::Quantity q, const std::string& option) {
  const std::vector<std::string> p = io::split(io::trim(text), ':');
  if (p.size() != 3) {
    throw InputError(option, "expected a range lo:hi:count (e.g. 100:170:71), got '" +
                                 std::string(text.substr(0, 40)) + "'");
  }
  sweep::Axis a;
  a.quantity = q;
  a.lo = io::parse_double(p[0], option);
  a.hi = io::parse_double(p[1], option);
  const std::string_view c = io::trim(p[2]);
  const auto [ptr, ec] = std::from_chars(c.data(), c.data() + c.size(), a.count);
  if (c.empty() || ec != std::errc() || ptr != c.data() + c.size()) {
    throw InputError(option, "count must be a whole number >= 1, got '" + std::string(c.substr(0, 40)) + "'");
  }
  if (auto e = a.validate(); !e.empty()) throw InputError(option, without_quantity_name(e));
  return a;
}

sweep::ValueOrAxis parse_value_or_axis(std::string_view text, sweep::Quantity q, const std::string& option) {
  sweep::ValueOrAxis r;
  if (text.find(':') != std::string_view::npos) {
    r.axis = parse_axis(text, q, option);
    return r;
  }
  r.value = io::parse_double(text, option);
  sweep::Axis single{q, r.value, r.value, 1};
  if (auto e = single.validate(); !e.empty()) throw InputError(option, without_quantity_name(e));
  return r;
}

sweep::Shard parse_shard(std::string_view text, const std::string& option) {
  const std::string_view t = io::trim(text);
  const auto slash = t.find('/');
  sweep::Shard s;
  auto parse = [&](std::string_view f, std::int64_t& v) {
    const auto [ptr, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
    return !f.empty() && ec == std::errc() && ptr == f.data() + f.size();
  };
  if (slash == std::string_view::npos || !parse(t.substr(0, slash), s.index) ||
      !parse(t.substr(slash + 1), s.count)) {
    throw InputError(option, "expected i/N with whole numbers 0 <= i < N (e.g. 0/4), got '" +
                                 std::string(text.substr(0, 40)) + "'");
  }
  if (auto e = s.validate(); !e.empty()) throw InputError(option, e);
  return s;
}

}  // namespace tribolab::app
