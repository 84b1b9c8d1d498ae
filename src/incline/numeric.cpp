#include "incline/numeric.hpp"

#include "numerics/error.hpp"
#include "numerics/ode.hpp"
#include "numerics/roots.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace tribolab::incline {

std::string NumericOptions::validate() const {
  if (!(abs_tol > 0) || !(rel_tol > 0)) return "ODE tolerances must be > 0";
  if (!std::isfinite(t_max) || t_max < 0) return "t_max must be finite and >= 0";
  if (!(switch_fraction > 0 && switch_fraction < 1)) return "switch_fraction must be in (0, 1)";
  if (!(log_speed_span > 0 && log_speed_span < 700)) return "log_speed_span must be in (0, 700)";
  if (region && !(region->x_min < region->x_max && region->y_min < region->y_max))
    return "region must have x_min < x_max and y_min < y_max";
  return {};
}

namespace {

using Vec4 = std::array<double, 4>;

double mu_at(const Parameters& p, const NumericOptions& o, double speed) {
  if (!o.friction_law) return p.mu;
  const double m = o.friction_law(speed);
  if (!std::isfinite(m) || m < 0) {
    throw InputError("friction law", "mu(" + std::to_string(speed) + " m/s) = " +
                                         std::to_string(m) + " is not a finite number >= 0");
  }
  return m;
}

class Runner {
 public:
  Runner(const Parameters& p, const NumericOptions& o, const std::vector<double>& times)
      : p_(p), o_(o), times_(times) {
    gcos_ = p.g * std::cos(p.phi);
    beta_ = p.beta();
    fn_ = o.model == Model::A ? p.normal_accel : 0.0;
    t_end_ = std::max(o.t_max, times.empty() ? 0.0 : times.back());
    ode_.abs_tol = o.abs_tol;
    ode_.rel_tol = o.rel_tol;
  }

  NumericResult run(const State& initial) {
    Vec4 s = {initial.x, initial.y, initial.vx, initial.vy};
    double t = 0;
    double speed = std::hypot(s[2], s[3]);
    if (speed == 0) {
      rest_or_slide(t, s[0], s[1]);
      return std::move(res_);
    }
    double v_switch = o_.switch_fraction * speed;
    for (int round = 0; round < 100; ++round) {
      const Phase1 r1 = time_phase(t, s, v_switch);
      if (r1.kind != Phase1::switched) return std::move(res_);
      t = r1.t;
      s = r1.x;
      const Phase2 r2 = log_speed_phase(t, s);
      if (r2.kind == Phase2::stopped) {
        res_.t_stop = r2.t;
        res_.x_stop = r2.x;
        res_.y_stop = r2.y;
        rest_or_slide(r2.t, r2.x, r2.y);
        return std::move(res_);
      }
      if (r2.kind != Phase2::speeds_up) return std::move(res_);
      // The speed stopped decreasing: back to time as the variable, with a lower switch.
      t = r2.t;
      s = r2.state;
      v_switch = 0.5 * std::hypot(s[2], s[3]);
    }
    res_.status = NumericStatus::failed;
    res_.message = "the speed oscillated around the stop more than 100 times";
    return std::move(res_);
  }

 private:
  struct Phase1 {
    enum Kind { done, switched } kind = done;
    double t = 0;
    Vec4 x{};
  };
  struct Phase2 {
    enum Kind { done, stopped, speeds_up } kind = done;
    double t = 0, x = 0, y = 0;
    Vec4 state{};
  };

  State make_state(double t, const Vec4& s) const {
    const auto [ax, ay] = acceleration(p_, o_, s[2], s[3]);
    return State{t, s[0], s[1], s[2], s[3], ax, ay};
  }

  void emit_until(double t_hi, const std::function<State(double)>& at) {
    while (next_ < times_.size() && times_[next_] <= t_hi) res_.samples.push_back(at(times_[next_++]));
  }

