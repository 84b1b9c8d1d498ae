// The contact law of the synthetic generators (`bounce synth-video`, `synth-table`, `render`):
// the truth the analyses should recover. Its defaults are fixed numbers (the seed's
// Hunt-Crossley fit K = 101054, n = 1.51, D = 60423, Coulomb mu = 0.5) rather than
// LawOptions' model-dependent ones, so a generated file states its truth whatever the model
// (hooke forces n = 1, hertz D = 0). Parsed with the same functions and messages as LawOptions
// (src/app/bounce/bounce_options.hpp); CLI11-free.
#pragma once

#include "app/common/option_fields.hpp"
#include "app/bounce/bounce_options.hpp"
#include "bounce/normal_law.hpp"

#include <optional>
#include <string>

namespace tribolab::app {

/// --model --K --n --D --restitution --mu --friction --slip-scale of the generators.
struct TruthLawOptions {
  std::string model = "hunt-crossley";  ///< normal law (bounce::parse_normal_model)
  double K = bounce::Seed001Law::K;     ///< stiffness, N/m^n
  double n = bounce::Seed001Law::n;     ///< exponent (hooke: 1 whatever is given)
  double D = bounce::Seed001Law::D;     ///< damping, N s/m^(n+1) (hertz: 0 whatever is given)
  std::optional<double> restitution;    ///< target central restitution, instead of D
  double mu = 0.5;                      ///< friction coefficient
  std::string friction = "coulomb";     ///< coulomb|regularized|spring
  double slip_scale = 0.01;             ///< v_s of the regularized law, m/s

  /// Checks every field (InputError naming the option) and fills the core's law and friction.
  void apply(bounce::NormalLawSpec& law, bounce::FrictionModel& friction_model) const;
};

/// The declarations of the generators' law options (group "truth law"; app/common/option_fields.hpp).
const Fields<TruthLawOptions>& truth_law_fields();

}  // namespace tribolab::app
