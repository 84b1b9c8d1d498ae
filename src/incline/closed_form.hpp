// Closed-form model B (friction opposite the velocity, no normal component) for a disc
// launched along +x across a rough incline: seed 000, eqs 一-九, rewritten in power forms of
// u = vx/vx0 that stay finite and accurate in every regime (docs/theory.md#incline-seed-000).
//
// With s = -ln(vx/vx0) >= 0 and E(c, s) = (1 - e^{-c s}) / c (-> s as c -> 0):
//   vy = -vx0 e^{-s} sinh(k s)                                   (eq 五)
//   t  = vx0 / (2 alpha) [E(1+k, s) + E(1-k, s)]                  (eq 二)
//   x  = vx0^2 / (2 alpha) [E(2+k, s) + E(2-k, s)]                (eq 三)
//   y  = vx0^2 / (4 alpha) [E(2+2k, s) - E(2-2k, s)]              (eq 六)
//   ax = -alpha / cosh(k s),  ay = alpha tanh(k s) - beta         (eqs 一, 四)
// E is evaluated as -expm1(-c s)/c, exact at k = 1 and k = 2 where the printed formulas
// divide by zero. mu = 0 (smooth incline), phi = 0 and v0 = 0 have their own branches.
#pragma once

#include "incline/params.hpp"

#include <optional>
#include <vector>

namespace tribolab::incline {

/// Kinematic state of the disc at time t (SI: s, m, m/s, m/s^2).
struct State {
  double t = 0;   ///< time since launch, s
  double x = 0;   ///< across the slope, m (launch direction +x)
  double y = 0;   ///< up the slope, m (negative: the disc moves down)
  double vx = 0;  ///< m/s
  double vy = 0;  ///< m/s
  double ax = 0;  ///< m/s^2
  double ay = 0;  ///< m/s^2
};

/// Summary of a launch: what `incline predict` reports (SPEC section 5).
struct Prediction {
  double k = 0;                       ///< tan(phi)/mu; +inf when mu = 0 < phi
  Regime regime = Regime::stops;      ///< of the actual motion (v0 = 0: stops or slides)
  std::optional<double> t_stop;       ///< s, when it stops (0 when it never moves)
  std::optional<double> x_stop;       ///< m (seed eq 八)
  std::optional<double> y_stop;       ///< m, <= 0 (seed eq 九)
  std::optional<double> v_terminal;   ///< m/s, limit speed when regime = terminal_speed
  std::optional<double> x_limit;      ///< m, sup of x when finite (k < 2), else empty
  double a_x0 = 0, a_y0 = 0;          ///< initial acceleration, m/s^2
  double a_x_final = 0, a_y_final = 0;  ///< limit at the stop or as t -> infinity, m/s^2
  bool stays_at_rest = true;          ///< a disc at rest here stays (Parameters::stays_at_rest)
};

/// (1 - e^{-c s}) / c, with the limit s at c = 0; no cancellation for small |c s|.
double one_minus_exp_over(double c, double s);

class ClosedForm {
 public:
  /// Throws InputError when the parameters are invalid. normal_accel is ignored (model B).
  explicit ClosedForm(const Parameters& p);

  const Parameters& parameters() const { return p_; }
  Prediction predict() const;

  /// State while moving, at s = -ln(vx/vx0) >= 0 (requires mu > 0, v0 > 0).
  State at_log_speed_ratio(double s) const;
  /// t(s) of eq 二 (requires mu > 0, v0 > 0).
  double time_at(double s) const;
  /// Inverse of time_at for 0 <= t < t_stop (or any t >= 0 when it never stops).
  double log_speed_ratio_at(double t) const;

  /// State at any time t >= 0, including at rest after the stop and the special branches.
  State at(double t) const;
  std::vector<State> trajectory(const std::vector<double>& times) const;

  /// Stop time, s; infinite when the disc never stops.
  double t_stop() const { return t_stop_; }

 private:
  State rest_or_slide(double t, double t0, double x0, double y0) const;

  Parameters p_;
  double alpha_, beta_, k_, t_stop_;
};

}  // namespace tribolab::incline
