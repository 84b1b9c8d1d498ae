// The seed's own method for one contact (seed 001, 實驗四 (二); docs/theory.md#bounce-contact):
// explicit steps of dt = 1 microsecond, velocities first and then positions (symplectic
// Euler), until the penetration of the support point returns to zero. It is the baseline
// our solver is measured against (docs/benchmarks.md), in speed and in accuracy: written as
// tight as a careful engineer would write it (no allocation, d^n as exp(n log d) as in our
// solver, sin and cos of theta advanced by the step's rotation instead of a sincos per step,
// the friction law chosen at compile time). Like our solver it runs compiled for x86-64-v3
// where the CPU has it (numerics/cpu_dispatch.hpp), so that the two are compiled alike; bench/
// compiles the same source a second time with -O3 -march=native (bench/seed/seed_native.cpp).
#pragma once

#include "bounce/normal_law.hpp"
#include "numerics/units.hpp"

namespace tribolab::bounce::seed {

/// Everything one contact needs, SI units (the ball, the Hunt–Crossley law
/// N = K d^n (1 + chi d_dot) clamped at 0, the friction law, gravity).
struct SeedParams {
  double a = 0.145, b = 0.095;   ///< semi-axes, m
  double mass = 0.435;           ///< kg
  double inertia = 4.1e-3;       ///< kg m^2
  double K = Seed001Law::K, n = Seed001Law::n;  ///< N/m^n, exponent (the seed's fit)
  double chi = Seed001Law::D / Seed001Law::K;   ///< D / K, s/m
  double mu = 0.5;               ///< Coulomb coefficient
  bool regularized = false;      ///< f = -mu N tanh(v_t / v_s) instead of exact Coulomb sign
  double slip_scale = 0.05;      ///< v_s, m/s
  double g = kDefaultG;          ///< m/s^2
};

struct SeedOut {
  double vx = 0, vy = 0, omega = 0;  ///< outgoing velocities, m/s and rad/s
  double duration = 0;               ///< s
  long steps = 0;
};

/// One contact from first touch (gap 0) at orientation theta (rad) with centre velocity
/// (vx, vy) (m/s) and spin omega (rad/s), steps of dt (s).
/// (seed_method.cpp; the same code built with -O3 -march=native is seed_contact_native, in
/// bench/ only.)
SeedOut seed_contact(const SeedParams& p, double theta, double vx, double vy, double omega, double dt);
SeedOut seed_contact_native(const SeedParams& p, double theta, double vx, double vy, double omega,
                            double dt);

}  // namespace tribolab::bounce::seed
