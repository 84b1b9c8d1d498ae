// Normal contact force laws N(d, d_dot) for the penetration d >= 0 of the support point
// into the floor (d_dot > 0 approaching). Every law is clamped so that N never pulls.
// docs/theory.md#bounce-normal-laws.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tribolab::bounce {

enum class NormalModel {
  hooke,               ///< N = K d + D d_dot (linear spring-dashpot, n = 1)
  hertz,               ///< N = K d^n (elastic, no damping; Hertz n = 3/2)
  hunt_crossley,       ///< N = K d^n + D d^n d_dot (Hunt & Crossley 1975, J. Appl. Mech. 42; seed 001)
  flores,              ///< N = K d^n (1 + 8(1 - e) / (5 e) d_dot / v_in) (Flores et al. 2011, Nonlinear Dyn. 65)
  lankarani_nikravesh, ///< N = K d^n (1 + 3(1 - e^2) / 4 d_dot / v_in) (Lankarani & Nikravesh 1990, J. Mech. Des. 112)
  gonthier,            ///< N = K d^n (1 + (1 - e^2) / e d_dot / v_in) (Gonthier et al. 2004, Multibody Syst. Dyn. 11)
};

/// The rugby-ball study's fitted Hunt–Crossley law (研究方法 六): N = K d^n + D d^n d_dot. The
/// defaults of every command's law, the seed's method and the demo's truth.
struct Seed001Law {
  static constexpr double K = 101054;  ///< N/m^n
  static constexpr double n = 1.51;
  static constexpr double D = 60423;   ///< N s/m^(n+1)
};

/// One row per normal law. A new law is one row here, its enumerator above, and its physics
/// (the damping it resolves to: bounce::resolve in normal_law.cpp; docs/theory.md
/// #bounce-normal-laws): its name, the front ends' choices and the messages follow from the row.
struct NormalModelInfo {
  NormalModel model;
  std::string_view name;  ///< as every front end spells it
  double default_n;       ///< exponent when none is given
  double default_D;       ///< damping when neither D nor a restitution is given
};
inline constexpr NormalModelInfo kNormalModels[] = {
    {NormalModel::hooke, "hooke", 1.0, 0.0},
    {NormalModel::hertz, "hertz", 1.5, 0.0},
    {NormalModel::hunt_crossley, "hunt-crossley", Seed001Law::n, Seed001Law::D},
    {NormalModel::flores, "flores", Seed001Law::n, Seed001Law::D},
    {NormalModel::lankarani_nikravesh, "lankarani-nikravesh", Seed001Law::n, Seed001Law::D},
    {NormalModel::gonthier, "gonthier", Seed001Law::n, Seed001Law::D},
};

/// The row of `m`.
const NormalModelInfo& info(NormalModel m);
/// "hooke", "hertz", "hunt-crossley", "flores", "lankarani-nikravesh", "gonthier".
std::string_view to_string(NormalModel m);
/// Parses the names above; nullopt for anything else.
std::optional<NormalModel> parse_normal_model(std::string_view name);
/// Every name, in the table's order (the choices of a `model` option).
std::vector<std::string> normal_model_names();

/// A law as the user gives it: (K, n, D) or (K, n, target restitution e).
struct NormalLawSpec {
  NormalModel model = NormalModel::hunt_crossley;
  double K = Seed001Law::K;  ///< stiffness, N/m^n (seed 001's fit: 101054 with n = 1.51)
  double n = Seed001Law::n;  ///< exponent (Hertz 1.5; forced to 1 for hooke); seed's fit 1.51
  /// Damping: Hooke N s/m; Hunt–Crossley family N s/m^(n+1) (seed's fit 60423). Used when
  /// `restitution` is empty.
  double D = Seed001Law::D;
  /// Target coefficient of restitution of a central impact, in (0, 1]; when set, D follows
  /// from it and the impact speed (see resolve()).
  std::optional<double> restitution;

  std::string validate() const;  ///< empty when valid; names the field ("K", "n", "D", "restitution")
};

/// A law ready to evaluate: N = max(0, K d^n (1 + chi d_dot)) for the Hunt–Crossley family
/// (chi = D/K), N = max(0, K d + D d_dot) for Hooke.
struct NormalLaw {
  bool linear = false;  ///< Hooke form (damping not multiplied by d^n)
  double K = 0;         ///< N/m^n
  double n = 1.5;       ///< exponent
  double D = 0;         ///< N s/m (Hooke) or N s/m^(n+1) (Hunt–Crossley family)

  struct Force {
    double N = 0;        ///< clamped normal force, N (>= 0)
    double elastic = 0;  ///< elastic part K d^n, N
    double dN_dd = 0;    ///< partial dN/dd at fixed d_dot (0 where clamped), N/m
    double dN_ddot = 0;  ///< partial dN/d(d_dot) at fixed d (0 where clamped), N s/m
  };
  /// Force at penetration d >= 0 (m) and rate d_dot (m/s). Inline (below): the contact
  /// solver calls it on every right-hand-side evaluation.
  Force eval(double d, double d_dot) const;
  /// Elastic potential energy K d^(n+1) / (n+1), J.
  double potential(double d) const;
};

inline NormalLaw::Force NormalLaw::eval(double d, double d_dot) const {
  Force f;
  if (!(d > 0)) return f;
  if (linear) {
    f.elastic = K * d;
    const double N = f.elastic + D * d_dot;
    if (N > 0) {
      f.N = N;
      f.dN_dd = K;
      f.dN_ddot = D;
    }
    return f;
  }
  // d^n as exp(n log d): glibc's exp and log together cost less than its pow (the contact
  // solver's largest single cost, docs/benchmarks.md#issue-15); the relative error grows by
  // |n log d| x 1.1e-16 (~1e-15 for d ~ 1 mm), far below any solver tolerance.
  const double dn = std::exp(n * std::log(d));
  f.elastic = K * dn;
  const double factor = 1 + (D / K) * d_dot;
  if (factor > 0) {
    f.N = f.elastic * factor;
    f.dN_dd = n * f.N / d;
    f.dN_ddot = D * dn;
  }
  return f;
}

/// Concrete law for an impact whose contact point approaches the floor at v_in > 0 (m/s).
/// `mass` is the mass of the central impact (kg), needed only by Hooke with a restitution.
/// Throws InputError for an invalid spec or a restitution the model cannot reach.
NormalLaw resolve(const NormalLawSpec& spec, double v_in, double mass);

/// Hunt–Crossley central impact (docs/theory.md#hunt-crossley-restitution): with
/// z = chi v_in, the restitution e solves (1 - e z) = (1 + z) exp(-z (1 + e)),
/// independent of K, n and the mass.
double hunt_crossley_restitution(double z);
/// Inverse: z = chi v_in for a restitution e in (0, 1]; exact to rounding.
double hunt_crossley_chi_v(double e);

/// Hooke (linear spring-dashpot) central impact with N clamped at 0: restitution as a
/// function of the damping ratio zeta = D / (2 sqrt(K m)) in [0, 1), and its inverse.
double hooke_restitution(double zeta);
double hooke_damping_ratio(double e);

}  // namespace tribolab::bounce
