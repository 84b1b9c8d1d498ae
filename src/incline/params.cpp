#include "incline/params.hpp"

#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"

#include <limits>

namespace tribolab::incline {

const char* to_string(Regime regime) {
  switch (regime) {
    case Regime::stops: return "stops";
    case Regime::terminal_speed: return "terminal_speed";
    case Regime::accelerates: return "accelerates";
  }
  return "?";
}

std::string Parameters::validate() const {
  // Physical ranges: numerics/physical_range.hpp, docs/cli.md#physical-ranges.
  if (auto e = range_error(mu, ranges::friction, "mu"); !e.empty()) return e;
  if (!std::isfinite(phi) || phi < 0 || phi >= M_PI / 2)
    return "phi must be in [0, 90) degrees";
  if (auto e = range_error(v0, ranges::speed, "v0"); !e.empty()) return e;
  if (auto e = range_error(g, ranges::gravity, "g"); !e.empty()) return e;
  if (mu_static)
    if (auto e = range_error(*mu_static, ranges::friction, "mu_static"); !e.empty()) return e;
  if (auto e = range_error(normal_accel, ranges::accel, "normal_accel"); !e.empty()) return e;
  return {};
}

void Parameters::check() const {
  const std::string message = validate();
  if (!message.empty()) throw InputError(message);
}

double Parameters::k() const {
  if (phi == 0) return 0.0;
  if (mu == 0) return std::numeric_limits<double>::infinity();
  const double k = std::tan(phi) / mu;
  // k within a few ulps of 1 is the boundary case itself: tan(45 deg) / 1 evaluates to
  // 1 - 1.1e-16, which would otherwise predict a stop after ~1e16 s instead of the
  // terminal speed v0/2. No physical input is known to 1e-15.
  if (std::abs(k - 1) <= 8 * std::numeric_limits<double>::epsilon()) return 1.0;
  return k;
}

Regime Parameters::regime() const {
  if (mu == 0) return phi == 0 ? Regime::terminal_speed : Regime::accelerates;
  const double kk = k();
  if (kk < 1) return Regime::stops;
  if (kk == 1) return Regime::terminal_speed;
  return Regime::accelerates;
}

bool Parameters::stays_at_rest() const {
  const double t = std::tan(phi);
  return t <= mu_s() || t <= mu;
}

}  // namespace tribolab::incline