  void add_region_events(std::vector<numerics::OdeEvent<Vec4>>& ev, int ix, int iy) const {
    if (!o_.region) return;
    const Region r = *o_.region;
    ev.push_back({[=](double, const Vec4& s) { return s[ix] - r.x_min; }, -1, true});
    ev.push_back({[=](double, const Vec4& s) { return r.x_max - s[ix]; }, -1, true});
    ev.push_back({[=](double, const Vec4& s) { return s[iy] - r.y_min; }, -1, true});
    ev.push_back({[=](double, const Vec4& s) { return r.y_max - s[iy]; }, -1, true});
  }

  bool failed(numerics::OdeStatus status) {
    if (status == numerics::OdeStatus::max_steps) {
      res_.status = NumericStatus::failed;
      res_.message = "the ODE integrator reached its step limit";
      return true;
    }
    if (status == numerics::OdeStatus::non_finite) {
      res_.status = NumericStatus::failed;
      res_.message = "the state became non-finite";
      return true;
    }
    return false;
  }

  /// Integration in time from (t0, s0) until t_end, the switch speed (falling) or the region.
  Phase1 time_phase(double t0, const Vec4& s0, double v_switch) {
    emit_until(t0, [&](double t) { return make_state(t, s0); });
    Phase1 out;
    if (t0 >= t_end_) return out;
    auto rhs = [this](const Vec4& s, Vec4& d, double) {
      const auto [ax, ay] = acceleration(p_, o_, s[2], s[3]);
      d = {s[2], s[3], ax, ay};
    };
    std::vector<numerics::OdeEvent<Vec4>> ev;
    if (v_switch > 0) {
      ev.push_back({[v_switch](double, const Vec4& s) { return std::hypot(s[2], s[3]) - v_switch; },
                    -1, true});
    }
    const std::size_t first_region = ev.size();
    add_region_events(ev, 0, 1);
    auto observer = [&](const auto& view) {
      emit_until(view.t1, [&](double t) { return make_state(t, view.at(t)); });
    };
    const auto r = numerics::integrate(rhs, s0, t0, t_end_, ode_, ev, observer);
    res_.steps += r.steps;
    if (failed(r.status)) return out;
    if (r.status == numerics::OdeStatus::event) {
      if (v_switch > 0 && r.event_index == 0) {
        out.kind = Phase1::switched;
        out.t = r.t;
        out.x = r.x;
        return out;
      }
      TRIBOLAB_ASSERT(static_cast<std::size_t>(r.event_index) >= first_region, "event index");
      res_.status = NumericStatus::left_region;
      res_.t_exit = r.t;
    }
    return out;
  }

  /// Integration in tau = ln(v_s/|v|) with state (t, x, y, psi), from the switch to the stop.
  Phase2 log_speed_phase(double t0, const Vec4& s0) {
    const double v_s = std::hypot(s0[2], s0[3]);
    const Vec4 l0 = {t0, s0[0], s0[1], std::atan2(s0[3], s0[2])};
    auto tangential = [&](double tau, const Vec4& l) {
      const double v = v_s * std::exp(-tau);
      return -gcos_ * mu_at(p_, o_, v) - beta_ * std::sin(l[3]);
    };
    auto rhs = [&](const Vec4& l, Vec4& d, double tau) {
      const double v = v_s * std::exp(-tau);
      const double at = tangential(tau, l);
      const double an = fn_ - beta_ * std::cos(l[3]);
      const double dt = v / (-at);
      d = {dt, v * std::cos(l[3]) * dt, v * std::sin(l[3]) * dt, an / (-at)};
    };
    auto to_state = [&](double tau, const Vec4& l) {
      const double v = v_s * std::exp(-tau);
      return make_state(l[0], {l[1], l[2], v * std::cos(l[3]), v * std::sin(l[3])});
    };
    std::vector<numerics::OdeEvent<Vec4>> ev;
    ev.push_back({[&](double tau, const Vec4& l) { return -tangential(tau, l); }, -1, true});
    add_region_events(ev, 1, 2);
    auto observer = [&](const auto& view) {
      const double ta = view.at(view.t0)[0], tb = view.at(view.t1)[0];
      while (next_ < times_.size() && times_[next_] <= tb) {
        const double ti = std::max(times_[next_], ta);
        const auto root = numerics::find_root(
            [&](double tau) { return view.at(tau)[0] - ti; }, view.t0, view.t1);
        const double tau = root.converged ? root.x : view.t1;
        State st = to_state(tau, view.at(tau));
        st.t = times_[next_++];
        res_.samples.push_back(st);
      }
    };
    const double span = o_.log_speed_span;
    const auto r = numerics::integrate(rhs, l0, 0.0, span, ode_, ev, observer);
    res_.steps += r.steps;
    Phase2 out;
    if (failed(r.status)) return out;
    if (r.status == numerics::OdeStatus::event) {
      const State st = to_state(r.t, r.x);
      if (r.event_index == 0) {
        out.kind = Phase2::speeds_up;
        out.t = st.t;
        out.state = {st.x, st.y, st.vx, st.vy};
        return out;
      }
      res_.status = NumericStatus::left_region;
      res_.t_exit = st.t;
      return out;
    }
    // Remaining speed v_e = v_s e^{-span}: finish with constant deceleration a_t (linear tail).
    const double v_e = v_s * std::exp(-span);
    const double at = tangential(span, r.x);
    const double tail_t = v_e / (-at), tail_d = v_e * v_e / (2 * -at);
    out.kind = Phase2::stopped;
    out.t = r.x[0] + tail_t;
    out.x = r.x[1] + tail_d * std::cos(r.x[3]);
    out.y = r.x[2] + tail_d * std::sin(r.x[3]);
    // Samples between the end of the log phase and the stop (a window of ~1e-18 s).
    emit_until(out.t, [&](double t) { return to_state(span, r.x); });
    return out;
  }

