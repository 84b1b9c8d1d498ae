#include "incline/closed_form.hpp"

#include "numerics/error.hpp"
#include "numerics/roots.hpp"

#include <boost/math/quadrature/gauss.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace tribolab::incline {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// D(k, s) = E(2+2k, s) - E(2-2k, s) = -2 int_0^s e^{-2t} sinh(2kt) dt, the bracket of
/// eq 六. Each branch is chosen where it has no cancellation (docs/theory.md#incline-seed-000).
double y_bracket(double k, double s) {
  if (s <= 1 && k * s <= 1) {
    // Entire integrand on an interval of length <= 1 with |2kt| <= 2: 20-point
    // Gauss-Legendre is exact to rounding.
    auto f = [k](double t) { return std::exp(-2 * t) * std::sinh(2 * k * t); };
    return -2 * boost::math::quadrature::gauss<double, 20>::integrate(f, 0.0, s);
  }
  if (k < 0.5) {
    // [e^{-2s} (sinh 2ks + k cosh 2ks) - k] / (1 - k^2): for s > 1 and k < 1/2 the
    // bracket is at least k (1 - 3 e^{-2}) in magnitude, so no cancellation.
    const double w = 2 * k * s;
    return (std::exp(-2 * s) * (std::sinh(w) + k * std::cosh(w)) - k) / (1 - k * k);
  }
  return one_minus_exp_over(2 + 2 * k, s) - one_minus_exp_over(2 - 2 * k, s);
}

}  // namespace

double one_minus_exp_over(double c, double s) {
  if (c == 0) return s;
  return -std::expm1(-c * s) / c;
}

ClosedForm::ClosedForm(const Parameters& p) : p_(p) {
  p_.check();
  alpha_ = p_.alpha();
  beta_ = p_.beta();
  k_ = p_.k();
  t_stop_ = kInf;
  if (p_.v0 == 0) {
    t_stop_ = p_.stays_at_rest() ? 0.0 : kInf;
  } else if (p_.mu > 0 && k_ < 1) {
    t_stop_ = p_.v0 / (alpha_ * (1 - k_) * (1 + k_));  // eq 七 (factored: exact near k = 1)
  }
}

double ClosedForm::time_at(double s) const {
  return p_.v0 / (2 * alpha_) * (one_minus_exp_over(1 + k_, s) + one_minus_exp_over(1 - k_, s));
}

State ClosedForm::at_log_speed_ratio(double s) const {
  const double v0 = p_.v0;
  State st;
  st.t = time_at(s);
  st.vx = v0 * std::exp(-s);
  // eq 五: vy = vx sinh(k ln u); for k s > 20 the two powers are used separately, which
  // avoids 0 * inf (k < 1) and overflow of sinh before the product (k > 1).
  st.vy = k_ * s <= 20 ? -v0 * std::exp(-s) * std::sinh(k_ * s)
                       : 0.5 * v0 * (std::exp(-(1 + k_) * s) - std::exp((k_ - 1) * s));
  st.x = v0 * v0 / (2 * alpha_) *
         (one_minus_exp_over(2 + k_, s) + one_minus_exp_over(2 - k_, s));  // eq 三
  st.y = v0 * v0 / (4 * alpha_) * y_bracket(k_, s);                       // eq 六
  st.ax = -alpha_ / std::cosh(k_ * s);                                     // eq 一
  st.ay = alpha_ * std::tanh(k_ * s) - beta_;                              // eq 四
  return st;
}

double ClosedForm::log_speed_ratio_at(double t) const {
  TRIBOLAB_ASSERT(p_.mu > 0 && p_.v0 > 0 && t >= 0 && t < t_stop_,
                  "t = " + std::to_string(t) + ", t_stop = " + std::to_string(t_stop_));
  if (t == 0) return 0.0;
  const double v0 = p_.v0, a = alpha_, k = k_;
  if (k < 1) {
    const double T = t_stop_;
    if (t <= 0.5 * T) {
      // t(s) >= T - T e^{-(1-k)s}, so the root lies below ln(T/(T-t))/(1-k).
      // The bound is attained at k = 0; widen it so that the bracket is strict.
      const double s_hi = -1.01 * std::log1p(-t / T) / (1 - k) + 1e-300;
      const auto r = numerics::find_root([&](double s) { return time_at(s) - t; }, 0.0, s_hi);
      if (!r.converged) throw SolverError("the closed form cannot be evaluated at t = " + std::to_string(t) + " s for these parameters");
      return r.x;
    }
    // Near the stop: match the remaining time R = T - t in logarithms, where
    // ln R(s) = ln(v0/(2a)) - (1-k)s + ln(1/(1-k) + e^{-2ks}/(1+k)) has no cancellation.
    const double R = T - t;
    const double c0 = std::log(v0 / (2 * a));
    auto log_rem = [&](double s) {
      return c0 - (1 - k) * s + std::log(1 / (1 - k) + std::exp(-2 * k * s) / (1 + k)) - std::log(R);
    };
    // R(s) >= v0/(2a(1-k)) e^{-(1-k)s} gives a lower bound on the root, R(s) <= T e^{-(1-k)s}
    // an upper one (widened by 1% so that the bracket is strict where a bound is attained,
    // as at k = 0).
    const double s_lo = std::max(0.0, 0.99 * std::log(v0 / (2 * a * (1 - k) * R)) / (1 - k));
    const double s_hi = 1.01 * std::log(T / R) / (1 - k) + 1e-300;
    const auto r = numerics::find_root(log_rem, s_lo, std::max(s_lo, s_hi));
    if (!r.converged) throw SolverError("the closed form cannot be evaluated at t = " + std::to_string(t) + " s for these parameters");
    return r.x;
  }
  // k >= 1: E(1+k, s) <= s <= E(1-k, s), so (v0/(2a)) E(1-k, s) <= t(s) <= (v0/a) E(1-k, s),
  // and E(1-k, s) = c brackets the root between c = a t / v0 and c = 2 a t / v0, where
  // s = log1p((k-1) c)/(k-1) (= c at k = 1). Widened by 1% so that the bracket is strict.
  auto s_for = [k](double c) { return k == 1 ? c : std::log1p((k - 1) * c) / (k - 1); };
  const double lo = 0.99 * s_for(a * t / v0), hi = 1.01 * s_for(2 * a * t / v0) + 1e-300;
  auto f = [&](double s) {
    const double v = time_at(s) - t;
    return std::isfinite(v) ? v : std::numeric_limits<double>::max();
  };
  const auto r = numerics::find_root(f, lo, hi);
  if (!r.converged) {
    throw SolverError("the closed form cannot be evaluated at t = " + std::to_string(t) +
                      " s for these parameters (k = " + std::to_string(k) + ")");
  }
  return r.x;
}

