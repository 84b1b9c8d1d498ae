#include "numerics/ode.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tribolab::numerics {
namespace {

using State2 = std::array<double, 2>;

// Harmonic oscillator x'' = -x with x(0) = 1, v(0) = 0: x = cos t, v = -sin t.
void oscillator(const State2& s, State2& d, double) {
  d[0] = s[1];
  d[1] = -s[0];
}

TEST(Ode, AdaptiveMatchesAnalyticSolution) {
  OdeOptions opt;
  opt.abs_tol = opt.rel_tol = 1e-12;
  const auto r = integrate(oscillator, State2{1.0, 0.0}, 0.0, 10.0, opt);
  ASSERT_EQ(r.status, OdeStatus::reached_end);
  EXPECT_DOUBLE_EQ(r.t, 10.0);
  // Global error grows ~ linearly in t over 1.6 periods; 1e-12 local tolerance -> < 1e-10.
  EXPECT_NEAR(r.x[0], std::cos(10.0), 1e-10);
  EXPECT_NEAR(r.x[1], -std::sin(10.0), 1e-10);
}

TEST(Ode, FixedStepConvergesAtFifthOrder) {
  // Error ratio for halved steps must approach 2^5 = 32 (Dormand–Prince order 5).
  auto err = [](int n) {
    const State2 x = integrate_fixed(oscillator, State2{1.0, 0.0}, 0.0, 2.0, n);
    return std::abs(x[0] - std::cos(2.0)) + std::abs(x[1] + std::sin(2.0));
  };
  const double e1 = err(10), e2 = err(20), e3 = err(40);
  const double order1 = std::log2(e1 / e2), order2 = std::log2(e2 / e3);
  // Asymptotic order 5; pre-asymptotic terms at these step sizes shift it by < 0.3.
  EXPECT_NEAR(order1, 5.0, 0.3) << "errors " << e1 << " " << e2;
  EXPECT_NEAR(order2, 5.0, 0.3) << "errors " << e2 << " " << e3;
}

TEST(Ode, TerminalEventLocatedOnDenseOutput) {
  // First zero of x = cos t is pi/2, falling.
  OdeOptions opt;
  opt.abs_tol = opt.rel_tol = 1e-12;
  std::vector<OdeEvent<State2>> events{{[](double, const State2& s) { return s[0]; }, -1, true}};
  const auto r = integrate(oscillator, State2{1.0, 0.0}, 0.0, 10.0, opt, events);
  ASSERT_EQ(r.status, OdeStatus::event);
  EXPECT_EQ(r.event_index, 0);
  // Dense output is 4th order; at tolerance 1e-12 the located time is good to ~1e-10.
  EXPECT_NEAR(r.t, M_PI / 2, 1e-10);
  EXPECT_NEAR(r.x[0], 0.0, 1e-10);
}

TEST(Ode, DirectionFilterSkipsWrongCrossings) {
  // Rising zeros of cos t are at 3pi/2 + 2k pi; the falling one at pi/2 must be skipped.
  OdeOptions opt;
  opt.abs_tol = opt.rel_tol = 1e-12;
  std::vector<OdeEvent<State2>> events{{[](double, const State2& s) { return s[0]; }, +1, true}};
  const auto r = integrate(oscillator, State2{1.0, 0.0}, 0.0, 10.0, opt, events);
  ASSERT_EQ(r.status, OdeStatus::event);
  EXPECT_NEAR(r.t, 1.5 * M_PI, 1e-10);
}

TEST(Ode, NonTerminalEventsAreAllRecorded) {
  OdeOptions opt;
  opt.abs_tol = opt.rel_tol = 1e-12;
  std::vector<OdeEvent<State2>> events{{[](double, const State2& s) { return s[0]; }, 0, false}};
  const auto r = integrate(oscillator, State2{1.0, 0.0}, 0.0, 10.0, opt, events);
  ASSERT_EQ(r.status, OdeStatus::reached_end);
  ASSERT_EQ(r.hits.size(), 3u);  // pi/2, 3pi/2, 5pi/2 < 10
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(r.hits[k].t, M_PI / 2 + k * M_PI, 1e-9);
}

TEST(Ode, ObserverCoversTheIntervalWithoutGaps) {
  OdeOptions opt;
  double covered_until = 0.0;
  bool contiguous = true;
  integrate(oscillator, State2{1.0, 0.0}, 0.0, 3.0, opt, {}, [&](const auto& view) {
    contiguous = contiguous && view.t0 == covered_until;
    covered_until = view.t1;
  });
  EXPECT_TRUE(contiguous);
  EXPECT_DOUBLE_EQ(covered_until, 3.0);
}

TEST(Ode, NonFiniteStateIsReported) {
  // x' = x^2 blows up at t = 1 for x(0) = 1.
  using S1 = std::array<double, 1>;
  OdeOptions opt;
  opt.max_steps = 100000;
  const auto r = integrate([](const S1& s, S1& d, double) { d[0] = s[0] * s[0]; }, S1{1.0}, 0.0,
                           2.0, opt);
  EXPECT_NE(r.status, OdeStatus::reached_end);
}

TEST(Roots, FindsBracketedRootToMachinePrecision) {
  const auto r = find_root([](double x) { return x * x - 2.0; }, 0.0, 2.0);
  ASSERT_TRUE(r.converged);
  EXPECT_NEAR(r.x, std::sqrt(2.0), 4e-16);
}

TEST(Roots, ReportsMissingBracket) {
  const auto r = find_root([](double x) { return x * x + 1.0; }, -1.0, 1.0);
  EXPECT_FALSE(r.converged);
  EXPECT_TRUE(std::isnan(r.x));
}

TEST(Roots, ScanFindsFirstSignChange) {
  const auto cell = first_sign_change([](double x) { return std::sin(x); }, 0.5, 10.0, 100);
  ASSERT_TRUE(cell.has_value());
  EXPECT_LE(cell->first, M_PI);
  EXPECT_GE(cell->second, M_PI);
}

}  // namespace
}  // namespace tribolab::numerics
