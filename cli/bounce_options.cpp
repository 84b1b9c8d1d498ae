// Binds the shared bounce options (src/app/bounce/bounce_options.hpp) to a command's CLI11 flags.
#include "bounce_options.hpp"

#include "bounce/friction.hpp"
#include "bounce/normal_law.hpp"

#include <fmt/format.h>

namespace tribolab::cli {

void add_ball_options(CLI::App* cmd, bounce::Ball& ball) {
  cmd->add_option("--a", ball.a, "semi-major axis, m");
  cmd->add_option("--b", ball.b, "semi-minor axis, m");
  cmd->add_option("--mass", ball.mass, "mass, kg");
  cmd->add_option("--inertia", ball.inertia, "moment of inertia about the centre, kg m^2");
}

void add_law_options(CLI::App* cmd, app::LawOptions& o, bool with_mu) {
  using bounce::Seed001Law;
  auto choices = [](const std::vector<std::string>& names) {
    std::string s;
    for (const std::string& n : names) s += (s.empty() ? "" : "|") + n;
    return s;
  };
  cmd->add_option("--model", o.model, "normal law: " + choices(bounce::normal_model_names()));
  cmd->add_option("--K", o.K, fmt::format("stiffness, N/m^n; unset: the rugby-ball study's fit, {:g}", Seed001Law::K));
  cmd->add_option("--n", o.n, fmt::format("exponent; unset: the rugby-ball study's fit {:g} (hertz 1.5, hooke 1)", Seed001Law::n));
  cmd->add_option("--D", o.D, fmt::format("damping, N s/m^(n+1) (hooke: N s/m); unset: the rugby-ball study's fit {:g} "
                                          "(hertz, hooke 0)", Seed001Law::D));
  cmd->add_option("--restitution", o.restitution, "target central-impact restitution in (0, 1], instead of --D");
  if (with_mu) cmd->add_option("--mu", o.mu, "friction coefficient");
  cmd->add_option("--friction", o.friction, "friction model: " + choices(bounce::friction_kind_names()));
  cmd->add_option("--slip-scale", o.slip_scale, "v_s of the regularized law, m/s");
  cmd->add_option("--k-t", o.k_t, "tangential stiffness of the spring model, N/m");
  cmd->add_option("--c-t", o.c_t, "tangential damping of the spring model, N s/m");
  cmd->add_option("--tol", o.tol, "integrator tolerance, absolute and relative");
}

}  // namespace tribolab::cli
