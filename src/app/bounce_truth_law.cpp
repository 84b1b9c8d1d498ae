#include "app/bounce_truth_law.hpp"

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

}  // namespace tribolab::app
