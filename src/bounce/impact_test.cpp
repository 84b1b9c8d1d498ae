// The whole impact (impact.hpp) against bounce::simulate_drop, an independent driver of the
// same flight search and contact solver, on the low-rebound cells of the seed's map.
#include "bounce/impact.hpp"

#include "bounce/drop.hpp"
#include "numerics/error.hpp"
#include "numerics/units.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <vector>

namespace tribolab::bounce {
namespace {

constexpr double kG = kDefaultG;

/// The seed's map of `bounce sweep --theta-deg 100:170:71 --omega 30:50:21 --D 6000`: the
/// collision angle chi (direction +1, vx = 0), spin omega (CCW), vy = -4 m/s.
struct Cell {
  double chi_deg = 0, omega = 0;
  BodyState touch;
};

std::vector<Cell> seed_map(const Ball& ball) {
  std::vector<Cell> cells;
  for (int i = 0; i < 71; ++i) {
    for (int j = 0; j < 21; ++j) {
      Cell c;
      c.chi_deg = 100 + i;
      c.omega = 30 + j;
      c.touch.theta = theta_for_collision_angle(ball, c.chi_deg, 1);
      c.touch.vy = -4;
      c.touch.omega = c.omega;
      cells.push_back(c);
    }
  }
  return cells;
}

NormalLawSpec low_damping() {
  NormalLawSpec s;  // the seed's K and n
  s.D = 6000;
  return s;
}

TEST(Impact, OneContactWhenTheBallReboundsCleanly) {
  // Central impact without spin: one contact, and the whole impact is the first phase.
  const Ball ball;
  BodyState s;
  s.vy = -4;
  const ImpactResult r = simulate_impact(ball, NormalLawSpec{}, FrictionModel{}, s);
  EXPECT_EQ(r.status, ImpactStatus::free_flight);
  ASSERT_EQ(r.contacts, 1u);
  EXPECT_EQ(r.whole.out.vy, r.first.out.vy);
  EXPECT_EQ(r.whole.restitution, r.first.restitution);
  EXPECT_EQ(r.whole.contact_duration, r.first.contact_duration);
}

// Every cell of the seed's map whose first contact phase ends with e < 0.2 (the ball leaves
// the floor slowly or still moving down), simulated twice: simulate_impact from the touch
// state, and simulate_drop released 2 ms of free flight before that touch. Drop's state
// after the contact where simulate_impact says the impact ends must be simulate_impact's
// outcome, and drop's apexes must confirm where the impact ends: every earlier contact is
// followed by a touch before the apex (or no rise at all), the last by a real apex.
TEST(Impact, EqualsTheDropAfterTheWholeImpactOnLowReboundCells) {
  const Ball ball;
  const NormalLawSpec law = low_damping();
  FrictionModel fr;  // Coulomb, mu = 0.5
  // The sweep's default tolerance (1e-6) classifies the cells as the sweep does.
  const ContactOptions sweep_tol = contact_options_with_tolerance(1e-6);
  int n_nonpositive = 0, n_low = 0, n_multi = 0;
  double worst_v = 0, worst_first = 1e300;
  for (const Cell& c : seed_map(ball)) {
    const ContactResult first = simulate_contact(ball, law, fr, c.touch, sweep_tol);
    ASSERT_EQ(first.status, ContactStatus::separated);
    if (!(first.restitution < 0.2)) continue;
    ++n_low;
    n_nonpositive += first.restitution <= 0;
    const ImpactResult imp = simulate_impact(ball, law, fr, c.touch);
    ASSERT_EQ(imp.status, ImpactStatus::free_flight) << c.chi_deg << " " << c.omega;
    const std::size_t n = imp.contacts;
    n_multi += n > 1;
    if (first.restitution <= 0) {
      EXPECT_GE(n, 2u) << "a ball leaving downwards must touch again";
    }

    DropRelease rel;
    const double tau = 2e-3;  // s before the touch: gap ~ |v_contact| tau, mm, positive
    const BodyState r0 = free_flight(c.touch, kG, -tau);
    rel.height = support_depth(ball, c.touch.theta) + (r0.y - c.touch.y);
    rel.theta = r0.theta;
    rel.omega = r0.omega;
    rel.vx = r0.vx;
    rel.vy = r0.vy;
    DropOptions d;
    d.max_bounces = n + 1;
    d.rest_height = 0;
    const DropResult drop = simulate_drop(ball, law, fr, rel, d);
    ASSERT_GE(drop.bounces.size(), n) << drop.message;
    // Same first touch: the drop's search finds the touch state back to rounding.
    EXPECT_NEAR(drop.bounces[0].t_touch, tau, 1e-12);
    EXPECT_NEAR(drop.bounces[0].touch.theta, c.touch.theta, 1e-12);
    const Bounce& last = drop.bounces[n - 1];
    // Tolerance: both integrate the same contacts at tolerance 1e-10 from touch states that
    // differ by rounding (~1e-15); outgoing velocities are accurate to ~1e-9 m/s per
    // contact (docs/theory.md#bounce-integrator), so 1e-7 m/s over a few contacts is ample
    // and still 1e5 times below the first-phase/whole-impact differences (checked below).
    const double tol_v = 1e-7;
    EXPECT_NEAR(imp.whole.out.vx, last.contact.out.vx, tol_v);
    EXPECT_NEAR(imp.whole.out.vy, last.contact.out.vy, tol_v);
    EXPECT_NEAR(imp.whole.out.omega, last.contact.out.omega, tol_v / ball.b);
    EXPECT_NEAR(imp.whole.restitution, -last.contact.out.vy / drop.bounces[0].touch.vy, tol_v);
    // Times: located events to ~1e-13 s, the integrator's contact ends to ~tol.
    EXPECT_NEAR(imp.whole.contact_duration, last.t_touch + last.contact.contact_duration - drop.bounces[0].t_touch, 1e-8);
    double peak = 0;
    for (std::size_t k = 0; k < n; ++k) peak = std::max(peak, drop.bounces[k].contact.peak_force);
    EXPECT_NEAR(imp.whole.peak_force, peak, 1e-6 * peak);
    EXPECT_NEAR(imp.whole.energy_out.total(), last.contact.energy_out.total(), 1e-6);
    // Drop's apexes: contacts 1..n-1 are followed by a touch before the apex (t_apex is the
    // next touch) or by no rise; contact n by its ballistic apex, before any next touch.
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const Bounce& b = drop.bounces[k];
      const bool no_rise = b.contact.out.vy <= 0;
      const bool touch_before_apex = b.t_apex == drop.bounces[k + 1].t_touch;
      EXPECT_TRUE(no_rise || touch_before_apex) << "contact " << k + 1 << " of " << n;
    }
    EXPECT_GT(last.contact.out.vy, 0);
    if (drop.bounces.size() > n) {
      EXPECT_LT(last.t_apex, drop.bounces[n].t_touch) << "the impact should have gone on";
    }
    worst_v = std::max({worst_v, std::abs(imp.whole.out.vy - last.contact.out.vy),
                        std::abs(imp.whole.out.vx - last.contact.out.vx)});
    if (n > 1) worst_first = std::min(worst_first, std::abs(first.out.vy - last.contact.out.vy) +
                                                        std::abs(first.out.vx - last.contact.out.vx));
  }
  std::cout << "seed map, D = 6000: " << n_nonpositive << " cells with e_first <= 0, " << n_low
            << " with e_first < 0.2, " << n_multi << " of them with several contacts; worst "
            << "|whole - drop| = " << worst_v << " m/s; smallest |first phase - drop| where "
            << "several contacts = " << worst_first << " m/s\n";
  // The seed map's counts at the sweep's tolerance (issue 11: 9 and 86).
  EXPECT_EQ(n_nonpositive, 9);
  EXPECT_EQ(n_low, 86);
  EXPECT_GT(n_multi, n_nonpositive - 1);
  // The first phase alone is far from drop's outcome where the impact has several contacts:
  // a simulate that stopped at the first separation fails the comparison above.
  EXPECT_GT(worst_first, 1e3 * 1e-7);
}

TEST(Impact, WithoutGravityEndsWhenTheGapCanNoLongerClose) {
  // g = 0 on the low-rebound cells: after the last separation the centre rises uniformly;
  // a dense scan of the gap until the centre passes a (no contact possible above) finds no
  // touch that simulate_impact missed.
  const Ball ball;
  const NormalLawSpec law = low_damping();
  ImpactOptions o;
  o.contact.g = 0;
  int checked = 0;
  for (const Cell& c : seed_map(ball)) {
    if (c.omega != 30 && c.omega != 40 && c.omega != 50) continue;
    const ImpactResult r = simulate_impact(ball, law, FrictionModel{}, c.touch, o);
    ASSERT_EQ(r.status, ImpactStatus::free_flight) << c.chi_deg << " " << c.omega;
    const BodyState s = r.whole.out;
    ASSERT_GT(s.vy, 0) << "with g = 0 a ball that does not rise must touch again";
    const double t_up = (ball.a - s.y) / s.vy;
    for (int k = 1; k <= 20000; ++k) {
      const BodyState f = free_flight(s, 0, t_up * k / 20000);
      ASSERT_GT(f.y - support_depth(ball, f.theta), 0) << c.chi_deg << " " << c.omega << " k " << k;
    }
    ++checked;
  }
  EXPECT_EQ(checked, 71 * 3);
}

TEST(Impact, EnergyBalanceHoldsOverTheWholeImpact) {
  // E_in + W_gravity = E_out + dissipated (+ residual ~ tolerance): flights add nothing.
  const Ball ball;
  const NormalLawSpec law = low_damping();
  for (const Cell& c : seed_map(ball)) {
    if (c.omega != 50) continue;
    const ImpactResult r = simulate_impact(ball, law, FrictionModel{}, c.touch);
    const ContactResult& w = r.whole;
    const double balance = w.energy_in.total() + w.work_gravity - w.energy_out.total() -
                           w.dissipated_normal - w.dissipated_friction;
    // 1e-6 J: residual ~1e-10 J per contact at tolerance 1e-10 (docs/theory.md#bounce-contact).
    EXPECT_NEAR(balance, 0, 1e-6) << c.chi_deg;
    EXPECT_LE(w.energy_out.total(), w.energy_in.total() + w.work_gravity + 1e-6);
  }
}

}  // namespace
}  // namespace tribolab::bounce
