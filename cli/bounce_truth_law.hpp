// The contact law of the synthetic generators (`bounce synth-video`, `synth-table`,
// `render`): --model --K --n --D --restitution --mu --friction --slip-scale with the seed's
// Hunt-Crossley fit and Coulomb mu = 0.5 as defaults (docs/cli.md#bounce-analyze).
#pragma once

#include "bounce_options.hpp"

#include "bounce/contact.hpp"
#include "numerics/error.hpp"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <utility>

namespace tribolab::cli {

inline bounce::NormalModel parse_model(const std::string& name) {
  const auto m = bounce::parse_normal_model(name);
  if (!m) throw InputError("--model", "unknown model '" + name + "' (hooke, hertz, hunt-crossley, flores, lankarani-nikravesh, gonthier)");
  return *m;
}

inline bounce::FrictionKind parse_friction(const std::string& name) {
  const auto k = bounce::parse_friction_kind(name);
  if (!k) throw InputError("--friction", "unknown friction model '" + name + "' (coulomb, regularized, spring)");
  return *k;
}

/// The contact law of the synthetic generators (truth).
struct TruthLaw {
  std::string model = "hunt-crossley", friction = "coulomb";
  double K = 101054, n = 1.51, D = 60423, mu = 0.5, slip_scale = 0.01;
  std::optional<double> restitution;
  void add(CLI::App* cmd) {
    cmd->add_option("--model", model, "normal law (default hunt-crossley)");
    cmd->add_option("--K", K, "stiffness, N/m^n (default 101054)");
    cmd->add_option("--n", n, "exponent (default 1.51)");
    cmd->add_option("--D", D, "damping, N s/m^(n+1) (default 60423)");
    cmd->add_option("--restitution", restitution, "target restitution instead of --D");
    cmd->add_option("--mu", mu, "friction coefficient (default 0.5)");
    cmd->add_option("--friction", friction, "coulomb|regularized|spring (default coulomb)");
    cmd->add_option("--slip-scale", slip_scale, "v_s of the regularized law, m/s (default 0.01)");
  }
  void apply(bounce::NormalLawSpec& s, bounce::FrictionModel& f) const {
    for (auto [v, name] : {std::pair{K, "--K"}, {n, "--n"}, {D, "--D"}, {mu, "--mu"}, {slip_scale, "--slip-scale"}})
      check_finite(v, name);
    s.model = parse_model(model);
    s.K = K;
    s.n = s.model == bounce::NormalModel::hooke ? 1.0 : n;
    s.D = s.model == bounce::NormalModel::hertz ? 0.0 : D;
    s.restitution = restitution;
    if (auto e = s.validate(); !e.empty()) invalid(e);
    f.kind = parse_friction(friction);
    f.mu = mu;
    f.slip_scale = slip_scale;
    if (auto e = f.validate(); !e.empty()) invalid(e);
  }
};

}  // namespace tribolab::cli
