// Tangential (friction) force models at the contact point. The slip velocity is the
// horizontal velocity of the material point at the support point, v_t = vx + omega Y.
// docs/theory.md#bounce-friction.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tribolab::bounce {

enum class FrictionKind {
  coulomb,      ///< exact Coulomb stick–slip, transitions located as events (default)
  regularized,  ///< f = -mu N tanh(v_t / v_s)
  spring,       ///< tangential spring–damper f = -(k_t u + c_t u'), capped at mu N
};

/// One row per friction law (a new law: a row, its enumerator and its force in contact.cpp).
struct FrictionKindInfo {
  FrictionKind kind;
  std::string_view name;  ///< as every front end spells it
};
inline constexpr FrictionKindInfo kFrictionKinds[] = {
    {FrictionKind::coulomb, "coulomb"}, {FrictionKind::regularized, "regularized"}, {FrictionKind::spring, "spring"}};

/// "coulomb", "regularized", "spring".
std::string_view to_string(FrictionKind k);
std::optional<FrictionKind> parse_friction_kind(std::string_view name);
/// Every name, in the table's order (the choices of a `friction` option).
std::vector<std::string> friction_kind_names();

struct FrictionModel {
  FrictionKind kind = FrictionKind::coulomb;
  double mu = 0.5;            ///< Coulomb coefficient (static = kinetic), typically 0.3-0.8
  double slip_scale = 0.01;   ///< v_s of the regularised law, m/s (smaller = closer to Coulomb)
  /// Tangential stiffness of the spring model, N/m. Default 2e4 N/m: about 2/3 (Mindlin's
  /// ratio for nu = 0.5) of the secant normal stiffness N_peak / d_max of the seed's law at a
  /// 4 m/s impact, so the tangential period 2 pi sqrt(m_t / k_t) (~20 ms, m_t ~ 0.2 kg) is
  /// comparable to the contact time and friction reversals appear.
  double k_t = 2.0e4;
  double c_t = 0.0;           ///< tangential damping of the spring model, N s/m (default none)

  std::string validate() const;  ///< empty when valid; names the field
};

}  // namespace tribolab::bounce
