#include "bounce_options.hpp"

#include "io/text.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"

#include <cmath>

namespace tribolab::cli {

using namespace tribolab::bounce;

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

void add_ball_options(CLI::App* cmd, Ball& ball) {
  cmd->add_option("--a", ball.a, "semi-major axis, m (default 0.145)");
  cmd->add_option("--b", ball.b, "semi-minor axis, m (default 0.095)");
  cmd->add_option("--mass", ball.mass, "mass, kg (default 0.435)");
  cmd->add_option("--inertia", ball.inertia, "moment of inertia about the centre, kg m^2 (default 4.1e-3)");
}

Ball checked_ball(const Ball& ball) {
  check_finite(ball.a, "--a");
  check_finite(ball.b, "--b");
  check_finite(ball.mass, "--mass");
  check_finite(ball.inertia, "--inertia");
  if (auto e = ball.validate(); !e.empty()) invalid(e);
  return ball;
}

void LawOptions::add(CLI::App* cmd, bool with_mu) {
  cmd->add_option("--model", model,
                  "normal law: hooke|hertz|hunt-crossley|flores|lankarani-nikravesh|gonthier (default hunt-crossley)");
  cmd->add_option("--K", K, "stiffness, N/m^n (default 101054, the seed's fit)");
  cmd->add_option("--n", n, "exponent (default 1.51; hertz 1.5; hooke 1)");
  cmd->add_option("--D", D, "damping, N s/m^(n+1) (hooke: N s/m) (default 60423; hertz, hooke 0)");
  cmd->add_option("--restitution", restitution, "target central-impact restitution in (0, 1], instead of --D");
  if (with_mu) cmd->add_option("--mu", mu, "friction coefficient (default 0.5)");
  cmd->add_option("--friction", friction, "friction model: coulomb|regularized|spring (default coulomb)");
  cmd->add_option("--slip-scale", slip_scale, "v_s of the regularized law, m/s (default 0.01)");
  cmd->add_option("--k-t", k_t, "tangential stiffness of the spring model, N/m (default 2e4)");
  cmd->add_option("--c-t", c_t, "tangential damping of the spring model, N s/m (default 0)");
  cmd->add_option("--tol", tol,
                  "integrator tolerance, absolute and relative (default " + io::format_number(tol) + ")");
}

NormalLawSpec LawOptions::law() const {
  const auto m = parse_normal_model(model);
  if (!m) {
    throw InputError("--model", "unknown model '" + model +
                                    "' (hooke, hertz, hunt-crossley, flores, lankarani-nikravesh, gonthier)");
  }
  if (D && restitution) throw InputError("--D", "give either --D or --restitution, not both");
  if (K) check_finite(*K, "--K");
  if (n) check_finite(*n, "--n");
  if (D) check_finite(*D, "--D");
  if (restitution) check_finite(*restitution, "--restitution");
  if (*m == NormalModel::hooke && n && *n != 1) throw InputError("--n", "the hooke law is linear (n = 1)");
  NormalLawSpec s;
  s.model = *m;
  s.K = K.value_or(101054);
  s.n = n.value_or(*m == NormalModel::hertz ? 1.5 : (*m == NormalModel::hooke ? 1.0 : 1.51));
  s.D = D.value_or((*m == NormalModel::hertz || *m == NormalModel::hooke) ? 0.0 : 60423);
  s.restitution = restitution;
  if (auto e = s.validate(); !e.empty()) invalid(e);
  return s;
}

FrictionModel LawOptions::friction_model(double mu_value) const {
  const auto k = parse_friction_kind(friction);
  if (!k) throw InputError("--friction", "unknown friction model '" + friction + "' (coulomb, regularized, spring)");
  check_finite(mu_value, "--mu");
  check_finite(slip_scale, "--slip-scale");
  check_finite(k_t, "--k-t");
  check_finite(c_t, "--c-t");
  FrictionModel f;
  f.kind = *k;
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

}  // namespace tribolab::cli
