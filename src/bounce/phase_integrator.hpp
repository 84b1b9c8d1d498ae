// An allocation-free adaptive Dormand–Prince 5(4) integrator for one smooth phase of a
// contact, ended by "guard" functions that must stay positive (separation, stick/slip
// changes). Why not numerics::integrate: a sweep calls the contact solver millions of times
// from many threads, and numerics::integrate allocates (std::function events, vectors of
// hits) on every call; here the system, the guards and the observer are inlined templates
// and all state lives in fixed-size arrays.
//
// Stepper: Dormand & Prince 1980 (J. Comp. Appl. Math. 6, 19-26), the 5th-order solution
// propagated, the embedded 4th-order one for the error estimate, standard step control
// (Hairer, Nørsett & Wanner, Solving ODE I, §II.4). Events: a guard that becomes <= 0
// inside an accepted step [ta, ta + h] is located by TOMS 748 on tau -> guard(step(x_a, tau)),
// each evaluation being a fresh 5th-order step of length tau from ta. The event time and
// state are therefore as accurate as an accepted step (no interpolant error), at the cost of
// 5 right-hand-side calls per root iteration (the FSAL stage is skipped); the bracket end
// reuses the accepted step's guard value, and the time is bracketed to
// PhaseOptions::event_tol() — events are rare (a few per contact).
// See docs/theory.md#bounce-integrator.
#pragma once

#include "numerics/roots.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

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

}  // namespace detail

/// One Dormand–Prince step of length h from (t, x) with k1 = f(t, x). Writes the 5th-order
/// solution to x_new, f(t + h, x_new) to k7 (FSAL; skipped, and k7 left unset, when
/// `fsal` is false and err == nullptr: a trial step that only needs x_new) and, when
/// err != nullptr, the error estimate (5th minus 4th order).
template <std::size_t N, class Rhs>
void dopri_step(Rhs& rhs, double t, const Vec<N>& x, const Vec<N>& k1, double h, Vec<N>& x_new,
                Vec<N>& k7, Vec<N>* err, bool fsal = true) {
  using namespace detail;
  Vec<N> k2, k3, k4, k5, k6, y;
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

/// Integrates x' = rhs(x, dxdt, t) from (t0, x0) until t_end or until one of the E guards
/// (guards(t, x, g) fills g[0..E)) falls to <= 0. A guard that is <= 0 at t0 is armed only
/// once it has become positive (so a phase may start exactly on its boundary); if it is
/// still negative at the first step end, the phase ends at once (immediate = true).
/// observer(t, x) is called at t0 and after every accepted step and at the end.
template <std::size_t N, std::size_t E, class Rhs, class Guards, class Observer>
PhaseEnd<N> integrate_phase(Rhs&& rhs, Guards&& guards, Observer&& observer, double t0,
                            const Vec<N>& x0, double t_end, double h0,
                            const PhaseOptions& opt) {
  PhaseEnd<N> out;
  out.t = t0;
  out.x = x0;
  double t = t0;
  Vec<N> x = x0, k1, x_new, k7, err;
  std::array<double, E> g_a{}, g_b{};
  std::array<bool, E> armed{};
  guards(t, x, g_a);
  for (std::size_t i = 0; i < E; ++i) armed[i] = g_a[i] > 0;
  rhs(x, k1, t);
  ++out.rhs_calls;
  observer(t, x);
  double h = std::max(h0 > 0 ? h0 : opt.initial_step, 1e-300);
  std::size_t attempts = 0;
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
    dopri_step<N>(rhs, t, x, k1, h, x_new, k7, &err);
    out.rhs_calls += 6;
    double err_norm = 0;
    bool finite = true;
    for (std::size_t i = 0; i < N; ++i) {
      if (!std::isfinite(x_new[i])) finite = false;
      const double sc = opt.abs_tol + opt.rel_tol * std::max(std::abs(x[i]), std::abs(x_new[i]));
      err_norm = std::max(err_norm, std::abs(err[i]) / sc);
    }
    if (!finite || !std::isfinite(err_norm)) {
      // Shrink hard; a genuinely non-finite state shows up as underflow of h.
      h *= 0.1;
      if (h < 1e-18) {
        out.status = PhaseStatus::non_finite;
        break;
      }
      continue;
    }
    const double factor =
        err_norm == 0 ? 5.0 : std::clamp(0.9 * std::pow(err_norm, -0.2), 0.2, 5.0);
    if (err_norm > 1) {
      h *= std::max(factor, 0.1);
      continue;
    }
    // Accepted step [t, t + h]: look for guards crossing to <= 0.
    ++out.steps;
    guards(t + h, x_new, g_b);
    int hit = -1;
    double tau_hit = h;
    bool immediate = false;
    for (std::size_t i = 0; i < E; ++i) {
      if (!armed[i]) {
        if (g_b[i] > 0) {
          armed[i] = true;
        } else if (g_b[i] < 0 && out.steps == 1) {
          hit = static_cast<int>(i);
          tau_hit = 0;
          immediate = true;
          break;
        }
        continue;
      }
      if (g_b[i] > 0) continue;
      auto phi = [&](double tau) {
        if (tau == 0) return g_a[i];
        if (tau == h) return g_b[i];  // the accepted step itself: same bits as x_new
        Vec<N> xs, ks;
        dopri_step<N>(rhs, t, x, k1, tau, xs, ks, nullptr, false);
        out.rhs_calls += 5;
        std::array<double, E> gs{};
        guards(t + tau, xs, gs);
        return gs[i];
      };
      numerics::RootOptions root_options;
      root_options.x_tol = opt.event_tol();
      const numerics::RootResult root = numerics::find_root(phi, 0.0, h, root_options);
      const double tau = root.converged ? root.hi : h;  // hi: the guard is <= 0 there
      if (tau <= tau_hit) {
        tau_hit = tau;
        hit = static_cast<int>(i);
      }
    }
    if (hit >= 0) {
      Vec<N> xs = x;
      if (tau_hit > 0) {
        Vec<N> ks;
        dopri_step<N>(rhs, t, x, k1, tau_hit, xs, ks, nullptr, false);
        out.rhs_calls += 5;
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
    observer(t, x);
    h *= std::min(factor, 5.0);
  }
  out.t = t;
  out.x = x;
  out.next_step = h;
  return out;
}

}  // namespace tribolab::bounce
