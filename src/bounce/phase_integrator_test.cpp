#include "bounce/phase_integrator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

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

}  // namespace
}  // namespace tribolab::bounce
