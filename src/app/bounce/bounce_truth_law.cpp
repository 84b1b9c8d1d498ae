#include "app/bounce/bounce_truth_law.hpp"

#include "numerics/error.hpp"

#include <utility>

namespace tribolab::app {

void TruthLawOptions::apply(bounce::NormalLawSpec& s, bounce::FrictionModel& f) const {
  for (auto [v, name] : {std::pair{K, field("K")}, {n, field("n")}, {D, field("D")}, {mu, field("mu")}, {slip_scale, field("slip_scale")}})
    check_finite(v, name);
  s.model = parsed_model(model);
  s.K = K;
  s.n = s.model == bounce::NormalModel::hooke ? 1.0 : n;
  s.D = s.model == bounce::NormalModel::hertz ? 0.0 : D;
  s.restitution = restitution;
  if (auto e = s.validate(); !e.empty()) invalid(e);
  f.kind = parsed_friction(friction);
  f.mu = mu;
  f.slip_scale = slip_scale;
  if (auto e = f.validate(); !e.empty()) invalid(e);
}

const Fields<TruthLawOptions>& truth_law_fields() {
  static const Fields<TruthLawOptions> f = [] {
    using O = TruthLawOptions;
    Fields<O> d;
    auto law = [](FieldDecl& x) -> FieldDecl& { x.group = "truth law"; return x; };
    law(d.add("model", &O::model, "", "normal law")).one_of(bounce::normal_model_names());
    law(d.add("K", &O::K, "N/m^n", "stiffness")).in(ranges::stiffness);
    law(d.add("n", &O::n, "", "exponent (hooke: 1 whatever is given)"));
    law(d.add("D", &O::D, "N s/m^(n+1)", "damping (hertz: 0 whatever is given)")).in(ranges::damping);
    law(d.add("restitution", &O::restitution, "", "target restitution instead of D"));
    law(d.add("mu", &O::mu, "", "friction coefficient")).in(ranges::friction);
    law(d.add("friction", &O::friction, "", "friction model")).one_of(bounce::friction_kind_names());
    law(d.add("slip_scale", &O::slip_scale, "m/s", "v_s of the regularized law")).in(PhysicalRange{0, 1e3, "m/s", true});
    return d;
  }();
  return f;
}

}  // namespace tribolab::app
