#include "bounce/normal_law.hpp"
#include "numerics/physical_range.hpp"

#include "numerics/error.hpp"
#include "numerics/roots.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tribolab::bounce {

const NormalModelInfo& info(NormalModel m) {
  for (const NormalModelInfo& i : kNormalModels)
    if (i.model == m) return i;
  TRIBOLAB_ASSERT(false, "a NormalModel without its row in kNormalModels");
  return kNormalModels[0];
}

std::string_view to_string(NormalModel m) { return info(m).name; }

std::optional<NormalModel> parse_normal_model(std::string_view name) {
  for (const NormalModelInfo& i : kNormalModels)
    if (name == i.name) return i.model;
  return std::nullopt;
}

std::vector<std::string> normal_model_names() {
  std::vector<std::string> names;
  for (const NormalModelInfo& i : kNormalModels) names.emplace_back(i.name);
  return names;
}

std::string NormalLawSpec::validate() const {
  // Physical ranges: numerics/physical_range.hpp (docs/cli.md#physical-ranges).
  if (auto e = range_error(K, ranges::stiffness, "K"); !e.empty()) return e;
  if (model != NormalModel::hooke && (!std::isfinite(n) || !(n >= 1) || n > 3))
    return "n: exponent must lie in [1, 3]";
  if (restitution) {
    const double e = *restitution;
    if (!std::isfinite(e) || !(e > 0) || e > 1) return "restitution: must lie in (0, 1]";
    if (model == NormalModel::hertz && e != 1)
      return "restitution: the hertz law is purely elastic (e = 1); use hunt-crossley, flores, "
             "lankarani-nikravesh or gonthier for e < 1";
  } else {
    if (auto e = range_error(D, ranges::damping, "D"); !e.empty()) return e;
    if (model == NormalModel::hertz && D != 0)
      return "D: the hertz law has no damping (D = 0); use hunt-crossley for K d^n + D d^n d_dot";
  }
  return {};
}

double NormalLaw::potential(double d) const {
  if (!(d > 0)) return 0;
  return linear ? 0.5 * K * d * d : K * std::pow(d, n + 1) / (n + 1);
}

namespace {

// G(z, e) / z^2 with G = ln(1 + z) - ln(1 - e z) - z (1 + e), the Hunt–Crossley loop
// integral (docs/theory.md#hunt-crossley-restitution). For small z the series
// G = sum_{k>=2} ((-1)^(k+1) + e^k) z^k / k avoids the cancellation of O(z) terms.
double hc_G_over_z2(double z, double e) {
  if (z == 0) return -0.5 * (1 - e) * (1 + e);
  if (std::max(z, e * z) < 0.2) {
    double sum = -0.5 * (1 - e) * (1 + e);
    double zk = 1;  // z^(k-2)
    double ek = e * e;
    for (int k = 3; k < 40; ++k) {
      zk *= z;
      ek *= e;
      const double sign = (k % 2 == 1) ? 1.0 : -1.0;
      sum += (sign + ek) * zk / k;
    }
    return sum;
  }
  return (std::log1p(z) - std::log1p(-e * z) - z * (1 + e)) / (z * z);
}

}  // namespace

double hunt_crossley_restitution(double z) {
  TRIBOLAB_ASSERT(z >= 0 && std::isfinite(z), "z = " + std::to_string(z));
  if (z == 0) return 1.0;
  // G is increasing in e; G(z, 0) < 0; G -> +inf as e -> 1/z; unique root.
  const double e_hi = z < 1 ? 1.0 : std::nextafter(1.0 / z, 0.0);
  auto f = [z](double e) { return hc_G_over_z2(z, e); };
  if (f(e_hi) <= 0) return e_hi;
  const numerics::RootResult r = numerics::find_root(f, 0.0, e_hi);
  TRIBOLAB_ASSERT(r.converged, "Hunt-Crossley restitution root, z = " + std::to_string(z));
  return r.x;
}

