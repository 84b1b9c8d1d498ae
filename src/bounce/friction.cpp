#include "bounce/friction.hpp"

#include <cmath>

namespace tribolab::bounce {

std::string_view to_string(FrictionKind k) {
  switch (k) {
    case FrictionKind::coulomb: return "coulomb";
    case FrictionKind::regularized: return "regularized";
    case FrictionKind::spring: return "spring";
  }
  return "?";
}

std::optional<FrictionKind> parse_friction_kind(std::string_view name) {
  for (FrictionKind k : {FrictionKind::coulomb, FrictionKind::regularized, FrictionKind::spring}) {
    if (name == to_string(k)) return k;
  }
  return std::nullopt;
}

std::string FrictionModel::validate() const {
  if (!std::isfinite(mu) || !(mu >= 0)) return "mu: friction coefficient must be >= 0";
  if (!std::isfinite(slip_scale) || !(slip_scale > 0)) return "slip-scale: must be positive (m/s)";
  if (!std::isfinite(k_t) || !(k_t > 0)) return "k-t: tangential stiffness must be positive (N/m)";
  if (!std::isfinite(c_t) || !(c_t >= 0)) return "c-t: tangential damping must be >= 0 (N s/m)";
  return {};
}

}  // namespace tribolab::bounce
