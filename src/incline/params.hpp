// Parameters of a disc launched across a rough incline (seed 000) and the quantities
// derived from them. Frame (SPEC section 1): x across the slope along the launch, y up the
// slope; the disc moves down, so y < 0. See docs/theory.md#incline-seed-000.
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "numerics/units.hpp"

namespace tribolab::incline {

/// Motion regimes of model B for a disc launched with v0 > 0 (seed 000, 陸-一 and 圖六).
enum class Regime {
  stops,           ///< k < 1: the disc stops at t_stop (x_stop, y_stop)
  terminal_speed,  ///< k = 1 (or mu = phi = 0): the speed tends to a finite limit
  accelerates,     ///< k > 1: the speed grows without bound
};

const char* to_string(Regime regime);

struct Parameters {
  double mu = 0.634;        ///< kinetic friction coefficient, >= 0 (seed 000: 0.583-0.634)
  double phi = 0.3658;      ///< incline angle, rad, in [0, pi/2) (seed 000: 4.8-23.2 deg)
  double v0 = 2.62;         ///< launch speed along +x, m/s, >= 0 (seed 000: 1-3 m/s)
  double g = kDefaultG;     ///< gravitational acceleration, m/s^2 (the seed's value)
  /// Static friction coefficient deciding whether a disc at rest stays; default = mu.
  std::optional<double> mu_static;
  /// Model A only: friction component normal to the path divided by the mass, m/s^2,
  /// positive toward the left of the velocity (up the slope for a launch along +x).
  double normal_accel = 0.0;

  /// Empty when valid, else a message naming the bad field.
  std::string validate() const;
  /// Throws InputError with validate()'s message when invalid.
  void check() const;

  double mu_s() const { return mu_static.value_or(mu); }
  /// alpha = g mu cos(phi): friction deceleration, m/s^2 (seed 000, eq 1.1).
  double alpha() const { return g * mu * std::cos(phi); }
  /// beta = g sin(phi): gravity along the slope, m/s^2 (seed 000, eq 1.2).
  double beta() const { return g * std::sin(phi); }
  /// k = tan(phi) / mu = beta / alpha; 0 when phi = 0, +inf when mu = 0 < phi; exactly 1
  /// when within 8 ulps of 1 (rounding of tan and of degrees).
  double k() const;
  Regime regime() const;
  /// A disc at rest on this incline stays at rest: tan(phi) <= mu_s, or kinetic friction
  /// alone holds it (mu >= tan(phi)), since it cannot slide against a net up-slope force.
  bool stays_at_rest() const;
};

/// Degrees to radians and back: the same as tribolab::to_rad / to_deg (numerics/units.hpp),
/// kept for the callers outside the core; new code calls those.
inline double deg_to_rad(double deg) { return to_rad(deg); }
inline double rad_to_deg(double rad) { return to_deg(rad); }

}  // namespace tribolab::incline
