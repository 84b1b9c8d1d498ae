// An allocation-free adaptive Dormand–Prince 5(4) integrator for one smooth phase of a
// contact, ended by "guard" functions that must stay positive (separation, stick/slip
// changes). Why not numerics::integrate: a sweep calls the contact solver millions of times
// from many threads, and numerics::integrate allocates (std::function events, vectors of
// hits) on every call; here the system, the guards and the observer are inlined templates
// and all state lives in fixed-size arrays.
//
// Stepper: Dormand & Prince 1980 (J. Comp. Appl. Math. 6, 19-26), the 5th-order solution
// propagated, the embedded 4th-order one for the error estimate, standard step control
// (Hairer, Nørsett & Wanner, Solving ODE I, §II.4). Events (docs/theory.md#bounce-integrator):
// a guard that becomes <= 0 inside an accepted step [ta, ta + h] is located by TOMS 748 on
// the step's continuous extension (Dormand–Prince's 4th-order dense output, Hairer et al.
// §II.6, built from the stages already computed: no new right-hand-side calls, one guard
// evaluation per root iteration); then one exact 5th-order step of the located length from
// ta gives the event state, and the zero is re-located next to it on that step's own dense
// output (detail::polish_event), so the event is as accurate as an accepted step.
// A guard that is positive at both ends of a step can still dip below zero inside it (a
// brief lift-off near grazing): when the guard supplies its rate, a cubic Hermite on
// (g, g') at both ends flags a possible interior minimum, the minimum of g on the dense
// output is searched there, and a non-positive minimum is an event at the first crossing
// before it.

#pragma once

#include "numerics/roots.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <type_traits>

namespace tribolab::bounce {

template <std::size_t N>
using Vec = std::array<double, N>;

struct PhaseOptions {
  double abs_tol = 1e-10;       ///< absolute local error per component (state units)
  double rel_tol = 1e-10;       ///< relative local error per component
  double initial_step = 1e-5;   ///< first trial step, s
  double max_step = 0;          ///< step cap, s; 0 = none
  std::size_t max_steps = 2'000'000;  ///< accepted + rejected steps before giving up
  /// Width to which a guard's zero (an event time) is bracketed, s; 0 = automatic,
  /// 1e-4 s x abs_tol (e.g. 1e-9 s at tol 1e-5). An event time late by delta changes the
  /// state by at most |jump of the acceleration| x delta; in a bounce contact the largest
  /// jump (slip -> stick, mu N / m) stays below ~1e4 m/s^2, so the velocity error stays
  /// below abs_tol. The state at the event is exact for the bracketed time either way.
  double event_time_tol = 0;

  /// event_time_tol, with 0 resolved to its automatic value.
  double event_tol() const { return event_time_tol > 0 ? event_time_tol : 1e-4 * abs_tol; }

