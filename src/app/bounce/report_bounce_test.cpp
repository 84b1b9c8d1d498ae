// In-process tests of the bounce report builders (src/app/bounce/report_bounce.cpp).
#include "app/bounce/report_bounce.hpp"

#include "bounce/geometry.hpp"
#include "bounce/impact.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tribolab::app {
namespace {

const report::Series* find_series(const report::Report& r, const std::string& name) {
  for (const auto& s : r.sections)
    for (const auto& b : s.blocks)
      if (const auto* f = std::get_if<report::Figure>(&b))
        for (const auto& se : f->series)
          if (se.name == name) return &se;
  return nullptr;
}

// The energy figure's mechanical curve must use the gravity of the simulation: it used
// 9.8 whatever --g said, so at g = 1 its end was off the work curve by m (9.8 - 1) dy.
TEST(BounceReport, EnergyBalanceUsesTheSimulatedGravity) {
  const bounce::Ball ball;
  bounce::NormalLawSpec law;
  const bounce::FrictionModel friction;
  bounce::BodyState touch;
  touch.theta = 0.3;
  touch.y = bounce::support_depth(ball, touch.theta);  // lowest point on the floor y = 0
  touch.vy = -3;
  touch.omega = -20;
  for (double g : {1.0, 9.8, 25.0}) {
    bounce::ImpactOptions io;
    io.contact.g = g;
    std::vector<bounce::ContactSample> hist;
    const auto r = bounce::simulate_impact(ball, law, friction, touch, io, &hist);
    const report::Report rep = bounce_simulate_report(ball, friction, g, r.whole, hist, r.contacts);
    const report::Series* mech = find_series(rep, "kinetic + m g (y − y_touch)");
    const report::Series* work = find_series(rep, "kinetic at touch + work of N and f");
    ASSERT_TRUE(mech && work);
    // Both are the energy at the end of the contact; they differ by the trapezoid rule's
    // error only (measured < 2e-4 J here; the old 9.8 at g = 1 gave m 8.8 dy ~ 2e-2 J).
    EXPECT_NEAR(mech->y.back(), work->y.back(), 2e-3) << "g = " << g;
  }
}

}  // namespace
}  // namespace tribolab::app
