// Adaptive ODE integration with dense output and event location, shared by every model.
//
// The stepper is Dormand–Prince 5(4) with its 4th-order continuous extension
// (Dormand & Prince 1980, J. Comp. Appl. Math. 6; Hairer, Nørsett & Wanner, Solving ODE I,
// §II.6), from Boost.Odeint. Events g(t, x) = 0 are found on the dense output of each
// accepted step by TOMS 748 bracketing (roots.hpp), so an event is located to the
// accuracy of the interpolant without extra right-hand-side evaluations. A system is a
// callable rhs(const State& x, State& dxdt, double t), as in Boost.Odeint.
// See docs/theory.md#numerics.
#pragma once

#include "numerics/error.hpp"
#include "numerics/roots.hpp"

#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace tribolab::numerics {

struct OdeOptions {
  double abs_tol = 1e-10;     ///< absolute local error per component, in the state's units
  double rel_tol = 1e-10;     ///< relative local error per component
  double initial_step = 1e-4; ///< first trial step, s (adapted at once)
  double max_step = 0.0;      ///< upper bound on the step, s; 0 = unbounded
  std::size_t max_steps = 5'000'000;  ///< accepted steps before giving up

  /// Empty when valid, else a message naming the bad field.
  std::string validate() const {
    if (!(abs_tol > 0) || !(rel_tol >= 0)) return "ODE tolerances must be positive";
    if (!(initial_step > 0)) return "ODE initial step must be positive";
    if (!(max_step >= 0)) return "ODE max step must be >= 0";
    if (max_steps == 0) return "ODE max steps must be positive";
    return {};
  }
};

enum class OdeStatus {
  reached_end,  ///< integrated to t_end
  event,        ///< stopped at a terminal event (OdeResult::event_index)
  max_steps,    ///< gave up after OdeOptions::max_steps steps
  non_finite,   ///< the state became NaN or infinite
};

/// An event surface g(t, x) = 0. direction: +1 only rising crossings, -1 only falling,
/// 0 both. A terminal event stops the integration at the crossing.
template <class State>
struct OdeEvent {
  std::function<double(double t, const State& x)> g;
  int direction = 0;
  bool terminal = true;
};

struct EventHit {
  int index = -1;  ///< position in the events list
  double t = 0;    ///< time of the crossing, s
};

template <class State>
struct OdeResult {
  OdeStatus status = OdeStatus::reached_end;
  double t = 0;                 ///< final time (t_end or the terminal event), s
  State x{};                    ///< state at t
  int event_index = -1;         ///< terminal event that stopped it, else -1
  std::vector<EventHit> hits;   ///< every event crossing located, in time order
  std::size_t steps = 0;        ///< accepted steps
};

/// One accepted step [t0, t1] of the dense-output stepper, given to observers.
template <class State, class Dense>
struct StepView {
  double t0, t1;
  const Dense* dense;
  State at(double t) const {
    State x;
    const_cast<Dense*>(dense)->calc_state(t, x);
    return x;
  }
};

template <class State>
bool all_finite(const State& x) {
  for (double v : x) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

/// Integrates dx/dt = rhs(x, t) from (t0, x0) to t_end (t_end > t0), stopping at the first
/// terminal event. `observer(const StepView&)` is called for every accepted step, clipped
/// at t_end or at the terminal event; use view.at(t) to sample inside it.
template <class State, class Rhs, class Observer>
OdeResult<State> integrate(Rhs&& rhs, const State& x0, double t0, double t_end,
                           const OdeOptions& options,
                           const std::vector<OdeEvent<State>>& events, Observer&& observer) {
  namespace odeint = boost::numeric::odeint;
  using Dopri = odeint::runge_kutta_dopri5<State>;
  auto dense = odeint::make_dense_output(options.abs_tol, options.rel_tol,
                                         options.max_step > 0 ? options.max_step : 0.0, Dopri());
  using Dense = decltype(dense);

  OdeResult<State> result;
  result.t = t0;
  result.x = x0;
  if (!(t_end > t0)) return result;
  dense.initialize(x0, t0, std::min(options.initial_step, t_end - t0));

  std::vector<double> g_prev(events.size());
  for (std::size_t i = 0; i < events.size(); ++i) g_prev[i] = events[i].g(t0, x0);

  auto system = [&rhs](const State& x, State& dxdt, double t) { rhs(x, dxdt, t); };
  while (true) {
    if (result.steps >= options.max_steps) {
      result.status = OdeStatus::max_steps;
      return result;
    }
    const auto [ta, tb_raw] = dense.do_step(system);
    ++result.steps;
    if (!all_finite(dense.current_state())) {
      result.status = OdeStatus::non_finite;
      return result;
    }
    const double tb = std::min(tb_raw, t_end);
    State xb;
    if (tb_raw > t_end) {
      dense.calc_state(tb, xb);
    } else {
      xb = dense.current_state();
    }

    // Locate every event crossing inside [ta, tb]; keep the earliest terminal one.
    double t_stop = tb;
    int stop_index = -1;
    std::vector<EventHit> step_hits;
    for (std::size_t i = 0; i < events.size(); ++i) {
      const double g_end = events[i].g(tb, xb);
      const double g0 = g_prev[i];
      g_prev[i] = g_end;
      if (g0 == 0 || !((g0 < 0) != (g_end < 0) || g_end == 0)) continue;
      const int dir = g_end > g0 ? +1 : -1;
      if (events[i].direction != 0 && events[i].direction != dir) continue;
      auto g_of_t = [&](double t) {
        State x;
        dense.calc_state(t, x);
        return events[i].g(t, x);
      };
      const RootResult root = find_root(g_of_t, ta, tb);
      const double te = root.converged ? root.x : tb;
      step_hits.push_back({static_cast<int>(i), te});
      if (events[i].terminal && te <= t_stop) {
        t_stop = te;
        stop_index = static_cast<int>(i);
      }
    }
    std::sort(step_hits.begin(), step_hits.end(),
              [](const EventHit& a, const EventHit& b) { return a.t < b.t; });
    for (const EventHit& h : step_hits) {
      if (h.t <= t_stop) result.hits.push_back(h);
    }

    observer(StepView<State, Dense>{ta, t_stop, &dense});
    if (stop_index >= 0) {
      result.status = OdeStatus::event;
      result.event_index = stop_index;
      result.t = t_stop;
      dense.calc_state(t_stop, result.x);
      return result;
    }
    if (tb >= t_end) {
      result.status = OdeStatus::reached_end;
      result.t = t_end;
      result.x = xb;
      return result;
    }
  }
}

/// integrate() without an observer.
template <class State, class Rhs>
OdeResult<State> integrate(Rhs&& rhs, const State& x0, double t0, double t_end,
                           const OdeOptions& options,
                           const std::vector<OdeEvent<State>>& events = {}) {
  return integrate(std::forward<Rhs>(rhs), x0, t0, t_end, options, events, [](const auto&) {});
}

/// Fixed-step Dormand–Prince 5 (no error control): n equal steps from t0 to t1. Used to
/// verify the convergence order and as a reference for step-size studies.
template <class State, class Rhs>
State integrate_fixed(Rhs&& rhs, State x, double t0, double t1, int n) {
  boost::numeric::odeint::runge_kutta_dopri5<State> stepper;
  auto system = [&rhs](const State& s, State& dsdt, double t) { rhs(s, dsdt, t); };
  const double h = (t1 - t0) / n;
  for (int i = 0; i < n; ++i) stepper.do_step(system, x, t0 + i * h, h);
  return x;
}

}  // namespace tribolab::numerics
