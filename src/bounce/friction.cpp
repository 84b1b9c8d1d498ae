#include "bounce/friction.hpp"
#include "numerics/physical_range.hpp"

#include <cmath>

namespace tribolab::bounce {

std::string_view to_string(FrictionKind k) {
  for (const FrictionKindInfo& i : kFrictionKinds)
    if (i.kind == k) return i.name;
  return "?";
}

std::optional<FrictionKind> parse_friction_kind(std::string_view name) {
  for (const FrictionKindInfo& i : kFrictionKinds)
    if (name == i.name) return i.kind;
  return std::nullopt;
}

std::vector<std::string> friction_kind_names() {
  std::vector<std::string> names;
  for (const FrictionKindInfo& i : kFrictionKinds) names.emplace_back(i.name);
  return names;
}

std::string FrictionModel::validate() const {
  // Physical ranges: numerics/physical_range.hpp (docs/cli.md#physical-ranges).
  if (auto e = range_error(mu, ranges::friction, "mu"); !e.empty()) return e;
  if (auto e = range_error(slip_scale, PhysicalRange{0, 1e3, "m/s", true}, "slip_scale"); !e.empty()) return e;
  if (auto e = range_error(k_t, ranges::tangential_stiffness, "k_t"); !e.empty()) return e;
  if (auto e = range_error(c_t, ranges::tangential_damping, "c_t"); !e.empty()) return e;
  return {};
}

}  // namespace tribolab::bounce
