// The loop of the seed's method (seed_method.hpp). bench/seed/seed_native.cpp includes this
// file with TRIBOLAB_SEED_CONTACT_FN = seed_contact_native to build the same code with
// -O3 -march=native.
#include "bounce/seed_method.hpp"

#include "numerics/cpu_dispatch.hpp"

#include <cmath>

#ifndef TRIBOLAB_SEED_CONTACT_FN
#define TRIBOLAB_SEED_CONTACT_FN seed_contact
#endif

namespace tribolab::bounce::seed {
namespace {

template <bool Regularized>
[[gnu::always_inline]] inline SeedOut run(const SeedParams& p, double th, double vx, double vy, double w,
                                          double dt) {
  const double a2 = p.a * p.a, b2 = p.b * p.b, ab = a2 - b2;
  const double inv_m = 1 / p.mass, inv_I = 1 / p.inertia, inv_vs = 1 / p.slip_scale;
  const double K = p.K, n = p.n, chi = p.chi, mu = p.mu, g = p.g;
  double s, c;
  ::sincos(th, &s, &c);
  double y = std::sqrt(a2 * s * s + b2 * c * c);  // gap 0 at first touch
  long k = 0;
  for (;; ++k) {
    // Support point (geometry.cpp): Y = sqrt(a^2 s^2 + b^2 c^2), X = -dY/dtheta, with
    // s, c = sin, cos of theta.
    const double Y = std::sqrt(a2 * s * s + b2 * c * c);
    const double X = -ab * s * c / Y;
    const double d = Y - y;
    if (k > 0 && d <= 0) break;
    double N = 0;
    if (d > 0) {
      const double fac = 1 - chi * (vy + w * X);  // 1 + chi d_dot
      // d^n as exp(n log d), as our solver computes it (normal_law.hpp): faster than pow
      // and within a few ulp of it (docs/benchmarks.md#issue-15).
      if (fac > 0) N = K * std::exp(n * std::log(d)) * fac;
    }
    const double v_t = vx + w * Y;
    double f;
    if constexpr (Regularized) {
      f = -mu * N * std::tanh(v_t * inv_vs);
    } else {
      f = v_t > 0 ? -mu * N : (v_t < 0 ? mu * N : 0.0);
    }
    vx += f * inv_m * dt;
    vy += (N * inv_m - g) * dt;
    w += (X * N + Y * f) * inv_I * dt;
    y += vy * dt;
    // theta += w dt, carried as its sine and cosine: angle addition with the series of
    // sin and cos of the step angle (|w dt| <= ~1e-4 rad: the omitted terms are below 1e-21),
    // so no sincos per step, as our solver carries the support point in its state
    // (docs/benchmarks.md, "fifth pass"). The map's outputs move by <= 1.8e-13 m/s.
    const double dl = w * dt, z = dl * dl;
    const double sin_dl = dl * (1 - z / 6), cos_dl_m1 = z * (-0.5 + z / 24);
    const double s_next = s + (s * cos_dl_m1 + c * sin_dl);
    c += c * cos_dl_m1 - s * sin_dl;
    s = s_next;
  }
  return {vx, vy, w, static_cast<double>(k) * dt, k};
}

[[gnu::always_inline]] inline SeedOut run_law(const SeedParams& p, double th, double vx, double vy, double w,
                                              double dt) {
  return p.regularized ? run<true>(p, th, vx, vy, w, dt) : run<false>(p, th, vx, vy, w, dt);
}

#ifndef TRIBOLAB_SEED_NO_DISPATCH
// The same CPU dispatch as our solver's (numerics/cpu_dispatch.hpp, contact.cpp), so that the
// two are compiled alike: with the library's flags, the loop runs compiled for x86-64-v3 (FMA)
// where the CPU has it (docs/benchmarks.md, "Issue 15, sixth pass").
SeedOut run_baseline(const SeedParams& p, double th, double vx, double vy, double w, double dt) {
  return run_law(p, th, vx, vy, w, dt);
}
TRIBOLAB_TARGET_X86_64_V3 SeedOut run_x86_64_v3(const SeedParams& p, double th, double vx, double vy, double w,
                                                 double dt) {
  return run_law(p, th, vx, vy, w, dt);
}
#endif

}  // namespace

SeedOut TRIBOLAB_SEED_CONTACT_FN(const SeedParams& p, double theta, double vx, double vy, double omega, double dt) {
#ifdef TRIBOLAB_SEED_NO_DISPATCH
  return run_law(p, theta, vx, vy, omega, dt);
#else
  if (numerics::cpu_level() == numerics::CpuLevel::x86_64_v3) return run_x86_64_v3(p, theta, vx, vy, omega, dt);
  return run_baseline(p, theta, vx, vy, omega, dt);
#endif
}

}  // namespace tribolab::bounce::seed