  std::string validate() const {
    if (!(abs_tol > 0) || !(rel_tol >= 0) || !std::isfinite(abs_tol) || !std::isfinite(rel_tol))
      return "integrator tolerances must be positive and finite";
    if (!(initial_step > 0) || !std::isfinite(initial_step)) return "initial step must be positive";
    if (!(max_step >= 0) || !std::isfinite(max_step)) return "max step must be >= 0";
    if (max_steps == 0) return "max steps must be positive";
    if (!(event_time_tol >= 0) || !std::isfinite(event_time_tol)) return "event time tolerance must be >= 0";
    return {};
  }
};

/// The largest growth of the step from one accepted step to the next (docs/theory.md#bounce-integrator,
/// "Step growth"). The error controller's h^5 model would allow up to 5x, but in a contact a
/// small error estimate is often an accident (an error component passing through zero, the
/// stiff tangential mode of the regularised law): on the seed's map 98 % (regularised) and
/// 83 % (Coulomb) of the rejected trial steps came right after an accepted step. 1.5 cuts the
/// right-hand-side calls per contact by 2-3 % on both friction laws at equal accuracy
/// (docs/benchmarks.md, "Issue 15, fourth pass").
inline constexpr double kMaxStepGrowth = 1.5;

/// Points of the dense output at which a guard that is negative at the end of a phase's first
/// step is looked at before the phase ends at once (integrate_phase).
inline constexpr int kFirstStepProbes = 16;

enum class PhaseStatus {
  guard,       ///< a guard reached zero (PhaseEnd::guard says which)
  reached_end, ///< t_end reached
  max_steps,   ///< step budget exhausted
  non_finite,  ///< the state became NaN/inf
  step_underflow,  ///< the step size fell below the rounding level of t
};

template <std::size_t N>
struct PhaseEnd {
  PhaseStatus status = PhaseStatus::reached_end;
  double t = 0;          ///< end time, s
  Vec<N> x{};            ///< state at t
  int guard = -1;        ///< guard that ended the phase
  bool immediate = false;  ///< the guard was already <= 0 right after the phase start
  std::size_t steps = 0;   ///< accepted steps
  std::size_t rhs_calls = 0;
  double next_step = 0;  ///< suggested first step for the following phase, s
};

namespace detail {

// Dormand–Prince 5(4) coefficients (Hairer, Nørsett & Wanner, Table II.5.2).
inline constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
inline constexpr double a21 = 1.0 / 5;
inline constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
inline constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
inline constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                        a54 = -212.0 / 729;
inline constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247,
                        a64 = 49.0 / 176, a65 = -5103.0 / 18656;
inline constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192,
                        b5 = -2187.0 / 6784, b6 = 11.0 / 84;
inline constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920,
                        e5 = -17253.0 / 339200, e6 = 22.0 / 525, e7 = -1.0 / 40;
// Dense output (Hairer, Nørsett & Wanner §II.6, the 4th-order continuous extension of
// dopri5; Shampine 1986, Math. Comp. 46, 135-150).
inline constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                        d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                        d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;

}  // namespace detail

/// The stages k3..k6 of one Dormand–Prince step (k2 is not used by the dense output).
template <std::size_t N>
struct DopriStages {
  Vec<N> k3, k4, k5, k6;
};

/// One Dormand–Prince step of length h from (t, x) with k1 = f(t, x). Writes the 5th-order
/// solution to x_new, f(t + h, x_new) to k7 (FSAL; skipped, and k7 left unset, when
/// `fsal` is false and err == nullptr: a trial step that only needs x_new), when
/// err != nullptr the error estimate (5th minus 4th order), and when stages != nullptr the
/// stages the dense output needs.
/// Always inline (as integrate_phase): the contact solver compiles its callers once per CPU
/// level (numerics/cpu_dispatch.hpp), and only inlined code runs at the caller's level.
template <std::size_t N, class Rhs>
[[gnu::always_inline]] inline void dopri_step(Rhs& rhs, double t, const Vec<N>& x, const Vec<N>& k1, double h,
                                              Vec<N>& x_new, Vec<N>& k7, Vec<N>* err, bool fsal = true,
                                              DopriStages<N>* stages = nullptr) {
  using namespace detail;
  DopriStages<N> local;
  DopriStages<N>& st = stages ? *stages : local;
  Vec<N>& k3 = st.k3;
  Vec<N>& k4 = st.k4;
  Vec<N>& k5 = st.k5;
  Vec<N>& k6 = st.k6;
  Vec<N> k2, y;
  for (std::size_t i = 0; i < N; ++i) y[i] = x[i] + h * a21 * k1[i];
  rhs(y, k2, t + c2 * h);
  for (std::size_t i = 0; i < N; ++i) y[i] = x[i] + h * (a31 * k1[i] + a32 * k2[i]);
  rhs(y, k3, t + c3 * h);
  for (std::size_t i = 0; i < N; ++i) y[i] = x[i] + h * (a41 * k1[i] + a42 * k2[i] + a43 * k3[i]);
  rhs(y, k4, t + c4 * h);
  for (std::size_t i = 0; i < N; ++i)
    y[i] = x[i] + h * (a51 * k1[i] + a52 * k2[i] + a53 * k3[i] + a54 * k4[i]);
  rhs(y, k5, t + c5 * h);
  for (std::size_t i = 0; i < N; ++i)
    y[i] = x[i] + h * (a61 * k1[i] + a62 * k2[i] + a63 * k3[i] + a64 * k4[i] + a65 * k5[i]);
  rhs(y, k6, t + h);
  for (std::size_t i = 0; i < N; ++i)
    x_new[i] = x[i] + h * (b1 * k1[i] + b3 * k3[i] + b4 * k4[i] + b5 * k5[i] + b6 * k6[i]);
  if (!fsal && err == nullptr) return;
  rhs(x_new, k7, t + h);
  if (err) {
    for (std::size_t i = 0; i < N; ++i)
      (*err)[i] = h * (e1 * k1[i] + e3 * k3[i] + e4 * k4[i] + e5 * k5[i] + e6 * k6[i] + e7 * k7[i]);
  }
}

/// The continuous extension of one accepted Dormand–Prince step [t, t + h]: a polynomial
/// in s = (tau / h) through x (s = 0) and x_new (s = 1) with the slopes k1 and k7 there,
/// 4th-order accurate inside (Hairer, Nørsett & Wanner §II.6, dopri5's CONTD5).
template <std::size_t N>
struct DopriDense {
  Vec<N> r1, r2, r3, r4, r5;

