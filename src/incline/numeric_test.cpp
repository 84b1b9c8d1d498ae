// Numerical models A and B against the closed form, the stop location, invariants and
// independent 1D solutions. Tolerances are justified next to each check.
#include "incline/numeric.hpp"

#include "incline/closed_form.hpp"
#include "numerics/error.hpp"
#include "numerics/ode.hpp"
#include "numerics/roots.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace tribolab::incline {
namespace {

Parameters params_k(double k, double phi_deg = 15.0, double v0 = 2.5) {
  Parameters p;
  p.phi = deg_to_rad(phi_deg);
  p.mu = std::tan(p.phi) / k;
  p.v0 = v0;
  return p;
}

std::vector<double> grid(double t_end, int n) {
  std::vector<double> t(n + 1);
  for (int i = 0; i <= n; ++i) t[i] = t_end * i / n;
  return t;
}

/// Numerical vs closed-form trajectory: positions relative to max(|x|, |y|) over the path,
/// velocities to v0, accelerations to alpha + beta while |v| > 1e-3 v0 (below, the direction
/// of v is set by components of size |v| that carry the integrator's absolute error).
void expect_matches_closed_form(const Parameters& p, const NumericOptions& o, double t_end,
                                double tol) {
  const ClosedForm cf(p);
  const auto times = grid(t_end, 400);
  const NumericResult r = simulate(p, times, o);
  ASSERT_EQ(r.status, NumericStatus::reached_end) << r.message;
  ASSERT_EQ(r.samples.size(), times.size());
  double pos_scale = 0;
  for (double t : times) {
    const State c = cf.at(t);
    pos_scale = std::max({pos_scale, std::abs(c.x), std::abs(c.y)});
  }
  const double acc_scale = p.alpha() + p.beta();
  for (std::size_t i = 0; i < times.size(); ++i) {
    const State c = cf.at(times[i]);
    const State& n = r.samples[i];
    EXPECT_EQ(n.t, times[i]);
    EXPECT_NEAR(n.x, c.x, tol * pos_scale) << "t = " << times[i];
    EXPECT_NEAR(n.y, c.y, tol * pos_scale) << "t = " << times[i];
    EXPECT_NEAR(n.vx, c.vx, tol * p.v0) << "t = " << times[i];
    EXPECT_NEAR(n.vy, c.vy, tol * p.v0) << "t = " << times[i];
    if (std::hypot(c.vx, c.vy) > 1e-3 * p.v0) {
      EXPECT_NEAR(n.ax, c.ax, 1e3 * tol * acc_scale) << "t = " << times[i];
      EXPECT_NEAR(n.ay, c.ay, 1e3 * tol * acc_scale) << "t = " << times[i];
    }
  }
}

TEST(Numeric, MatchesClosedFormWhenItStops) {
  for (double k : {0.1, 0.5, 0.8}) {
    const Parameters p = params_k(k);
    expect_matches_closed_form(p, {}, 1.3 * ClosedForm(p).t_stop(), 1e-9);
  }
}

TEST(Numeric, MatchesClosedFormWhenItNeverStops) {
  for (double k : {1.0, 1.5, 2.0, 3.0}) expect_matches_closed_form(params_k(k), {}, 2.0, 1e-9);
}

TEST(Numeric, LocatesTheStopToOnePartInABillion) {
  for (double k : {0.0, 0.05, 0.3, 0.6, 0.9, 0.97}) {
    Parameters p = params_k(k == 0 ? 1 : k);
    if (k == 0) p.phi = 0;
    const Prediction pr = ClosedForm(p).predict();
    NumericOptions o;
    o.t_max = 2 * *pr.t_stop;
    const NumericResult r = simulate(p, {}, o);
    ASSERT_TRUE(r.t_stop.has_value()) << k << " " << r.message;
    EXPECT_NEAR(*r.t_stop / *pr.t_stop, 1, 1e-9) << "k = " << k;
    EXPECT_NEAR(*r.x_stop / *pr.x_stop, 1, 1e-9) << "k = " << k;
    if (k > 0) {
      EXPECT_NEAR(*r.y_stop / *pr.y_stop, 1, 1e-9) << "k = " << k;
    }
    EXPECT_FALSE(r.slides_after_stop);
    RecordProperty("steps_k_" + std::to_string(k), static_cast<int>(r.steps));
  }
}

TEST(Numeric, SpeedNeverIncreasesWhenKBelowOne) {
  for (double k : {0.2, 0.9}) {
    const Parameters p = params_k(k);
    const NumericResult r = simulate(p, grid(1.05 * ClosedForm(p).t_stop(), 20000));
    double prev = p.v0;
    for (const State& s : r.samples) {
      const double v = std::hypot(s.vx, s.vy);
      // Speed decreases at >= alpha - beta > 0; 1e-13 m/s allows rounding of hypot.
      EXPECT_LE(v, prev + 1e-13) << "t = " << s.t;
      prev = v;
    }
  }
}

TEST(Numeric, ModelAWithoutNormalFrictionIsModelB) {
  Parameters p = params_k(0.6);
  p.normal_accel = 0.0;
  NumericOptions a;
  a.model = Model::A;
  const auto times = grid(1.2 * ClosedForm(p).t_stop(), 50);
  const NumericResult ra = simulate(p, times, a), rb = simulate(p, times);
  ASSERT_EQ(ra.samples.size(), rb.samples.size());
  for (std::size_t i = 0; i < ra.samples.size(); ++i) {
    EXPECT_EQ(ra.samples[i].x, rb.samples[i].x);
    EXPECT_EQ(ra.samples[i].y, rb.samples[i].y);
  }
  // And normal_accel is ignored by model B.
  p.normal_accel = 1.0;
  EXPECT_EQ(simulate(p, times).samples.back().x, rb.samples.back().x);
}

TEST(Numeric, ModelANormalFrictionPointsLeftOfTheVelocity) {
  Parameters p = params_k(0.6);
  p.normal_accel = 0.4;
  NumericOptions a;
  a.model = Model::A;
  const auto [ax, ay] = acceleration(p, a, p.v0, 0.0);
  EXPECT_DOUBLE_EQ(ax, -p.alpha());
  EXPECT_DOUBLE_EQ(ay, 0.4 - p.beta());  // launch along +x: left = up the slope
}

TEST(Numeric, MirrorSymmetry) {
  // x -> -x maps a launch along +x with f_N to a launch along -x with -f_N (left <-> right).
  Parameters p = params_k(0.5);
  p.normal_accel = 0.7;
  NumericOptions a;
  a.model = Model::A;
  const auto times = grid(0.5, 40);
  const NumericResult r1 = simulate(p, times, a);
  Parameters q = p;
  q.normal_accel = -0.7;
  State mirrored;
  mirrored.vx = -p.v0;
  const NumericResult r2 = simulate_from(q, mirrored, times, a);
  ASSERT_EQ(r1.samples.size(), r2.samples.size());
  for (std::size_t i = 0; i < times.size(); ++i) {
    // Same arithmetic up to signs: agreement to rounding of the step-size control.
    EXPECT_NEAR(r1.samples[i].x, -r2.samples[i].x, 1e-12);
    EXPECT_NEAR(r1.samples[i].y, r2.samples[i].y, 1e-12);
    EXPECT_NEAR(r1.samples[i].vx, -r2.samples[i].vx, 1e-12);
  }
}

TEST(Numeric, ModelAStopsAndSpiralsSmoothly) {
  // With f_N the direction turns faster and faster near the stop (rate f_N/|v|); the
  // log-speed phase integrates it smoothly, and the stop is independent of the tolerance.
  Parameters p = params_k(0.5);
  p.normal_accel = 0.3;
  NumericOptions a;
  a.model = Model::A;
  a.t_max = 5;
  const NumericResult r1 = simulate(p, {}, a);
  a.abs_tol = a.rel_tol = 1e-10;
  const NumericResult r2 = simulate(p, {}, a);
  ASSERT_TRUE(r1.t_stop && r2.t_stop) << r1.message;
  // Error control at 1e-10 vs 1e-12: the global error of the looser run is <= ~1e-9.
  EXPECT_NEAR(*r1.t_stop, *r2.t_stop, 1e-8);
  EXPECT_NEAR(*r1.x_stop, *r2.x_stop, 1e-8);
  EXPECT_NEAR(*r1.y_stop, *r2.y_stop, 1e-8);
  // Normal friction up the slope (left of a rightward, then downward path) keeps it higher.
  EXPECT_GT(*r1.y_stop, *ClosedForm(p).predict().y_stop);
}

TEST(Numeric, ConstantFrictionLawIsModelB) {
  const Parameters p = params_k(0.4);
  NumericOptions o;
  o.friction_law = [mu = p.mu](double) { return mu; };
  expect_matches_closed_form(p, o, 1.2 * ClosedForm(p).t_stop(), 1e-9);
}

TEST(Numeric, SpeedDependentFrictionOnAFlatPlane) {
  // phi = 0: dv/dt = -g mu0 (1 + c v), so t_stop = ln(1 + c v0) / (g mu0 c) and
  // x_stop = (c v0 - ln(1 + c v0)) / (g mu0 c^2).
  Parameters p;
  p.phi = 0;
  p.mu = 0.3;
  p.v0 = 2.0;
  const double mu0 = 0.3, c = 0.8;
  NumericOptions o;
  o.friction_law = [=](double v) { return mu0 * (1 + c * v); };
  o.t_max = 5;
  const NumericResult r = simulate(p, {}, o);
  ASSERT_TRUE(r.t_stop.has_value());
  const double gm = p.g * mu0;
  EXPECT_NEAR(*r.t_stop, std::log1p(c * p.v0) / (gm * c), 1e-9 * *r.t_stop);
  EXPECT_NEAR(*r.x_stop, (c * p.v0 - std::log1p(c * p.v0)) / (gm * c * c), 1e-9 * *r.x_stop);
  EXPECT_NEAR(*r.y_stop, 0.0, 1e-15);
}

TEST(Numeric, FromRestSlidesDownTheFallLine) {
  Parameters p;
  p.phi = deg_to_rad(35);
  p.mu = 0.5;
  p.v0 = 0;
  const auto times = grid(1.0, 10);
  const NumericResult r = simulate(p, times);
  const ClosedForm cf(p);
  for (std::size_t i = 0; i < times.size(); ++i) {
    // Straight line from rest: Dormand-Prince integrates the quadratic exactly.
    EXPECT_NEAR(r.samples[i].y, cf.at(times[i]).y, 1e-12);
    EXPECT_EQ(r.samples[i].x, 0.0);
  }
  p.mu_static = 0.8;  // tan 35 = 0.70 < 0.8: it stays
  EXPECT_EQ(simulate(p, times).samples.back().y, 0.0);
}

TEST(Numeric, StopsWhenLeavingTheRegion) {
  const Parameters p = params_k(0.5);
  NumericOptions o;
  o.region = Region{-1, 0.3, -10, 10};
  const NumericResult r = simulate(p, grid(1.0, 100), o);
  ASSERT_EQ(r.status, NumericStatus::left_region);
  const ClosedForm cf(p);
  const auto root = numerics::find_root([&](double t) { return cf.at(t).x - 0.3; }, 0, cf.t_stop());
  // The event is located on the dense output (4th order, error ~ tolerance).
  EXPECT_NEAR(*r.t_exit, root.x, 1e-9);
  EXPECT_LE(r.samples.back().t, *r.t_exit);
}

TEST(Numeric, ConvergesWithFifthOrder) {
  // Fixed-step Dormand-Prince on the incline right-hand side (k = 1.5, no stop): halving
  // the step divides the error by ~2^5 = 32; accept 24..40 (asymptotic regime).
  const Parameters p = params_k(1.5);
  const ClosedForm cf(p);
  const NumericOptions o;
  auto rhs = [&](const std::array<double, 4>& s, std::array<double, 4>& d, double) {
    const auto [ax, ay] = acceleration(p, o, s[2], s[3]);
    d = {s[2], s[3], ax, ay};
  };
  const State exact = cf.at(1.0);
  auto error = [&](int n) {
    const auto s = numerics::integrate_fixed(rhs, std::array<double, 4>{0, 0, p.v0, 0}, 0.0, 1.0, n);
    return std::hypot(s[0] - exact.x, s[1] - exact.y);
  };
  const double e1 = error(20), e2 = error(40), e3 = error(80);
  EXPECT_GT(e1 / e2, 24);
  EXPECT_LT(e1 / e2, 40);
  EXPECT_GT(e2 / e3, 24);
  EXPECT_LT(e2 / e3, 40);
}

TEST(Numeric, RejectsBadInput) {
  const Parameters p = params_k(0.5);
  EXPECT_THROW(simulate(p, {0.2, 0.1}), InputError);
  EXPECT_THROW(simulate(p, {-1.0}), InputError);
  NumericOptions o;
  o.friction_law = [](double) { return -1.0; };
  EXPECT_THROW(simulate(p, {0.1}, o), InputError);
}

}  // namespace
}  // namespace tribolab::incline
