#include "bounce/phase_integrator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace tribolab::bounce {
namespace {

struct Oscillator {
  void operator()(const Vec<2>& x, Vec<2>& dx, double) const {
    dx[0] = x[1];
    dx[1] = -x[0];
  }
};

TEST(PhaseIntegrator, FifthOrderConvergence) {
  // Fixed steps on x'' = -x over [0, 1]: halving h divides the error by 2^5 = 32.
  Oscillator f;
  auto run = [&](int n) {
    Vec<2> x{1, 0}, k1, xn, k7;
    double t = 0;
    const double h = 1.0 / n;
    f(x, k1, t);
    for (int i = 0; i < n; ++i) {
      dopri_step<2>(f, t, x, k1, h, xn, k7, nullptr);
      x = xn;
      k1 = k7;
      t += h;
    }
    return std::abs(x[0] - std::cos(1.0));
  };
  const double r = run(10) / run(20);
  EXPECT_NEAR(std::log2(r), 5.0, 0.3);  // asymptotic order, within the pre-asymptotic spread
}

TEST(PhaseIntegrator, GuardLocatedAtTheExactCrossing) {
  // x = cos t crosses 0 at pi/2: the guard x[0] ends the phase there.
  Oscillator f;
  PhaseOptions o;
  o.abs_tol = o.rel_tol = 1e-12;
  auto guards = [](double, const Vec<2>& x, std::array<double, 1>& g) { g[0] = x[0]; };
  auto end = integrate_phase<2, 1>(f, guards, [](double, const Vec<2>&) {}, 0.0, Vec<2>{1, 0},
                                   10.0, 1e-3, o);
  ASSERT_EQ(end.status, PhaseStatus::guard);
  // Event time error = state error / |x'| = tolerance-level: 1e-10 is 100x the tolerance.
  EXPECT_NEAR(end.t, std::numbers::pi / 2, 1e-10);
  EXPECT_NEAR(end.x[1], -1.0, 1e-10);
}

// A guard that starts at zero, is positive on (0, 0.5) and negative after, with a first step
// of 2 that ends where it is negative: the phase must run to its zero at 0.5 (the dense output
// shows it positive inside the step, so the first step is retried shorter), not end at once.
TEST(PhaseIntegrator, GuardPositiveInsideALongFirstStepDoesNotEndThePhaseAtOnce) {
  auto f = [](const Vec<1>&, Vec<1>& dx, double) { dx[0] = 1; };  // x = t
  auto guards = [](double, const Vec<1>& x, std::array<double, 1>& g) { g[0] = x[0] * (0.5 - x[0]); };
  PhaseOptions o;
  o.abs_tol = o.rel_tol = 1e-10;
  auto end = integrate_phase<1, 1>(f, guards, [](double, const Vec<1>&) {}, 0.0, Vec<1>{0}, 10.0, 2.0, o);
  ASSERT_EQ(end.status, PhaseStatus::guard);
  EXPECT_FALSE(end.immediate);
  EXPECT_NEAR(end.t, 0.5, 1e-9);  // the event time tolerance is 1e-4 s x 1e-10
}

TEST(PhaseIntegrator, AdaptiveAccuracyFollowsTolerance) {
  Oscillator f;
  auto none = [](double, const Vec<2>&, std::array<double, 1>& g) { g[0] = 1; };
  for (double tol : {1e-6, 1e-9, 1e-12}) {
    PhaseOptions o;
    o.abs_tol = o.rel_tol = tol;
    auto end = integrate_phase<2, 1>(f, none, [](double, const Vec<2>&) {}, 0.0, Vec<2>{1, 0},
                                     10.0, 1e-3, o);
    ASSERT_EQ(end.status, PhaseStatus::reached_end);
    // Global error ~ (number of steps) x local tolerance; 100 x tol covers ~10 periods.
    EXPECT_NEAR(end.x[0], std::cos(10.0), 100 * tol) << tol;
  }
}

TEST(PhaseIntegrator, PhaseStartingOnItsBoundaryIsArmedLater) {
  // Guard g = x[0] starts at 0 and grows: not an event; the next crossing (t = pi) is.
  Oscillator f;
  PhaseOptions o;
  auto guards = [](double, const Vec<2>& x, std::array<double, 1>& g) { g[0] = x[0]; };
  auto end = integrate_phase<2, 1>(f, guards, [](double, const Vec<2>&) {}, 0.0, Vec<2>{0, 1},
                                   10.0, 1e-3, o);
  ASSERT_EQ(end.status, PhaseStatus::guard);
  EXPECT_NEAR(end.t, std::numbers::pi, 1e-8);
}

TEST(PhaseIntegrator, EventTimeBracketedToTheEventTolerance) {
  // x = cos t crosses 0 at pi/2. With a coarse explicit event tolerance (1e-4 s) the event
  // is the upper end of a bracket narrower than that: within 1e-4 s after pi/2 (plus the
  // ~1e-12 integration error), never before it, and the state is that of the event time
  // (x[0] = cos(t) <= 0, x[1] = -sin(t)) to the integration tolerance.
  Oscillator f;
  PhaseOptions o;
  o.abs_tol = o.rel_tol = 1e-12;
  o.event_time_tol = 1e-4;
  auto guards = [](double, const Vec<2>& x, std::array<double, 1>& g) { g[0] = x[0]; };
  auto end = integrate_phase<2, 1>(f, guards, [](double, const Vec<2>&) {}, 0.0, Vec<2>{1, 0},
                                   10.0, 1e-3, o);
  ASSERT_EQ(end.status, PhaseStatus::guard);
  EXPECT_GE(end.t, std::numbers::pi / 2 - 1e-10);
  EXPECT_LE(end.t, std::numbers::pi / 2 + 1e-4 + 1e-10);
  EXPECT_LE(end.x[0], 1e-10);
  EXPECT_NEAR(end.x[0], std::cos(end.t), 1e-10);
  EXPECT_NEAR(end.x[1], -std::sin(end.t), 1e-10);
  // The automatic value: 1e-4 s x abs_tol; negative or non-finite values are invalid.
  EXPECT_EQ(PhaseOptions{}.event_tol(), 1e-4 * PhaseOptions{}.abs_tol);
  o.event_time_tol = -1;
  EXPECT_FALSE(o.validate().empty());
}

// x'' = 2 from x = 0.999, x' = -2: x = (t - 1)^2 - 0.001 dips below 0 on
// (1 - 0.0316, 1 + 0.0316) and is positive at t = 0 and t = 3. Dormand–Prince integrates
// this quadratic exactly, so a first step of 3 s is accepted and jumps over the dip.
struct Parabola {
  void operator()(const Vec<2>& x, Vec<2>& dx, double) const {
    dx[0] = x[1];
    dx[1] = 2;
  }
};

TEST(PhaseIntegrator, DipInsideAStepIsFoundWithGuardRates) {
  Parabola f;
  PhaseOptions o;
  o.abs_tol = o.rel_tol = 1e-6;
  auto observer = [](double, const Vec<2>&) {};
  const double t_root = 1 - std::sqrt(0.001);
  auto with_rate = [](double, const Vec<2>& x, std::array<double, 1>& g, std::array<double, 1>& r) {
    g[0] = x[0];
    r[0] = x[1];
  };
  auto end = integrate_phase<2, 1>(f, with_rate, observer, 0.0, Vec<2>{0.999, -2}, 3.0, 3.0, o);
  ASSERT_EQ(end.status, PhaseStatus::guard);
  EXPECT_EQ(end.steps, 1u);  // the dip was inside the first (and only) step
  // The polynomial is integrated exactly: the event time to the event tolerance (1e-10 s)
  // plus rounding.
  EXPECT_NEAR(end.t, t_root, 1e-9);
  EXPECT_LE(end.x[0], 0);
  EXPECT_NEAR(end.x[1], 2 * (t_root - 1), 1e-8);  // x' = 2 (t - 1), |x''| = 2: 2 x 1e-9 s
  // Without rates the guard is only tested at step ends: the same step misses the dip.
  auto without_rate = [](double, const Vec<2>& x, std::array<double, 1>& g) { g[0] = x[0]; };
  auto missed = integrate_phase<2, 1>(f, without_rate, observer, 0.0, Vec<2>{0.999, -2}, 3.0, 3.0, o);
  EXPECT_EQ(missed.status, PhaseStatus::reached_end);
  // A dip that stays above zero ((t - 1)^2 + 0.001) is not an event.
  auto above = integrate_phase<2, 1>(f, with_rate, observer, 0.0, Vec<2>{1.001, -2}, 3.0, 3.0, o);
  EXPECT_EQ(above.status, PhaseStatus::reached_end);
  EXPECT_NEAR(above.x[0], 4.001, 1e-12);
}

TEST(PhaseIntegrator, DenseOutputIsFourthOrderInside) {
  // The continuous extension of one step of x' = x from 1: error at mid-step falls by
  // 2^5 = 32 per halving of h (local error O(h^5) of a 4th-order interpolant).
  auto f = [](const Vec<1>& x, Vec<1>& dx, double) { dx[0] = x[0]; };
  auto err = [&](double h) {
    Vec<1> x{1}, k1{1}, xn, k7;
    DopriStages<1> st;
    dopri_step<1>(f, 0.0, x, k1, h, xn, k7, nullptr, true, &st);
    DopriDense<1> d;
    d.build(x, xn, k1, st, k7, h);
    Vec<1> mid;
    d.at(0.5, mid);
    return std::abs(mid[0] - std::exp(0.5 * h));
  };
  EXPECT_NEAR(std::log2(err(0.1) / err(0.05)), 5.0, 0.3);  // asymptotic order, pre-asymptotic spread
}

TEST(PhaseIntegrator, EventOnDenseOutputMatchesExactSteps) {
  // x = cos t crosses 0 at pi/2: located on the dense output and refined by one exact step,
  // the event time and state are as accurate as the integration itself at every tolerance
  // (the error of a 4th-order interpolant alone would be ~ the tolerance, not below it).
  Oscillator f;
  auto guards = [](double, const Vec<2>& x, std::array<double, 1>& g) { g[0] = x[0]; };
  for (double tol : {1e-6, 1e-9, 1e-12}) {
    PhaseOptions o;
    o.abs_tol = o.rel_tol = tol;
    auto end = integrate_phase<2, 1>(f, guards, [](double, const Vec<2>&) {}, 0.0, Vec<2>{1, 0},
                                     10.0, 1e-3, o);
    ASSERT_EQ(end.status, PhaseStatus::guard);
    // Global error over ~1.6 rad: a few steps x tol (10 x tol); the time tolerance 1e-4 tol.
    EXPECT_NEAR(end.t, std::numbers::pi / 2, 10 * tol) << tol;
    EXPECT_NEAR(end.x[0], std::cos(end.t), 10 * tol) << tol;
    EXPECT_NEAR(end.x[1], -std::sin(end.t), 10 * tol) << tol;
  }
}

TEST(PhaseIntegrator, HermiteInteriorMinimum) {
  // p = (s - 1/2)^2 on [0, 1]: p0 = p1 = 1/4, slopes -1 and +1: minimum at s = 1/2.
  EXPECT_NEAR(detail::hermite_interior_minimum(0.25, 0.25, -1, 1), 0.5, 1e-15);
  // Monotone (slopes of one sign, no interior turning point): none.
  EXPECT_EQ(detail::hermite_interior_minimum(1, 0, -1, -1), -1);
  // A maximum inside only (slopes + then -): none.
  EXPECT_EQ(detail::hermite_interior_minimum(0, 0, 1, -1), -1);
}

TEST(PhaseIntegrator, NoStepGrowthRightAfterARejection) {
  // x' = nine narrow bumps (width 0.01, at t = 0.1, 0.2, ..., 0.9) on a flat rhs: between
  // bumps the step grows freely, and the long step that reaches the next bump is rejected,
  // so each bump brings rejections. Every trial step calls the rhs 6 times,
  // the last at its end t + h; a trial whose end is not the next accepted time was rejected.
  // After a rejection the step accepted next must not grow the step that follows it
  // (docs/theory.md#bounce-integrator): h_next <= h_accepted. Both are differences of times
  // of order 1 (rounding 1e-16 against steps >= 1e-6), hence the relative slack 1e-9.
  std::vector<double> calls, accepted;
  auto f = [&](const Vec<1>& x, Vec<1>& dx, double t) {
    calls.push_back(t);
    dx[0] = 0;
    for (int k = 1; k < 10; ++k) dx[0] += std::exp(-std::pow((t - 0.1 * k) / 1e-2, 2)) / 1e-2;
  };
  auto none = [](double, const Vec<1>&, std::array<double, 1>& g) { g[0] = 1; };
  PhaseOptions o;
  o.abs_tol = o.rel_tol = 1e-6;
  auto end = integrate_phase<1, 1>(f, none, [&](double t, const Vec<1>&) { accepted.push_back(t); }, 0.0,
                                   Vec<1>{0}, 1.0, 1e-4, o);
  ASSERT_EQ(end.status, PhaseStatus::reached_end);
  ASSERT_EQ((calls.size() - 1) % 6, 0u);  // the first call, then 6 per trial step
  std::size_t next = 1, rejections = 0, checked = 0;
  double t = 0, h_after_rejection = 0;
  bool rejected = false;
  for (std::size_t b = 6; b < calls.size(); b += 6) {
    const double h = calls[b] - t;
    if (h_after_rejection > 0) {
      EXPECT_LE(h, h_after_rejection * (1 + 1e-9)) << "trial step at t = " << t;
      ++checked;
      h_after_rejection = 0;
    }
    if (next < accepted.size() && calls[b] == accepted[next]) {
      if (rejected) h_after_rejection = h;
      rejected = false;
      t = accepted[next++];
    } else {
      rejected = true;
      ++rejections;
    }
  }
  EXPECT_EQ(next, accepted.size()) << calls.size();
  EXPECT_GT(rejections, 5u);  // the problem does exercise the rule
  EXPECT_GT(checked, 5u);
}

TEST(PhaseIntegrator, StepGrowsAtMostByTheGrowthLimit) {
  // x'' = -x from a first step 1e-7 s, ~1e4 times shorter than the tolerance allows: the
  // error controller asks for 5x per step; the integrator grows the step by at most 1.5x
  // from one accepted step to the next (kMaxStepGrowth, docs/theory.md#bounce-integrator,
  // "Step growth"), so the step needs ~23 steps to reach its error-limited size. Steps are
  // differences of times of order 1: relative slack 1e-9 for rounding.
  Oscillator f;
  std::vector<double> accepted;
  auto none = [](double, const Vec<2>&, std::array<double, 1>& g) { g[0] = 1; };
  PhaseOptions o;
  o.abs_tol = o.rel_tol = 1e-6;
  auto end = integrate_phase<2, 1>(f, none, [&](double t, const Vec<2>&) { accepted.push_back(t); }, 0.0,
                                   Vec<2>{1, 0}, 10.0, 1e-7, o);
  ASSERT_EQ(end.status, PhaseStatus::reached_end);
  ASSERT_GT(accepted.size(), 20u);
  double largest_ratio = 0;
  for (std::size_t i = 2; i < accepted.size(); ++i) {
    const double h_prev = accepted[i - 1] - accepted[i - 2], h = accepted[i] - accepted[i - 1];
    EXPECT_LE(h, 1.5 * h_prev * (1 + 1e-9)) << "step " << i;
    largest_ratio = std::max(largest_ratio, h / h_prev);
  }
  EXPECT_GT(largest_ratio, 1.4);  // the limit, not the error, bounded the growth
  EXPECT_NEAR(end.x[0], std::cos(10.0), 100 * o.abs_tol);  // as AdaptiveAccuracyFollowsTolerance
}

}  // namespace
}  // namespace tribolab::bounce