  void build(const Vec<N>& x, const Vec<N>& x_new, const Vec<N>& k1, const DopriStages<N>& st,
             const Vec<N>& k7, double h) {
    using namespace detail;
    for (std::size_t i = 0; i < N; ++i) {
      r1[i] = x[i];
      r2[i] = x_new[i] - x[i];
      r3[i] = h * k1[i] - r2[i];
      r4[i] = r2[i] - h * k7[i] - r3[i];
      r5[i] = h * (d1 * k1[i] + d3 * st.k3[i] + d4 * st.k4[i] + d5 * st.k5[i] + d6 * st.k6[i] +
                   d7 * k7[i]);
    }
  }
  /// The state at s = tau / h in [0, 1].
  void at(double s, Vec<N>& out) const {
    const double s1 = 1 - s;
    for (std::size_t i = 0; i < N; ++i)
      out[i] = r1[i] + s * (r2[i] + s1 * (r3[i] + s * (r4[i] + s1 * r5[i])));
  }
};

namespace detail {

/// Where the cubic Hermite p on [0, 1] with p(0) = p0, p(1) = p1, p'(0) = m0, p'(1) = m1
/// (slopes per unit s) has an interior local minimum: its s, or -1 when there is none.
inline double hermite_interior_minimum(double p0, double p1, double m0, double m1) {
  // p(s) = p0 + m0 s + c s^2 + e s^3 with c = 3 (p1 - p0) - 2 m0 - m1, e = m0 + m1 - 2 (p1 - p0).
  const double dp = p1 - p0;
  const double c = 3 * dp - 2 * m0 - m1;
  const double e = m0 + m1 - 2 * dp;
  // p'(s) = m0 + 2 c s + 3 e s^2; a minimum where p' changes from - to +.
  const double A = 3 * e, B = 2 * c, C = m0;
  double roots[2];
  int n = 0;
  if (std::abs(A) <= 1e-14 * (std::abs(B) + std::abs(C))) {
    if (B != 0) roots[n++] = -C / B;
  } else {
    const double disc = B * B - 4 * A * C;
    if (disc < 0) return -1;
    const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
    if (q != 0) roots[n++] = q / A;
    if (q != 0) roots[n++] = C / q;
  }
  for (int k = 0; k < n; ++k) {
    const double s = roots[k];
    if (s > 0 && s < 1 && 2 * c + 6 * e * s > 0) return s;
  }
  return -1;
}

}  // namespace detail

namespace detail {

/// The event of guard `i` located at tau1 on the dense output of the step [t, t + h] is
/// refined: one exact step of length tau1 from (t, x) (its FSAL stage included) gives the
/// state there and a new dense output on [t, t + tau1], which matches that exact state and
/// its slope at tau1 and so is accurate to a far higher order near tau1 than the first one
/// (its error grows like (tau - tau1)^2 away from the end). The guard's zero is
/// re-bracketed near tau1 on it (expanding probes from event_tol, guided by a secant) and
/// located by TOMS 748 to event_tol. Returns the event time (guard <= 0 there, state in
/// xs); costs 6 right-hand-side calls plus a few guard evaluations. If the zero lies
/// after tau1 beyond the reach of that extrapolation, it falls back to TOMS 748 on exact
/// steps over [tau1, h] when the guard is <= 0 at the step end (g_h), and otherwise (a dip
/// seen on the first dense output but not by the exact step) returns -1: no event.
template <std::size_t N, class Rhs, class GuardValue>
double polish_event(Rhs& rhs, GuardValue& guard_value, std::size_t i, double t, const Vec<N>& x,
                    const Vec<N>& k1, double g0, double g_h, double h, double tau1,
                    const PhaseOptions& opt, Vec<N>& xs, std::size_t& rhs_calls) {
  DopriStages<N> st;
  Vec<N> ke;
  dopri_step<N>(rhs, t, x, k1, tau1, xs, ke, nullptr, true, &st);
  rhs_calls += 6;
  DopriDense<N> dense;
  dense.build(x, xs, k1, st, ke, tau1);
  auto guard_at = [&](double tau) {
    if (tau == 0) return g0;
    Vec<N> y;
    dense.at(tau / tau1, y);
    return guard_value(t + tau, y, i);
  };
  const double g1 = guard_value(t + tau1, xs, i);
  const double etol = opt.event_tol();
  if (!(g1 > 0) && guard_at(std::max(0.0, tau1 - etol)) > 0) return tau1;  // the usual case
  // Bracket [lo, hi] with guard(lo) > 0 >= guard(hi), one end at tau1.
  const bool left = !(g1 > 0);  // the zero is before tau1
  const double reach = left ? tau1 : 0.25 * (h - tau1);  // how far the dense output is trusted
  double lo = tau1, hi = tau1, g_lo = g1, g_hi = g1;
  double step = left ? etol : 0.5 * etol;
  bool found = false;
  for (int it = 0; it < 40 && !found; ++it) {
    step = std::min(step, reach);
    const double probe = left ? tau1 - step : tau1 + step;
    const double gp = guard_at(probe);
    (left ? lo : hi) = probe;
    (left ? g_lo : g_hi) = gp;
    found = left ? gp > 0 : !(gp > 0);
    if (found || step == reach) break;
    // Secant through (tau1, g1) and the probe predicts the zero; overshoot it by half.
    const double slope = (gp - g1) / (probe - tau1);
    const double predicted = slope != 0 ? std::abs(g1 / slope) : 0;
    step = std::max(8 * step, 1.5 * predicted);
  }
  if (!found) {
    if (g_h > 0) return -1;  // a dip the exact step does not confirm
    // Exact steps from t over [tau1, h] (guard > 0 at tau1, <= 0 at h).
    auto exact = [&](double tau) {
      if (tau == tau1) return g1;
      if (tau == h) return g_h;
      Vec<N> y, ky;
      dopri_step<N>(rhs, t, x, k1, tau, y, ky, nullptr, false);
      rhs_calls += 5;
      return guard_value(t + tau, y, i);
    };
    numerics::RootOptions ro;
    ro.x_tol = etol;
    const numerics::RootResult root = numerics::find_root(exact, tau1, h, ro);
    const double tau = root.converged ? root.hi : h;
    Vec<N> ky;
    dopri_step<N>(rhs, t, x, k1, tau, xs, ky, nullptr, false);
    rhs_calls += 5;
    return tau;
  }
  auto phi = [&](double tau) {
    if (tau == lo) return g_lo;
    if (tau == hi) return g_hi;
    return guard_at(tau);
  };
  double tau = hi;
  if (hi - lo > etol) {
    numerics::RootOptions ro;
    ro.x_tol = etol;
    const numerics::RootResult root = numerics::find_root(phi, lo, hi, ro);
    if (root.converged) tau = root.hi;
  }
  if (tau != tau1) dense.at(tau / tau1, xs);
  return tau;
}

}  // namespace detail

namespace detail {

/// The error of a trial step in the max norm of the step control (Hairer, Nørsett & Wanner
/// §II.4): max_i w_i |err_i| / (abs_tol + rel_tol max(|x_i|, |x_new_i|)), with the weights
/// w_i = (*weights)[i] (all 1 when weights is null: a weight w holds its component to 1/w of
/// the tolerances); `finite` is false when a component of x_new is not finite
/// (docs/theory.md#bounce-integrator).
template <std::size_t N>
double step_error_norm(const Vec<N>& x, const Vec<N>& x_new, const Vec<N>& err, const PhaseOptions& opt,
                       bool& finite, const Vec<N>* weights = nullptr) {
  double err_norm = 0;
  finite = true;
  for (std::size_t i = 0; i < N; ++i) {
    if (!std::isfinite(x_new[i])) finite = false;
    const double sc = opt.abs_tol + opt.rel_tol * std::max(std::abs(x[i]), std::abs(x_new[i]));
    const double e = weights ? (*weights)[i] * std::abs(err[i]) : std::abs(err[i]);
    err_norm = std::max(err_norm, e / sc);
  }
  return err_norm;
}

/// The step size's factor after a trial step whose error norm is err_norm (Hairer, Nørsett &
/// Wanner §II.4): 0.9 err_norm^(-1/5), clamped to [0.2, 5], and at most `cap` (<= 5). Where the
/// cap wins, err_norm <= (0.9 / cap)^5, the power is not computed (about one step in five of
/// a contact at tol 1e-6; std::pow was ~5 % of the contact solver's time, docs/benchmarks.md,
/// "Issue 15, sixth pass"). The factor is the same either way.
inline double step_factor(double err_norm, double cap) {
  const double r = 0.9 / cap;
  if (err_norm <= r * r * r * r * r) return cap;
  return std::min(std::clamp(0.9 * std::pow(err_norm, -0.2), 0.2, 5.0), cap);
}

/// The retry after a rejected step of length h whose controller proposes h_new
/// (docs/theory.md#bounce-integrator, "Brief lift-offs"). When an armed guard with a known
/// rate is <= 0 at the trial end (g_b), the step may have failed because the right-hand side
/// is not smooth beyond that event (the normal force's kink at d = 0, seen by the later
/// stages): the retry is aimed just past the guard's zero, estimated by the quadratic through
/// g and g' at the start (g_a, r_a) and g at the trial end, so that little of the step lies
/// beyond it.
template <std::size_t E>
double retry_step_past_guard_zero(double h, double h_new, const std::array<bool, E>& armed,
                                  const std::array<double, E>& g_a, const std::array<double, E>& r_a,
                                  const std::array<double, E>& g_b) {
  for (std::size_t i = 0; i < E; ++i) {
    if (!armed[i] || g_b[i] > 0 || !(r_a[i] < 0)) continue;
    const double c = (g_b[i] - g_a[i] - r_a[i] * h) / (h * h);
    // Root of g_a + r_a tau + c tau^2 in (0, h]: the smaller positive one.
    const double disc = r_a[i] * r_a[i] - 4 * c * g_a[i];
    double tau = -g_a[i] / r_a[i];
    if (c != 0 && disc >= 0) tau = 2 * g_a[i] / (-r_a[i] + std::sqrt(disc));
    if (tau > 0 && tau < h) h_new = std::min(h_new, std::max(1.05 * tau, 0.1 * h));
  }
  return h_new;
}

/// For an armed guard over the accepted step [0, h] (values g_a, g_b and rates r_a, r_b at
/// its ends; guard_at(tau) on the dense output): h if it is <= 0 at the step end; else, if it
/// dips to <= 0 inside the step, a time where it does so; else -1
/// (docs/theory.md#bounce-integrator, "Brief lift-offs").
template <class GuardAt>
double guard_zero_bound(double h, double g_a, double g_b, double r_a, double r_b, GuardAt&& guard_at) {
  if (!(g_b > 0)) return h;
  // Positive at both ends: a dip below zero inside? Only where the guard falls at the
  // start and rises at the end (rates known), and its cubic Hermite has an interior
  // minimum; that minimum is then searched on the dense output.
  if (!(r_a < 0 && r_b > 0)) return -1;
  const double s_min = hermite_interior_minimum(g_a, g_b, h * r_a, h * r_b);
  if (s_min < 0) return -1;
  double lo_m = 0, hi_m = h, tau_m = s_min * h;
  double g_m = guard_at(tau_m);
  // Golden-section search for the minimum on [0, h], started at the Hermite minimum;
  // it stops at a non-positive value or when the minimum is known to 1e-3 h (then g
  // there is within ~1e-6 g'' h^2 / 2 of the minimum, far below the tolerance).
  constexpr double kGold = 0.3819660112501051;
  for (int it = 0; it < 40 && g_m > 0 && hi_m - lo_m > 1e-3 * h; ++it) {
    const bool right = tau_m - lo_m < hi_m - tau_m;
    const double probe = right ? tau_m + kGold * (hi_m - tau_m) : tau_m - kGold * (tau_m - lo_m);
    const double g_p = guard_at(probe);
    if (g_p < g_m) {
      (right ? lo_m : hi_m) = tau_m;
      tau_m = probe;
      g_m = g_p;
    } else {
      (right ? hi_m : lo_m) = probe;
    }
  }
  return g_m > 0 ? -1 : tau_m;
}

/// Guards not yet armed after an accepted step (values g_b at its end): one that became
/// positive is armed (newly_armed); one still negative at the end of the phase's first
/// step (steps == 1) ends the phase at once, unless its bit is set in patient_guards
/// (docs/theory.md#bounce-integrator, "Zero-progress chatter"). Returns that guard, or -1.
template <std::size_t E>
int guard_ending_phase_at_once(const std::array<bool, E>& armed, const std::array<double, E>& g_b,
                               std::size_t steps, unsigned patient_guards, std::array<bool, E>& newly_armed) {
  for (std::size_t i = 0; i < E; ++i) {
    if (armed[i]) continue;
    if (g_b[i] > 0) {
      newly_armed[i] = true;
    } else if (g_b[i] < 0 && steps == 1 && !((patient_guards >> i) & 1u)) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

/// The first event of the accepted step [t, t + h] (docs/theory.md#bounce-integrator,
/// "Events"): the earliest zero on the dense output among the armed guards (zero_bound(i):
/// guard_zero_bound of guard i; guard_at(i, tau): guard i on the dense output), located by
/// TOMS 748 and refined by polish_event (state in x_ev); a dip the exact step does not
/// confirm is dropped and the search repeated without that guard. Returns the guard, or -1,
/// with its time in tau_hit (h: at the step end, whose state is x_new).
template <std::size_t N, std::size_t E, class Rhs, class GuardValue, class ZeroBound, class GuardAt>
int first_event_in_step(Rhs& rhs, GuardValue& guard_value, ZeroBound& zero_bound, GuardAt& guard_at,
                        const std::array<bool, E>& armed, double t, const Vec<N>& x, const Vec<N>& k1,
                        const std::array<double, E>& g_a, const std::array<double, E>& g_b, double h,
                        const PhaseOptions& opt, Vec<N>& x_ev, std::size_t& rhs_calls, double& tau_hit) {
  numerics::RootOptions root_options;
  root_options.x_tol = opt.event_tol();
  std::array<bool, E> excluded{};
  int hit = -1;
  tau_hit = h;
  for (std::size_t attempt = 0; attempt < E; ++attempt) {
    hit = -1;
    tau_hit = h;
    for (std::size_t i = 0; i < E; ++i) {
      if (!armed[i] || excluded[i]) continue;
      const double hi = zero_bound(i);  // the guard is <= 0 at tau = hi; -1: none
      if (hi < 0) continue;
      auto phi = [&](double tau) { return guard_at(i, tau); };
      const numerics::RootResult root = numerics::find_root(phi, 0.0, hi, root_options);
      const double tau = root.converged ? root.hi : hi;  // root.hi: the guard is <= 0 there
      if (tau <= tau_hit) {
        tau_hit = tau;
        hit = static_cast<int>(i);
      }
    }
    if (hit < 0 || tau_hit == h) break;
    const std::size_t ih = static_cast<std::size_t>(hit);
    const double tau = polish_event(rhs, guard_value, ih, t, x, k1, g_a[ih], g_b[ih], h, tau_hit, opt, x_ev,
                                    rhs_calls);
    if (tau >= 0) {
      tau_hit = tau;
      break;
    }
    excluded[ih] = true;  // the dip was not confirmed: look again without this guard
    hit = -1;
    tau_hit = h;
  }
  return hit;
}

}  // namespace detail

/// Integrates x' = rhs(x, dxdt, t) from (t0, x0) until t_end or until one of the E guards
/// falls to <= 0. guards(t, x, g) fills g[0..E); a guard functor that also takes a second
/// array, guards(t, x, g, rate), fills rate[i] = dg_i/dt too (NaN when unknown), which
/// enables the detection of a guard dipping below zero inside a step (see the top of this
/// file). A guard that is <= 0 at t0 is armed only once it has become positive (so a phase
/// may start exactly on its boundary); if it is still negative at the first step end, the
/// phase ends at once (immediate = true) — unless its bit is set in `patient_guards`: such a
/// guard then just waits to become positive (used to leave a point where two phases both
/// end at once, see contact.cpp).
/// observer(t, x) is called at t0 and after every accepted step and at the end.
/// error_weights (optional) weighs each component's local error (step_error_norm).
/// Always inline: see dopri_step. docs/theory.md#bounce-integrator.
template <std::size_t N, std::size_t E, class Rhs, class Guards, class Observer>
[[gnu::always_inline]] inline PhaseEnd<N> integrate_phase(Rhs&& rhs, Guards&& guards, Observer&& observer,
                                                          double t0, const Vec<N>& x0, double t_end, double h0,
                                                          const PhaseOptions& opt, unsigned patient_guards = 0,
                                                          const Vec<N>* error_weights = nullptr) {
  using G = std::array<double, E>;
  constexpr bool has_rates = std::is_invocable_v<Guards&, double, const Vec<N>&, G&, G&>;
  auto eval_guards = [&](double tt, const Vec<N>& st, G& g, G& rate) {
    if constexpr (has_rates) {
      guards(tt, st, g, rate);
    } else {
      guards(tt, st, g);
      rate.fill(std::numeric_limits<double>::quiet_NaN());
    }
  };
  auto guard_value = [&](double tt, const Vec<N>& st, std::size_t i) {
    G g{}, rate{};
    eval_guards(tt, st, g, rate);
    return g[i];
  };
  PhaseEnd<N> out;
  out.t = t0;
  out.x = x0;
  double t = t0;
  Vec<N> x = x0, k1, x_new, k7, err, x_ev;
  DopriStages<N> stages;
  DopriDense<N> dense;
  bool dense_built = false;
  G g_a{}, g_b{}, r_a{}, r_b{};
  std::array<bool, E> armed{};
  eval_guards(t, x, g_a, r_a);
  for (std::size_t i = 0; i < E; ++i) armed[i] = g_a[i] > 0;
  rhs(x, k1, t);
  ++out.rhs_calls;
  observer(t, x);
  double h = std::max(h0 > 0 ? h0 : opt.initial_step, 1e-300);
  std::size_t attempts = 0;
  bool after_rejection = false;  // the last trial step was rejected (no growth on the next accept)
  while (true) {
    if (t >= t_end) {
      out.status = PhaseStatus::reached_end;
      break;
    }
    if (++attempts > opt.max_steps) {
      out.status = PhaseStatus::max_steps;
      break;
    }
    if (opt.max_step > 0) h = std::min(h, opt.max_step);
    bool last = false;
    if (t + h >= t_end) {
      h = t_end - t;
      last = true;
    }
    if (h <= 4 * std::numeric_limits<double>::epsilon() * std::abs(t)) {
      out.status = PhaseStatus::step_underflow;
      break;
    }
    dopri_step<N>(rhs, t, x, k1, h, x_new, k7, &err, true, &stages);
    out.rhs_calls += 6;
    bool finite = true;
    const double err_norm = detail::step_error_norm<N>(x, x_new, err, opt, finite, error_weights);
    if (!finite || !std::isfinite(err_norm)) {
      // Shrink hard; a genuinely non-finite state shows up as underflow of h.
      h *= 0.1;
      if (h < 1e-18) {
        out.status = PhaseStatus::non_finite;
        break;
      }
      continue;
    }
    if (err_norm > 1) {
      double h_new = h * detail::step_factor(err_norm, 5.0);
      if constexpr (has_rates) {
        eval_guards(t + h, x_new, g_b, r_b);  // k7 was evaluated there: no new model call
        h_new = detail::retry_step_past_guard_zero<E>(h, h_new, armed, g_a, r_a, g_b);
      }
      h = h_new;
      after_rejection = true;
      continue;
    }
    // Accepted step [t, t + h]: look for guards crossing to <= 0.
    ++out.steps;
    dense_built = false;
    auto guard_at = [&](std::size_t i, double tau) {
      if (tau == 0) return g_a[i];
      if (tau == h) return g_b[i];  // the accepted step itself: same bits as x_new
      if (!dense_built) {
        dense.build(x, x_new, k1, stages, k7, h);
        dense_built = true;
      }
      Vec<N> xs;
      dense.at(tau / h, xs);
      G gs{}, rs{};
      eval_guards(t + tau, xs, gs, rs);
      return gs[i];
    };
    eval_guards(t + h, x_new, g_b, r_b);
    std::array<bool, E> newly_armed{};
    int hit = detail::guard_ending_phase_at_once<E>(armed, g_b, out.steps, patient_guards, newly_armed);
    if (hit >= 0 && h > opt.event_tol()) {
      // A guard that starts at zero can rise and fall back below zero inside a long first step
      // (the spring model entering its elastic phase on the cap: positive for 1.5 ms, then a
      // stick-slip change, docs/theory.md#bounce-integrator, "Zero-progress chatter"). If the
      // dense output shows it positive inside the step, the first step is retried up to there,
      // where the guard is armed, instead of ending the phase at once.
      const std::size_t ih = static_cast<std::size_t>(hit);
      double tau_positive = -1;
      for (int k = kFirstStepProbes - 1; k >= 1 && tau_positive < 0; --k) {
        const double tau = h * k / kFirstStepProbes;
        if (guard_at(ih, tau) > 0) tau_positive = tau;
      }
      if (tau_positive > 0) {
        --out.steps;
        h = tau_positive;
        continue;
      }
    }
    const bool immediate = hit >= 0;
    double tau_hit = immediate ? 0 : h;
    if (!immediate) {
      auto zero_bound = [&](std::size_t i) {
        return detail::guard_zero_bound(h, g_a[i], g_b[i], r_a[i], r_b[i],
                                        [&](double tau) { return guard_at(i, tau); });
      };
      hit = detail::first_event_in_step<N, E>(rhs, guard_value, zero_bound, guard_at, armed, t, x, k1, g_a, g_b, h,
                                              opt, x_ev, out.rhs_calls, tau_hit);
    }
    for (std::size_t i = 0; i < E; ++i) armed[i] = armed[i] || newly_armed[i];
    if (hit >= 0) {
      Vec<N> xs = x;
      if (tau_hit == h) {
        xs = x_new;
      } else if (tau_hit > 0) {
        xs = x_ev;
      }
      out.status = PhaseStatus::guard;
      out.guard = hit;
      out.immediate = immediate;
      out.t = t + tau_hit;
      out.x = xs;
      out.next_step = h;
      if (tau_hit > 0) observer(out.t, out.x);
      return out;
    }
    t = last ? t_end : t + h;
    x = x_new;
    k1 = k7;
    g_a = g_b;
    r_a = r_b;
    observer(t, x);
    // No growth right after a rejection (Hairer, Nørsett & Wanner §II.4, dopri5): the step
    // just accepted was cut to what the error allowed, growing it again at once mostly buys
    // another rejection; otherwise at most kMaxStepGrowth (docs/theory.md#bounce-integrator).
    h *= detail::step_factor(err_norm, after_rejection ? 1.0 : kMaxStepGrowth);
    after_rejection = false;
  }
  out.t = t;
  out.x = x;
  out.next_step = h;
  return out;
}

}  // namespace tribolab::bounce
