// Numerical models A and B (and any friction law mu(speed)) for the disc on the incline,
// integrated with numerics::integrate (Dormand-Prince 5(4), dense output, events).
//
// Equations (seed 000, 肆-三; SPEC section 2), with v-hat = v/|v| and n-hat its left normal:
//   dv/dt = -g cos(phi) mu(|v|) v-hat + f_N/m n-hat - g sin(phi) y-hat,   dx/dt = v.
// Model B has f_N = 0; model A adds f_N/m = Parameters::normal_accel.
//
// The stop is singular (v-hat is undefined at v = 0 and the solution has fractional powers
// of t_stop - t), so a step straddling it would be inaccurate. Below a switch speed the
// integration changes its independent variable to tau = ln(v_switch/|v|) with state
// (t, x, y, psi), psi = direction of v:
//   dt/dtau = |v|/(-a_t),  dx/dtau = |v| cos(psi) dt/dtau,  dy/dtau = |v| sin(psi) dt/dtau,
//   dpsi/dtau = a_n/(-a_t),  a_t = -g cos(phi) mu - g sin(phi) sin(psi),
//   a_n = f_N/m - g sin(phi) cos(psi),
// which is smooth up to |v| -> 0 (tau -> infinity) while the speed decreases (a_t < 0).
// See docs/theory.md#numerical-model.
#pragma once

#include "incline/closed_form.hpp"
#include "incline/params.hpp"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace tribolab::incline {

enum class Model {
  A,  ///< friction with a component normal to the path (Parameters::normal_accel)
  B,  ///< friction opposite the velocity only (the seed's conclusion)
};

/// Kinetic friction coefficient as a function of speed (m/s); must return a finite value
/// >= 0. Empty: the constant Parameters::mu.
using FrictionLaw = std::function<double(double speed)>;

/// Rectangle of the incline plane; the integration stops when the disc leaves it.
struct Region {
  double x_min = -1e300, x_max = 1e300;  ///< m
  double y_min = -1e300, y_max = 1e300;  ///< m
};

struct NumericOptions {
  Model model = Model::B;
  FrictionLaw friction_law;               ///< empty = constant mu
  std::optional<Region> region;           ///< stop when leaving it (status left_region)
  /// Integrate at least to this time, s, even past the last sample (e.g. to find the stop
  /// with no samples requested); the integration always ends at the stop if the disc rests.
  double t_max = 0.0;
  double abs_tol = 1e-12;                 ///< ODE absolute tolerance (m, m/s, rad)
  double rel_tol = 1e-12;                 ///< ODE relative tolerance
  /// Speed below which the log-speed formulation takes over, as a fraction of the launch
  /// speed; 0.05 keeps the time phase far from the singularity.
  double switch_fraction = 0.05;
  /// e-folds of speed integrated in the log-speed phase; 40 leaves a remaining speed of
  /// 4e-18 v_switch, whose contribution (a linear tail) is added analytically.
  double log_speed_span = 40.0;

  std::string validate() const;
};

enum class NumericStatus {
  reached_end,  ///< integrated to the last requested time
  left_region,  ///< left Region at t_exit
  failed,       ///< the integrator gave up (message says why)
};

struct NumericResult {
  NumericStatus status = NumericStatus::reached_end;
  std::string message;
  std::vector<State> samples;         ///< at the requested times (up to t_exit)
  std::optional<double> t_stop;       ///< first stop, s
  std::optional<double> x_stop, y_stop;  ///< m
  bool slides_after_stop = false;     ///< tan(phi) > mu_s and gravity beats kinetic friction
  std::optional<double> t_exit;       ///< when it left the region, s
  std::size_t steps = 0;              ///< accepted ODE steps, all phases
};

/// Simulates a launch along +x at Parameters::v0 from the origin, sampling at `times`
/// (non-decreasing, >= 0). Throws InputError for invalid parameters, options or times.
NumericResult simulate(const Parameters& p, const std::vector<double>& times,
                       const NumericOptions& options = {});

/// Same from an arbitrary initial state (t = 0): initial.x, y, vx, vy are used.
NumericResult simulate_from(const Parameters& p, const State& initial,
                            const std::vector<double>& times, const NumericOptions& options = {});

/// Acceleration (ax, ay) of the model at velocity (vx, vy); at v = 0 the friction acts up
/// the fall line (the direction of motion that is about to start).
std::pair<double, double> acceleration(const Parameters& p, const NumericOptions& options,
                                       double vx, double vy);

}  // namespace tribolab::incline
