// Analytic cell models with known answers, for the sweep's tests and benchmarks (the
// bounce contact lives in src/bounce). Each is a pure function of its input.
#pragma once

#include <cmath>
#include <numbers>

#include "sweep/runner.hpp"
#include "numerics/units.hpp"

namespace tribolab::sweep::synthetic {

/// Spin at which the "wave" model has e = 1: 40.3 + 5 sin(2 theta) + 2 (speed - 4)
/// + 3 (mu - 0.5) rad/s, close to the seed's boundary near 35-45 rad/s.
inline double wave_threshold(double theta_deg, double speed, double mu) {
  return 40.3 + 5 * std::sin(theta_deg * std::numbers::pi / 90) + 2 * (speed - 4) + 3 * (mu - 0.5);
}

/// e = exp((omega - wave_threshold) / 5): monotone in omega, e = 1 exactly on the
/// threshold curve. Outputs vx, vy, omega_out, e like a bounce.
inline CellModel wave_model() {
  CellModel m;
  m.output_names = {"vx", "vy", "omega_out", "e"};
  m.evaluate = [](const CellInput& in) {
    const double e = std::exp((in.omega - wave_threshold(in.theta_deg, in.speed, in.mu)) / 5);
    return CellOutputs{0.1 * std::cos(to_rad(in.theta_deg)), e * in.speed,
                       in.omega * (1.2 - 0.2 * e), e};
  };
  m.description = "synthetic wave: e = exp((omega - 40.3 - 5 sin(2 theta) - 2 (speed - 4) - 3 (mu - 0.5)) / 5)";
  m.mass = 0.435;
  m.inertia = 4.1e-3;
  return m;
}

/// e = 1.5 - ((theta - 135)/20)^2 - ((omega - 40)/5)^2: the e = 1 set is the ellipse
/// ((theta - 135)/20)^2 + ((omega - 40)/5)^2 = 0.5, a closed curve.
inline CellModel ellipse_model() {
  CellModel m;
  m.output_names = {"e"};
  m.evaluate = [](const CellInput& in) {
    const double u = (in.theta_deg - 135) / 20, v = (in.omega - 40) / 5;
    return CellOutputs{1.5 - u * u - v * v};
  };
  m.description = "synthetic ellipse";
  return m;
}

/// e = 1 + (theta - 131.3)(omega - 41.7) / 100: the e = 1 set is two crossing lines, with
/// saddle squares; used to test the marching-squares ambiguity.
inline CellModel saddle_model() {
  CellModel m;
  m.output_names = {"e"};
  m.evaluate = [](const CellInput& in) {
    return CellOutputs{1 + (in.theta_deg - 131.3) * (in.omega - 41.7) / 100};
  };
  m.description = "synthetic saddle";
  return m;
}

/// The cheapest cell: returns its inputs; measures the engine's overhead per cell.
inline CellModel trivial_model() {
  CellModel m;
  m.output_names = {"vx", "vy", "omega_out", "e"};
  m.evaluate = [](const CellInput& in) {
    return CellOutputs{in.theta_deg, in.speed, in.omega, in.ratio};
  };
  m.description = "synthetic trivial";
  return m;
}

}  // namespace tribolab::sweep::synthetic
