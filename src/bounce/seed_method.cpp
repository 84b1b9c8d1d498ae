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

}  // namespace

SeedOut TRIBOLAB_SEED_CONTACT_FN(const SeedParams& p, double theta, double vx, double vy, double omega, double dt) {
  return p.regularized ? run<true>(p, theta, vx, vy, omega, dt) : run<false>(p, theta, vx, vy, omega, dt);
}

}  // namespace tribolab::bounce::seed
