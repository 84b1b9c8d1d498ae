#include "app/bounce/bounce_options.hpp"

#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"

#include <fmt/format.h>

#include <cmath>

namespace tribolab::app {

using namespace tribolab::bounce;

namespace {

std::string comma_list(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

}  // namespace

NormalModel parsed_model(const std::string& name) {
  const auto m = parse_normal_model(name);
  if (!m) throw InputError(field("model"), "unknown model '" + name + "' (" + comma_list(normal_model_names()) + ")");
  return *m;
}

FrictionKind parsed_friction(const std::string& name) {
  const auto k = parse_friction_kind(name);
  if (!k) throw InputError(field("friction"), "unknown friction model '" + name + "' (" + comma_list(friction_kind_names()) + ")");
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
  s.K = K.value_or(Seed001Law::K);
  s.n = n.value_or(info(m).default_n);
  s.D = D.value_or(info(m).default_D);
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

const Fields<BallOptions>& ball_fields() {
  static const Fields<BallOptions> f = [] {
    Fields<Ball> b;  // the core's ball, its defaults the seed's rugby ball (bounce::Ball)
    b.add("a", &Ball::a, "m", "semi-major axis").in(ranges::size).group = "ball";
    b.add("b", &Ball::b, "m", "semi-minor axis").in(ranges::size).group = "ball";
    b.add("mass", &Ball::mass, "kg", "mass").in(ranges::mass).group = "ball";
    b.add("inertia", &Ball::inertia, "kg m^2", "moment of inertia about the centre").in(ranges::inertia).group = "ball";
    Fields<BallOptions> o;
    o.group(&BallOptions::ball, b);
    return o;
  }();
  return f;
}

const Fields<LawOptions>& law_fields() {
  static const Fields<LawOptions> f = [] {
    Fields<LawOptions> l;
    auto law = [](FieldDecl& d) -> FieldDecl& { d.group = "law"; return d; };
    law(l.add("model", &LawOptions::model, "", "normal law")).one_of(normal_model_names());
    law(l.add("K", &LawOptions::K, "N/m^n", fmt::format("stiffness; unset: the rugby-ball study's fit, {:g}", Seed001Law::K)))
        .in(ranges::stiffness);
    law(l.add("n", &LawOptions::n, "",
              fmt::format("exponent in [1, 3]; unset: the rugby-ball study's fit {:g} (hertz 1.5, hooke 1)", Seed001Law::n)));
    law(l.add("D", &LawOptions::D, "N s/m^(n+1)",
              fmt::format("damping (hooke: N s/m); unset: the rugby-ball study's fit {:g} (hertz, hooke 0)", Seed001Law::D)))
        .in(ranges::damping);
    law(l.add("restitution", &LawOptions::restitution, "", "target central-impact restitution in (0, 1], instead of D"));
    law(l.add("mu", &LawOptions::mu, "", "friction coefficient")).in(ranges::friction);
    law(l.add("friction", &LawOptions::friction, "", "friction model")).one_of(friction_kind_names());
    law(l.add("slip_scale", &LawOptions::slip_scale, "m/s", "v_s of the regularized law"))
        .in(PhysicalRange{0, 1e3, "m/s", true});
    law(l.add("k_t", &LawOptions::k_t, "N/m", "tangential stiffness of the spring model")).in(ranges::tangential_stiffness);
    law(l.add("c_t", &LawOptions::c_t, "N s/m", "tangential damping of the spring model")).in(ranges::tangential_damping);
    law(l.add("tol", &LawOptions::tol, "", "integrator tolerance, absolute and relative")).in(ranges::tolerance);
    return l;
  }();
  return f;
}

ResultKeys law_result_keys(const std::string& prefix) {
  return {{prefix + "model", "", "normal law used"},
          {prefix + "K", "N/m^n", "stiffness used"},
          {prefix + "n", "", "exponent used"},
          {prefix + "D", "N s/m^(n+1)", "damping used (resolved from the restitution when given)"}};
}

}  // namespace tribolab::app
