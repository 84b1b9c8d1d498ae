#include "app/bounce_options.hpp"

#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"

#include <cmath>

namespace tribolab::app {

using namespace tribolab::bounce;

NormalModel parsed_model(const std::string& name) {
  const auto m = parse_normal_model(name);
  if (!m) {
    throw InputError("--model", "unknown model '" + name +
                                    "' (hooke, hertz, hunt-crossley, flores, lankarani-nikravesh, gonthier)");
  }
  return *m;
}

FrictionKind parsed_friction(const std::string& name) {
  const auto k = parse_friction_kind(name);
  if (!k) throw InputError("--friction", "unknown friction model '" + name + "' (coulomb, regularized, spring)");
  return *k;
}

void check_finite(double v, const char* option) {
  if (!std::isfinite(v)) throw InputError(option, "must be a finite number");
}

void invalid(const std::string& message) {
  const auto colon = message.find(':');
  if (colon != std::string::npos && colon < 24 && message.find(' ') > colon) {
    throw InputError("--" + message.substr(0, colon), message.substr(colon + 2));
  }
  throw InputError(message);
}

double checked_g(double g, bool zero_allowed) {
  return check_range(g, zero_allowed ? ranges::gravity_or_zero : ranges::gravity, "--g");
}

Ball checked_ball(const Ball& ball) {
  check_finite(ball.a, "--a");
  check_finite(ball.b, "--b");
  check_finite(ball.mass, "--mass");
  check_finite(ball.inertia, "--inertia");
  if (auto e = ball.validate(); !e.empty()) invalid(e);
  return ball;
}

NormalLawSpec LawOptions::law() const {
  const NormalModel m = parsed_model(model);
  if (D && restitution) throw InputError("--D", "give either --D or --restitution, not both");
  if (K) check_finite(*K, "--K");
  if (n) check_finite(*n, "--n");
  if (D) check_finite(*D, "--D");
  if (restitution) check_finite(*restitution, "--restitution");
  if (m == NormalModel::hooke && n && *n != 1) throw InputError("--n", "the hooke law is linear (n = 1)");
  NormalLawSpec s;
  s.model = m;
  s.K = K.value_or(101054);
  s.n = n.value_or(m == NormalModel::hertz ? 1.5 : (m == NormalModel::hooke ? 1.0 : 1.51));
  s.D = D.value_or((m == NormalModel::hertz || m == NormalModel::hooke) ? 0.0 : 60423);
  s.restitution = restitution;
  if (auto e = s.validate(); !e.empty()) invalid(e);
  return s;
}

FrictionModel LawOptions::friction_model(double mu_value) const {
  const FrictionKind k = parsed_friction(friction);
  check_finite(mu_value, "--mu");
  check_finite(slip_scale, "--slip-scale");
  check_finite(k_t, "--k-t");
  check_finite(c_t, "--c-t");
  FrictionModel f;
  f.kind = k;
  f.mu = mu_value;
  f.slip_scale = slip_scale;
  f.k_t = k_t;
  f.c_t = c_t;
  if (auto e = f.validate(); !e.empty()) invalid(e);
  return f;
}

ContactOptions LawOptions::contact(double g) const {
  check_range(tol, ranges::tolerance, "--tol");
  ContactOptions o = contact_options_with_tolerance(tol);
  o.g = g;
  return o;
}

}  // namespace tribolab::app