double hunt_crossley_chi_v(double e) {
  TRIBOLAB_ASSERT(e > 0 && e <= 1, "e = " + std::to_string(e));
  if (e == 1) return 0.0;
  auto f = [e](double z) { return hc_G_over_z2(z, e); };
  // f(0) < 0; f -> +inf as z -> 1/e: move the upper end towards 1/e until f > 0. For tiny e
  // the root is within rounding of 1/e (1 - e z ~ exp(-1/e)); then 1/e's last
  // representable neighbour below is returned.
  double z_lo = 0;
  double z_hi = 0.5 / e;
  for (int k = 2;; ++k) {
    const double fv = f(z_hi);
    if (!std::isfinite(fv) || k > 60) return z_lo;
    if (fv > 0) break;
    z_lo = z_hi;
    z_hi = (1 - std::ldexp(1.0, -k)) / e;
  }
  const numerics::RootResult r = numerics::find_root(f, z_lo, z_hi);
  TRIBOLAB_ASSERT(r.converged, "Hunt-Crossley chi root, e = " + std::to_string(e));
  return r.x;
}

// Linear spring-dashpot, unit natural frequency, damping ratio zeta < 1:
// d = (v/wd) e^{-zeta t} sin(wd t). N = K d + D d_dot first vanishes at wd t* = phi with
// (1 - 2 zeta^2) sin(phi) + 2 zeta wd cos(phi) = 0, phi in (0, pi]; the ball leaves then
// (Schwager & Pöschel 2007, Granular Matter 9: the force-free separation).
double hooke_restitution(double zeta) {
  TRIBOLAB_ASSERT(zeta >= 0 && zeta < 1, "zeta = " + std::to_string(zeta));
  const double wd = std::sqrt((1 - zeta) * (1 + zeta));
  const double phi = std::numbers::pi - std::atan2(2 * zeta * wd, 1 - 2 * zeta * zeta);
  const double t = phi / wd;
  return -std::exp(-zeta * t) * (std::cos(phi) - zeta / wd * std::sin(phi));
}

double hooke_damping_ratio(double e) {
  TRIBOLAB_ASSERT(e > 0 && e <= 1, "e = " + std::to_string(e));
  if (e == 1) return 0.0;
  const double zeta_max = 1 - 1e-12;
  const double e_min = hooke_restitution(zeta_max);
  if (e <= e_min) {
    throw InputError("restitution", "the linear spring-dashpot cannot reach e = " +
                                        message_number(e) + " without overdamping (minimum " +
                                        message_number(e_min) + ")");
  }
  auto f = [e](double zeta) { return hooke_restitution(zeta) - e; };
  const numerics::RootResult r = numerics::find_root(f, 0.0, zeta_max);
  TRIBOLAB_ASSERT(r.converged, "Hooke damping root, e = " + std::to_string(e));
  return r.x;
}

NormalLaw resolve(const NormalLawSpec& spec, double v_in, double mass) {
  if (auto err = spec.validate(); !err.empty()) throw InputError(err);
  NormalLaw law;
  law.K = spec.K;
  law.n = spec.model == NormalModel::hooke ? 1.0 : spec.n;
  law.linear = spec.model == NormalModel::hooke;
  if (!spec.restitution) {
    law.D = spec.model == NormalModel::hertz ? 0.0 : spec.D;
    return law;
  }
  const double e = *spec.restitution;
  if (e == 1 || spec.model == NormalModel::hertz) return law;  // D = 0
  if (!(v_in > 0) || !std::isfinite(v_in)) {
    throw InputError("restitution", "a restitution-based law needs an approaching contact point");
  }
  double chi = 0;  // D / K, s/m
  switch (spec.model) {
    case NormalModel::hooke: {
      const double zeta = hooke_damping_ratio(e);
      law.D = 2 * zeta * std::sqrt(spec.K * mass);
      return law;
    }
    case NormalModel::hertz: break;
    case NormalModel::hunt_crossley: chi = hunt_crossley_chi_v(e) / v_in; break;
    case NormalModel::flores: chi = 8 * (1 - e) / (5 * e * v_in); break;
    case NormalModel::lankarani_nikravesh: chi = 3 * (1 - e * e) / (4 * v_in); break;
    case NormalModel::gonthier: chi = (1 - e * e) / (e * v_in); break;
  }
  law.D = chi * spec.K;
  return law;
}

}  // namespace tribolab::bounce
