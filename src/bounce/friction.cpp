#include "bounce/friction.hpp"
#include "numerics/physical_range.hpp"

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
  // Physical ranges: numerics/physical_range.hpp (docs/cli.md#physical-ranges).
  if (auto e = range_error(mu, ranges::friction, "mu"); !e.empty()) return e;
  if (auto e = range_error(slip_scale, PhysicalRange{0, 1e3, "m/s", true}, "slip-scale"); !e.empty()) return e;
  if (auto e = range_error(k_t, ranges::tangential_stiffness, "k-t"); !e.empty()) return e;
  if (auto e = range_error(c_t, ranges::tangential_damping, "c-t"); !e.empty()) return e;
  return {};
}

}  // namespace tribolab::bounce
