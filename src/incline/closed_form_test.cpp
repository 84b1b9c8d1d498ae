// Closed-form model B: the seed's hyperbolic formulas, the limits k -> 1 and k -> 2, the
// special branches and the inversion of t(s). Tolerances are stated next to each check.
#include "incline/closed_form.hpp"

#include "numerics/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tribolab::incline {
namespace {

Parameters make(double mu, double phi_deg, double v0) {
  Parameters p;
  p.mu = mu;
  p.phi = deg_to_rad(phi_deg);
  p.v0 = v0;
  return p;
}

/// mu giving k = tan(phi)/mu exactly `k` for k = 1 and 2 (division by 1 or 2 is exact).
Parameters with_k(double k, double phi_deg = 20.0, double v0 = 2.0) {
  Parameters p = make(0, phi_deg, v0);
  p.mu = std::tan(p.phi) / k;
  return p;
}

double rel(double a, double b, double scale) { return std::abs(a - b) / scale; }

TEST(ClosedForm, AgreesWithTheSeedHyperbolicFormulas) {
  // Seed 000 eqs 二, 三, 五, 六 as printed (with the correct sign of (A2), see theory.md),
  // evaluated where they are well conditioned (k = 0.5, u in [0.05, 1]).
  const Parameters p = make(0.634, 20.96, 2.62);
  const ClosedForm cf(p);
  const double a = p.alpha(), k = p.k(), v0 = p.v0;
  for (double u : {1.0, 0.9, 0.5, 0.2, 0.05}) {
    const double L = k * std::log(u), vx = v0 * u;
    const double t = (vx * (k * std::sinh(L) - std::cosh(L)) + v0) / ((a * a - p.beta() * p.beta()) / a);
    const double x = -(vx * vx * (k * std::sinh(L) - 2 * std::cosh(L)) + 2 * v0 * v0) / (a * (k * k - 4));
    const double vy = vx * std::sinh(L);
    const double y = -(vx * vx * (k * std::cosh(2 * L) - std::sinh(2 * L)) - v0 * v0 * k) / (4 * a * (k * k - 1));
    const State st = cf.at_log_speed_ratio(-std::log(u));
    // Both forms are exact; the hyperbolic ones lose a few digits to cancellation at u ~ 1.
    EXPECT_NEAR(st.t, t, 1e-13) << "u = " << u;
    EXPECT_NEAR(st.x, x, 1e-13) << "u = " << u;
    EXPECT_NEAR(st.vy, vy, 1e-13) << "u = " << u;
    EXPECT_NEAR(st.y, y, 1e-13) << "u = " << u;
    EXPECT_NEAR(st.ax, -a / std::cosh(L), 1e-13);
    EXPECT_NEAR(st.ay, -a * std::tanh(L) - p.beta(), 1e-13);
  }
}

TEST(ClosedForm, StopValuesAreTheLimitsOfTheTrajectory) {
  for (double k : {0.05, 0.3, 0.7, 0.95}) {
    const Parameters p = with_k(k, 15.0, 2.5);
    const ClosedForm cf(p);
    const Prediction pr = cf.predict();
    ASSERT_EQ(pr.regime, Regime::stops);
    // s = 40 / (1 - k): u^(1-k) = e^-40, so the remaining terms are below 1e-17; also
    // k s >= 20 so that tanh(k s) = 1 - 2e-17 in a_y.
    const State st = cf.at_log_speed_ratio(std::max(40 / (1 - k), 20 / k));
    EXPECT_NEAR(st.t / *pr.t_stop, 1, 1e-14) << k;
    EXPECT_NEAR(st.x / *pr.x_stop, 1, 1e-14) << k;
    EXPECT_NEAR(st.y / *pr.y_stop, 1, 1e-14) << k;
    EXPECT_NEAR(st.ay, p.alpha() - p.beta(), 1e-12 * p.g) << k;
    EXPECT_DOUBLE_EQ(*pr.x_limit, *pr.x_stop);
    // After the stop the disc is at rest at the stop point (k < 1: friction holds it).
    const State after = cf.at(*pr.t_stop * 1.5);
    EXPECT_EQ(after.x, *pr.x_stop);
    EXPECT_EQ(after.y, *pr.y_stop);
    EXPECT_EQ(after.vx, 0.0);
    EXPECT_EQ(after.vy, 0.0);
  }
}

TEST(ClosedForm, InversionOfTimeIsExactUpToTheStop) {
  for (double k : {0.0, 0.2, 0.9, 0.999999, 1.0, 1.7, 2.0, 6.0}) {
    const ClosedForm cf(k == 0 ? make(0.5, 0.0, 2.0) : with_k(k));
    const double T = cf.t_stop();
    std::vector<double> ts = {1e-12, 1e-3, 0.1, 0.7, 2.0};
    if (std::isfinite(T)) ts = {1e-12 * T, 0.3 * T, 0.5 * T, 0.9 * T, T * (1 - 1e-9), T * (1 - 1e-15)};
    for (double t : ts) {
      const double s = cf.log_speed_ratio_at(t);
      ASSERT_TRUE(std::isfinite(s)) << k << " " << t;
      // The root is found to the last bits of s; t(s) is then t to a few ulps of max(t, T-t).
      EXPECT_NEAR(cf.time_at(s), t, 1e-14 * std::max(t, 1.0)) << "k = " << k << ", t = " << t;
    }
  }
}

TEST(ClosedForm, DerivativesAreConsistent) {
  // Central differences with h = 1e-5 s have truncation error h^2 |f'''| / 6 < 1e-9 here.
  for (double k : {0.4, 1.0, 1.5, 2.0, 3.0}) {
    const ClosedForm cf(with_k(k));
    for (double t : {0.05, 0.2, 0.4}) {
      if (t >= 0.9 * cf.t_stop()) continue;
      const double h = 1e-5;
      const State m = cf.at(t - h), c = cf.at(t), pl = cf.at(t + h);
      EXPECT_NEAR((pl.x - m.x) / (2 * h), c.vx, 1e-8) << k << " " << t;
      EXPECT_NEAR((pl.y - m.y) / (2 * h), c.vy, 1e-8) << k << " " << t;
      EXPECT_NEAR((pl.vx - m.vx) / (2 * h), c.ax, 1e-7) << k << " " << t;
      EXPECT_NEAR((pl.vy - m.vy) / (2 * h), c.ay, 1e-7) << k << " " << t;
      // Friction magnitude alpha opposite the velocity (model B).
      const double fx = c.ax, fy = c.ay + cf.parameters().beta();
      EXPECT_NEAR(std::hypot(fx, fy), cf.parameters().alpha(), 1e-12);
      EXPECT_NEAR(fx * c.vy - fy * c.vx, 0.0, 1e-12);
    }
  }
}

/// Relative change of the state at fixed s when k moves by +-delta around k0.
void expect_continuous_in_k(double k0, double delta = 1e-10) {
  const double phi = deg_to_rad(20.0);
  for (double s : {0.01, 0.5, 3.0, 20.0}) {
    Parameters p = with_k(k0);
    const State mid = ClosedForm(p).at_log_speed_ratio(s);
    for (double sign : {-1.0, 1.0}) {
      p.mu = std::tan(phi) / (k0 + sign * delta);
      const State side = ClosedForm(p).at_log_speed_ratio(s);
      // The exact change is O(delta * s^2 * scale) (<= 4e-8 relative at s = 20 for
      // delta = 1e-10); an unguarded 0/0 would give O(eps / delta) or NaN. The floor 2e-15
      // covers rounding of the state itself.
      const double tol = 10 * delta * (1 + s * s) + 2e-15;
      const double xs = std::max(std::abs(mid.x), 1e-300), ts = std::max(mid.t, 1e-300);
      EXPECT_LT(rel(side.t, mid.t, ts), tol) << "k0 = " << k0 << " s = " << s << " sign " << sign;
      EXPECT_LT(rel(side.x, mid.x, xs), tol) << "k0 = " << k0 << " s = " << s << " sign " << sign;
      EXPECT_LT(rel(side.y, mid.y, std::abs(mid.y)), tol) << "k0 = " << k0 << " s = " << s;
      EXPECT_LT(rel(side.vy, mid.vy, std::abs(mid.vy)), tol) << "k0 = " << k0 << " s = " << s;
    }
  }
}

TEST(ClosedForm, ContinuousAcrossKEqualsOne) {
  expect_continuous_in_k(1.0);
  expect_continuous_in_k(1.0, 1e-13);  // ~1e-12 relative continuity (s <= 3: 1e-11 at s = 3)
}
TEST(ClosedForm, ContinuousAcrossKEqualsTwo) {
  expect_continuous_in_k(2.0);
  expect_continuous_in_k(2.0, 1e-13);
}

TEST(ClosedForm, KWithinRoundingOfOneIsTheBoundary) {
  Parameters p = make(1.0, 45.0, 2.0);  // tan(45 deg) = 1 - 1.1e-16 in double
  EXPECT_EQ(p.k(), 1.0);
  EXPECT_EQ(ClosedForm(p).predict().regime, Regime::terminal_speed);
  p.mu = 1.0 - 1e-9;
  EXPECT_EQ(ClosedForm(p).predict().regime, Regime::accelerates);
}

TEST(ClosedForm, KEqualsOneTendsToHalfTheLaunchSpeed) {
  const ClosedForm cf(with_k(1.0, 20.0, 3.0));
  const Prediction pr = cf.predict();
  EXPECT_EQ(pr.regime, Regime::terminal_speed);
  EXPECT_DOUBLE_EQ(*pr.v_terminal, 1.5);
  EXPECT_FALSE(pr.t_stop.has_value());
  // At k = 1, vy = (v0/2)(u^2 - 1): |v| - v0/2 = O(u^2); at t = 200 s, u ~ e^{-2at/v0}.
  const State st = cf.at(200.0);
  EXPECT_NEAR(std::hypot(st.vx, st.vy), 1.5, 1e-12);
  EXPECT_NEAR(st.ay, 0.0, 1e-12);
}

TEST(ClosedForm, LateralLimitIsFiniteOnlyBelowKEqualsTwo) {
  for (double k : {1.2, 1.9}) {
    const ClosedForm cf(with_k(k));
    const Prediction pr = cf.predict();
    ASSERT_TRUE(pr.x_limit.has_value());
    // x_limit - x(s) = v0^2/(2a) u^(2-k)/(2-k) + ...; s = 40/(2-k) leaves < 1e-16.
    EXPECT_NEAR(cf.at_log_speed_ratio(40 / (2 - k)).x / *pr.x_limit, 1, 1e-14) << k;
    EXPECT_EQ(pr.regime, Regime::accelerates);
  }
  for (double k : {2.0, 2.5}) {
    const ClosedForm cf(with_k(k));
    EXPECT_FALSE(cf.predict().x_limit.has_value());
    // At k = 2, x grows like v0^2/(2a) ln(1/u): unbounded, slowly.
    EXPECT_GT(cf.at_log_speed_ratio(200).x, cf.at_log_speed_ratio(100).x * 1.5);
  }
}

TEST(ClosedForm, SmoothInclineIsProjectileMotion) {
  const ClosedForm cf(make(0.0, 23.2, 2.3));
  const Prediction pr = cf.predict();
  EXPECT_EQ(pr.regime, Regime::accelerates);
  EXPECT_TRUE(std::isinf(pr.k));
  const double b = 9.8 * std::sin(deg_to_rad(23.2));
  const State st = cf.at(0.5);
  EXPECT_DOUBLE_EQ(st.x, 1.15);
  EXPECT_DOUBLE_EQ(st.y, -0.125 * b);
  // mu -> 0+ approaches it: the friction work over 0.5 s changes x by ~ alpha t^2/2 ~ 2e-9.
  const State near = ClosedForm(make(1e-9, 23.2, 2.3)).at(0.5);
  EXPECT_NEAR(near.x, st.x, 1e-8);
  EXPECT_NEAR(near.y, st.y, 1e-8);
}

TEST(ClosedForm, FlatPlaneIsStraightDeceleration) {
  const Parameters p = make(0.4, 0.0, 2.0);
  const ClosedForm cf(p);
  const double a = 9.8 * 0.4;
  const Prediction pr = cf.predict();
  EXPECT_DOUBLE_EQ(*pr.t_stop, 2.0 / a);
  EXPECT_DOUBLE_EQ(*pr.x_stop, 2.0 / a);  // v0^2 / (2a)
  EXPECT_EQ(*pr.y_stop, 0.0);
  EXPECT_EQ(pr.a_x_final, -a);
  for (double t : {0.1, 0.3, 0.5}) {
    const State st = cf.at(t);
    // The inversion is exact to a few ulps.
    EXPECT_NEAR(st.vx, 2.0 - a * t, 1e-14);
    EXPECT_NEAR(st.x, 2.0 * t - 0.5 * a * t * t, 1e-14);
    EXPECT_EQ(st.y, 0.0);
    EXPECT_EQ(st.vy, 0.0);
  }
}

TEST(ClosedForm, StartingAtRestStaysOrSlides) {
  Parameters p = make(0.5, 20.0, 0.0);  // tan 20 deg = 0.364 < 0.5
  EXPECT_TRUE(ClosedForm(p).predict().stays_at_rest);
  EXPECT_EQ(ClosedForm(p).at(1.0).y, 0.0);
  p.phi = deg_to_rad(30.0);  // tan 30 = 0.577 > 0.5: slides with a = g sin - mu g cos
  const State st = ClosedForm(p).at(1.0);
  const double a = p.beta() - p.alpha();
  EXPECT_NEAR(st.y, -0.5 * a, 1e-15);
  EXPECT_EQ(st.x, 0.0);
  EXPECT_EQ(ClosedForm(p).predict().regime, Regime::accelerates);
  p.mu_static = 0.6;  // static friction holds it
  EXPECT_EQ(ClosedForm(p).at(1.0).y, 0.0);
}

TEST(ClosedForm, NeverProducesNaN) {
  for (double k : {0.0, 1e-12, 0.3, 1 - 1e-12, 1.0, 1 + 1e-12, 1.5, 2 - 1e-12, 2.0, 2 + 1e-12, 5.0, 60.0}) {
    // k = 1e-12 from a nearly flat incline (mu = 0.5): tan(30 deg)/k would be mu = 6e11,
    // outside the physical range of mu (docs/cli.md#physical-ranges) that validate() enforces.
    Parameters p = k == 0 ? make(0.5, 0.0, 1.0) : with_k(k, 30.0, 1.0);
    if (k > 0 && k < 1e-6) p.phi = std::atan(0.5 * k), p.mu = 0.5;
    const ClosedForm cf(p);
    const Prediction pr = cf.predict();
    std::vector<double> ts = {0, 1e-300, 1e-9, 0.01, 1, 10, 100};
    if (std::isfinite(cf.t_stop())) {
      for (double f : {1 - 1e-16, 1 - 1e-10, 0.999, 1.0, 2.0}) ts.push_back(f * cf.t_stop());
    }
    for (double t : ts) {
      const State st = cf.at(t);
      for (double v : {st.x, st.y, st.vx, st.vy, st.ax, st.ay}) {
        EXPECT_FALSE(std::isnan(v)) << "k = " << k << ", t = " << t;
      }
    }
    EXPECT_FALSE(std::isnan(pr.a_y_final)) << k;
  }
}

TEST(ClosedForm, NearlyFrictionlessIsTheSmoothIncline) {
  // mu = 1e-300: k = 6e299, t(s) overflows for s > 1e-297; the bracket of the inversion is
  // explicit, so the state is the projectile's to rounding.
  const ClosedForm cf(make(1e-300, 30.0, 1.0));
  const ClosedForm smooth(make(0.0, 30.0, 1.0));
  for (double t : {0.1, 1.0, 10.0}) {
    const State a = cf.at(t), b = smooth.at(t);
    EXPECT_NEAR(a.x, b.x, 1e-12 * std::abs(b.x)) << t;
    EXPECT_NEAR(a.y, b.y, 1e-12 * std::abs(b.y)) << t;
    EXPECT_NEAR(a.vy, b.vy, 1e-12 * std::abs(b.vy)) << t;
  }
}

TEST(ClosedForm, StopScalesWithLaunchSpeed) {
  // Seed 000 eqs 七-十: t_stop ~ v0, (x_stop, y_stop) ~ v0^2, y_stop/x_stop independent of v0.
  const Prediction a = ClosedForm(make(0.585, 10.37, 1.0)).predict();
  const Prediction b = ClosedForm(make(0.585, 10.37, 3.0)).predict();
  EXPECT_NEAR(*b.t_stop / *a.t_stop, 3.0, 1e-14);
  EXPECT_NEAR(*b.x_stop / *a.x_stop, 9.0, 1e-13);
  EXPECT_NEAR(*b.y_stop / *a.y_stop, 9.0, 1e-13);
  EXPECT_NEAR(*b.y_stop / *b.x_stop, *a.y_stop / *a.x_stop, 1e-15);
}

TEST(ClosedForm, RejectsInvalidParameters) {
  EXPECT_THROW(ClosedForm(make(-0.1, 20, 1)), InputError);
  EXPECT_THROW(ClosedForm(make(0.5, 90, 1)), InputError);
  EXPECT_THROW(ClosedForm(make(0.5, 20, -1)), InputError);
  EXPECT_THROW(ClosedForm(make(0.5, 20, 1)).at(-1), InputError);
}

}  // namespace
}  // namespace tribolab::incline