State ClosedForm::rest_or_slide(double t, double t0, double x0, double y0) const {
  State st;
  st.t = t;
  st.x = x0;
  st.y = y0;
  if (p_.stays_at_rest()) return st;
  // Slides straight down the fall line with kinetic friction (SPEC section 2).
  const double a = beta_ - alpha_;
  const double dt = t - t0;
  st.y = y0 - 0.5 * a * dt * dt;
  st.vy = -a * dt;
  st.ay = -a;
  return st;
}

State ClosedForm::at(double t) const {
  if (!(t >= 0) || !std::isfinite(t))
    throw InputError("time must be finite and >= 0, got " + std::to_string(t));
  if (p_.v0 == 0) return rest_or_slide(t, 0, 0, 0);
  if (p_.mu == 0) {  // smooth incline: projectile motion in the plane (seed 000, 肆-一-(三))
    State st;
    st.t = t;
    st.x = p_.v0 * t;
    st.y = -0.5 * beta_ * t * t;
    st.vx = p_.v0;
    st.vy = -beta_ * t;
    st.ay = -beta_;
    return st;
  }
  if (t >= t_stop_) {
    const double x_stop = 2 * p_.v0 * p_.v0 / (alpha_ * (2 - k_) * (2 + k_));         // eq 八
    const double y_stop = -k_ * p_.v0 * p_.v0 / (4 * alpha_ * (1 - k_) * (1 + k_)) + 0.0;  // eq 九
    return rest_or_slide(t, t_stop_, x_stop, y_stop);
  }
  State st = at_log_speed_ratio(log_speed_ratio_at(t));
  st.t = t;
  return st;
}

std::vector<State> ClosedForm::trajectory(const std::vector<double>& times) const {
  std::vector<State> out;
  out.reserve(times.size());
  for (double t : times) out.push_back(at(t));
  return out;
}

Prediction ClosedForm::predict() const {
  Prediction pr;
  const double v0 = p_.v0, a = alpha_, b = beta_, k = k_;
  pr.k = k;
  pr.stays_at_rest = p_.stays_at_rest();
  if (v0 == 0) {
    const State s0 = rest_or_slide(0, 0, 0, 0);
    pr.regime = pr.stays_at_rest ? Regime::stops : Regime::accelerates;
    if (pr.stays_at_rest) {
      pr.t_stop = 0.0;
      pr.x_stop = 0.0;
      pr.y_stop = 0.0;
    }
    pr.x_limit = 0.0;
    pr.a_x0 = pr.a_x_final = s0.ax;
    pr.a_y0 = pr.a_y_final = s0.ay;
    return pr;
  }
  pr.regime = p_.regime();
  if (p_.mu == 0) {
    pr.a_x0 = pr.a_x_final = 0;
    pr.a_y0 = pr.a_y_final = -b;
    if (pr.regime == Regime::terminal_speed) pr.v_terminal = v0;
    return pr;
  }
  pr.a_x0 = -a;
  pr.a_y0 = -b;
  // Limits as u -> 0 (stop or t -> infinity): cosh(ks) -> inf, tanh(ks) -> 1 when k > 0.
  pr.a_x_final = k > 0 ? 0.0 : -a;
  pr.a_y_final = k > 0 ? a - b : 0.0;
  if (k < 1) {
    pr.t_stop = t_stop_;                                 // eq 七
    pr.x_stop = 2 * v0 * v0 / (a * (2 - k) * (2 + k));         // eq 八
    pr.y_stop = -k * v0 * v0 / (4 * a * (1 - k) * (1 + k)) + 0.0;  // eq 九 (+0: no -0 at k = 0)
  }
  if (k == 1) pr.v_terminal = 0.5 * v0;  // vy -> -v0/2, vx -> 0
  if (k < 2) pr.x_limit = 2 * v0 * v0 / (a * (2 - k) * (2 + k));
  return pr;
}

}  // namespace tribolab::incline