  /// After a stop at (t0, x0, y0): rest if static friction holds, else slide down.
  void rest_or_slide(double t0, double x0, double y0) {
    const bool slides = std::tan(p_.phi) > p_.mu_s() && beta_ > gcos_ * mu_at(p_, o_, 0.0);
    res_.slides_after_stop = slides && res_.t_stop.has_value();
    if (!slides) {
      emit_until(1e300, [&](double t) { return State{t, x0, y0, 0, 0, 0, 0}; });
      return;
    }
    // From rest the friction acts up the fall line (acceleration() at v = 0), so the
    // disc leaves along -y; no switch speed: it accelerates.
    time_phase(t0, {x0, y0, 0.0, 0.0}, 0.0);
  }

  const Parameters& p_;
  const NumericOptions& o_;
  const std::vector<double>& times_;
  numerics::OdeOptions ode_;
  double gcos_, beta_, fn_, t_end_;
  std::size_t next_ = 0;
  NumericResult res_;
};

}  // namespace

std::pair<double, double> acceleration(const Parameters& p, const NumericOptions& o, double vx,
                                       double vy) {
  const double speed = std::hypot(vx, vy);
  const double af = p.g * std::cos(p.phi) * mu_at(p, o, speed);
  const double fn = o.model == Model::A ? p.normal_accel : 0.0;
  double ux = 0, uy = -1;  // at rest: the motion about to start is down the fall line
  if (speed > 0) {
    ux = vx / speed;
    uy = vy / speed;
  }
  // Friction -af u, normal part fn (-uy, ux) (left of the velocity), gravity -beta y-hat.
  return {-af * ux - fn * uy, -af * uy + fn * ux - p.beta()};
}

NumericResult simulate_from(const Parameters& p, const State& initial,
                            const std::vector<double>& times, const NumericOptions& options) {
  p.check();
  const std::string msg = options.validate();
  if (!msg.empty()) throw InputError(msg);
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (!std::isfinite(times[i]) || times[i] < 0 || (i > 0 && times[i] < times[i - 1]))
      throw InputError("sample times must be finite, >= 0 and non-decreasing");
  }
  for (double v : {initial.x, initial.y, initial.vx, initial.vy}) require_finite(v, "initial state");
  Runner runner(p, options, times);
  return runner.run(initial);
}

NumericResult simulate(const Parameters& p, const std::vector<double>& times,
                       const NumericOptions& options) {
  State initial;
  initial.vx = p.v0;
  return simulate_from(p, initial, times, options);
}

}  // namespace tribolab::incline
