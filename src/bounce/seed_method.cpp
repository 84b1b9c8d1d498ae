// The loop of the seed's method (seed_method.hpp). bench/seed/seed_native.cpp includes this
// file with TRIBOLAB_SEED_CONTACT_FN = seed_contact_native to build the same code with
// -O3 -march=native.
#include "bounce/seed_method.hpp"

#include <cmath>

#ifndef TRIBOLAB_SEED_CONTACT_FN
#define TRIBOLAB_SEED_CONTACT_FN seed_contact
#endif

namespace tribolab::bounce::seed {
namespace {

template <bool Regularized>
SeedOut run(const SeedParams& p, double th, double vx, double vy, double w, double dt) {
  const double a2 = p.a * p.a, b2 = p.b * p.b, ab = a2 - b2;
  const double inv_m = 1 / p.mass, inv_I = 1 / p.inertia, inv_vs = 1 / p.slip_scale;
  const double K = p.K, n = p.n, chi = p.chi, mu = p.mu, g = p.g;
  double s, c;
  ::sincos(th, &s, &c);
  double y = std::sqrt(a2 * s * s + b2 * c * c);  // gap 0 at first touch
  long k = 0;
  for (;; ++k) {
    // Support point (geometry.cpp): Y = sqrt(a^2 s^2 + b^2 c^2), X = -dY/dtheta.
    ::sincos(th, &s, &c);
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
    th += w * dt;
  }
  return {vx, vy, w, static_cast<double>(k) * dt, k};
}

}  // namespace

SeedOut TRIBOLAB_SEED_CONTACT_FN(const SeedParams& p, double theta, double vx, double vy, double omega, double dt) {
  return p.regularized ? run<true>(p, theta, vx, vy, omega, dt) : run<false>(p, theta, vx, vy, omega, dt);
}

}  // namespace tribolab::bounce::seed
