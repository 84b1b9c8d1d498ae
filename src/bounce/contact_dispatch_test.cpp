// The contact solver compiled for two CPU levels (numerics/cpu_dispatch.hpp, contact.cpp): the
// x86-64-v3 kernel (FMA) and the baseline kernel solve the same equations and must agree on the
// seed's map to the tolerance's scale; the last bits differ (FMA rounds once where the baseline
// rounds twice), and where that flips a step's acceptance the two trajectories differ by an
// amount of the order of the tolerance (docs/benchmarks.md, "Issue 15, sixth pass").
#include "bounce/contact.hpp"

#include "numerics/cpu_dispatch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace tribolab::bounce {
namespace {

FrictionModel friction_of(FrictionKind kind) {
  FrictionModel f;
  f.mu = 0.5;
  f.kind = kind;
  f.slip_scale = 0.05;
  return f;
}

/// Largest difference of (vx, vy, b omega) between the two kernels over every second angle and
/// spin of the seed's map (figure 53: 100..170 deg x 30..50 rad/s at 4 m/s, the seed's law), m/s.
double largest_kernel_difference(FrictionKind kind, double tol) {
  const NormalLaw law = resolve(NormalLawSpec{}, 4, Ball{}.mass);
  const ContactOptions o = contact_options_with_tolerance(tol);
  double worst = 0;
  for (int angle = 100; angle <= 170; angle += 2) {
    for (int omega = 30; omega <= 50; omega += 2) {
      BodyState s;
      s.theta = theta_for_collision_angle(Ball{}, angle, 1);
      s.vy = -4;
      s.omega = omega;
      const ContactResult a = detail::simulate_contact_baseline(Ball{}, law, friction_of(kind), s, o, nullptr);
      const ContactResult b = detail::simulate_contact_x86_64_v3(Ball{}, law, friction_of(kind), s, o, nullptr);
      EXPECT_EQ(a.status, ContactStatus::separated);
      EXPECT_EQ(b.status, ContactStatus::separated);
      worst = std::max({worst, std::abs(a.out.vx - b.out.vx), std::abs(a.out.vy - b.out.vy),
                        Ball{}.b * std::abs(a.out.omega - b.out.omega)});
    }
  }
  return worst;
}

TEST(ContactDispatch, BothCpuLevelsAgreeOnTheSeedsMap) {
  if (numerics::cpu_level_supported() != numerics::CpuLevel::x86_64_v3)
    GTEST_SKIP() << "this CPU or build has no x86-64-v3 kernel";
  for (FrictionKind kind : {FrictionKind::coulomb, FrictionKind::regularized, FrictionKind::spring}) {
    // At the sweep's default 1e-6 each kernel is within 1.6e-5 m/s of the tolerance-1e-12
    // reference on the whole map (docs/benchmarks.md); measured between the kernels: at most
    // 2.1e-6 m/s (the spring model, where a rounding difference flips a step), most cells
    // equal to 1e-12. At 1e-10 the trajectories follow each other to 2.2e-12 m/s.
    EXPECT_LT(largest_kernel_difference(kind, 1e-6), 1e-5) << to_string(kind);
    EXPECT_LT(largest_kernel_difference(kind, 1e-10), 1e-9) << to_string(kind);
  }
}

TEST(ContactDispatch, OptionsChooseTheKernel) {
  BodyState s;
  s.theta = theta_for_collision_angle(Ball{}, 135, 1);
  s.vy = -4;
  s.omega = 40;
  const NormalLaw law = resolve(NormalLawSpec{}, 4, Ball{}.mass);
  const FrictionModel f = friction_of(FrictionKind::regularized);
  ContactOptions o = contact_options_with_tolerance(1e-6);
  // The same code on the same input gives the same bits.
  auto same = [](const ContactResult& a, const ContactResult& b) {
    return a.out.vx == b.out.vx && a.out.vy == b.out.vy && a.out.omega == b.out.omega && a.rhs_calls == b.rhs_calls;
  };
  EXPECT_EQ(o.kernel, ContactKernel::reproducible);  // the default
  EXPECT_TRUE(same(simulate_contact(Ball{}, law, f, s, o), detail::simulate_contact_baseline(Ball{}, law, f, s, o, nullptr)));
  o.kernel = ContactKernel::fastest;
  const ContactResult fastest = numerics::cpu_level() == numerics::CpuLevel::x86_64_v3
                                    ? detail::simulate_contact_x86_64_v3(Ball{}, law, f, s, o, nullptr)
                                    : detail::simulate_contact_baseline(Ball{}, law, f, s, o, nullptr);
  EXPECT_TRUE(same(simulate_contact(Ball{}, law, f, s, o), fastest));
}

}  // namespace
}  // namespace tribolab::bounce
