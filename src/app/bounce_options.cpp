#include "app/bounce_options.hpp"

#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"

#include <cmath>

namespace tribolab::app {

using namespace tribolab::bounce;

NormalModel parsed_model(const std::string& name) {
  const auto m = parse_normal_model(name);
  if (!m) {
    throw InputError(field("model"), "unknown model '" + name +
                                    "' (hooke, hertz, hunt-crossley, flores, lankarani-nikravesh, gonthier)");
  }
  return *m;
}

FrictionKind parsed_friction(const std::string& name) {
  const auto k = parse_friction_kind(name);
  if (!k) throw InputError(field("friction"), "unknown friction model '" + name + "' (coulomb, regularized, spring)");
  return *k;
}

void check_finite(double v, const std::string& option) {
  if (!std::isfinite(v)) throw InputError(option, "must be a finite number");
  if (auto e = subnormal_error(v); !e.empty()) throw InputError(option, e);
}

void invalid(const std::string& message) { throw input_error_of(message); }

double checked_g(double g, bool zero_allowed) {
  return check_range(g, zero_allowed ? ranges::gravity_or_zero : ranges::gravity, field("g"));
}

Ball checked_ball(const Ball& ball) {
  check_finite(ball.a, field("a"));
  check_finite(ball.b, field("b"));
  check_finite(ball.mass, field("mass"));
  check_finite(ball.inertia, field("inertia"));
  if (auto e = ball.validate(); !e.empty()) invalid(e);
  return ball;
}

NormalLawSpec LawOptions::law() const {
  const NormalModel m = parsed_model(model);
  if (D && restitution) throw InputError(field("D"), "give either " + field("D") + " or " + field("restitution") + ", not both");
  if (K) check_finite(*K, field("K"));
  if (n) check_finite(*n, field("n"));
  if (D) check_finite(*D, field("D"));
  if (restitution) check_finite(*restitution, field("restitution"));
  if (m == NormalModel::hooke && n && *n != 1) throw InputError(field("n"), "the hooke law is linear (n = 1)");
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
  check_finite(mu_value, field("mu"));
  check_finite(slip_scale, field("slip_scale"));
  check_finite(k_t, field("k_t"));
  check_finite(c_t, field("c_t"));
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
  check_range(tol, ranges::tolerance, field("tol"));
  ContactOptions o = contact_options_with_tolerance(tol);
  o.g = g;
  return o;
}

}  // namespace tribolab::app
