// Inverse problem of seed 000 (陸-四, eq 十A): the kinetic friction coefficient from the
// stopping point alone, with propagated uncertainty and advice on the incline angle.
//
// With r = |x_stop / y_stop| and k = tan(phi)/mu, eqs 八 and 九 give r = 8(1-k^2)/(k(4-k^2)),
// i.e. the cubic (seed eq 10.3, multiplied by r)
//   Q(k, r) = r k^3 - 8 k^2 - 4 r k + 8 = 0.
// On (0, 1), r(k) falls strictly from +inf to 0, so for every r > 0 there is exactly one
// root in (0, 1): the physical one (the disc stops only when k < 1). It is found by
// bracketing (Q(0) = 8 > 0, Q(1) = -3r < 0), not by the trigonometric formula.
// sigma_mu follows by implicit differentiation: dk/dr = -Q_r/Q_k. docs/theory.md#mu-from-the-stopping-point-eq-十a.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "numerics/units.hpp"

namespace tribolab::incline {

struct StopMeasurement {
  double phi = 0;        ///< incline angle, rad, in (0, pi/2) (seed: 0.08-0.41 rad)
  double x_stop = 0;     ///< stopping point across the slope, m, > 0 (seed: 0.2-0.7 m)
  double y_stop = 0;     ///< stopping point up the slope, m, < 0 (seed: -0.03 to -0.28 m)
  double sigma_phi = 0;  ///< standard uncertainty of phi, rad (0 = exact)
  double sigma_pos = 0;  ///< standard uncertainty of x_stop and of y_stop, m (0 = exact)
  double g = kDefaultG;  ///< m/s^2; only used for the implied launch speed

  std::string validate() const;
};

struct MuFromStopResult {
  double mu = 0;      ///< kinetic friction coefficient
  double k = 0;       ///< tan(phi)/mu, in (0, 1)
  double r = 0;       ///< |x_stop / y_stop|
  double sigma_mu = 0;  ///< propagated standard uncertainty (0 when both sigmas are 0)
  double dmu_dphi = 0;  ///< partial derivatives, 1/rad and 1/m
  double dmu_dx = 0;
  double dmu_dy = 0;
  double v0 = 0;      ///< launch speed implied by x_stop (eq 八), m/s
  std::uintmax_t iterations = 0;  ///< of the root finder
};

/// The unique root in (0, 1) of Q(k, r) = 0, for r > 0 (throws InputError otherwise).
double k_from_ratio(double r, std::uintmax_t* iterations = nullptr);

/// The seed's closed formula (十A) for k: appendix version (eq 10.6, the 2 pi inside the
/// 1/3) when `as_printed_in_main_text` is false, else the main-text version (2 pi outside).
/// For checking the seed only.
double k_from_ratio_seed_formula(double r, bool as_printed_in_main_text);

/// mu from the stopping point (seed eq 十A). Throws InputError naming the bad quantity.
MuFromStopResult mu_from_stop(const StopMeasurement& m);

/// sigma_mu of the stop method for a disc launched at v0 on an incline of friction mu and
/// angle phi (its predicted stop point), with the given measurement uncertainties.
double stop_method_sigma_mu(double mu, double phi, double v0, double sigma_phi,
                            double sigma_pos, double g = kDefaultG);

/// What is held fixed while the incline angle is varied.
enum class SetupConstraint {
  launch_speed,   ///< the same launch speed v0 at every angle
  stop_distance,  ///< the same distance from launch to stop (e.g. the plate's size)
};

struct AngleAdvice {
  double phi = 0;       ///< angle minimising sigma_mu, rad
  double phi_max = 0;   ///< largest admissible angle (stop within max_stop_distance), rad
  bool at_boundary = false;  ///< the minimum is at phi_max (sigma_mu still falling there)
  double sigma_mu = 0;  ///< at that angle
  double x_stop = 0, y_stop = 0;  ///< predicted stop there, m
  std::uintmax_t iterations = 0;  ///< Brent iterations
};

/// The incline angle that minimises sigma_mu of the stop method, by a coarse scan and
/// Brent's method (Boost.Math), over the angles where the disc stops (0, atan(mu)) and, for
/// the launch_speed constraint, stops within `max_stop_distance` (m; +inf = no limit) of
/// the launch. `scale` is v0 (m/s) or the stop distance (m) according to `constraint`.
/// For mu <= 1, sigma_mu falls monotonically toward atan(mu) (docs/theory.md), so the
/// answer is usually the largest admissible angle (at_boundary). Throws InputError.
AngleAdvice best_angle(double mu, double scale, SetupConstraint constraint, double sigma_phi,
                       double sigma_pos, double max_stop_distance, double g = kDefaultG);

}  // namespace tribolab::incline
