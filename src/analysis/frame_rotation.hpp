// A camera frame turned against the incline (docs/theory.md#incline-analysis): the tracked
// coordinates are the incline-frame ones rotated counterclockwise by psi about the launch
// point (x0, y0). psi is the direction of the incline's +x axis (the launch direction) seen in
// the file's frame, counterclockwise from the file's +x axis; a plumb line set 0.5 deg off
// gives |psi| = 0.5 deg. Rotating about another point differs by a translation only, which
// the fitted launch point absorbs.
#pragma once

#include "incline/closed_form.hpp"

#include <cmath>

namespace tribolab::analysis {

/// State `s` (relative to the launch point, incline frame) turned by psi (rad) and moved to
/// (x0, y0): positions, velocities and accelerations all rotate.
inline incline::State rotate_state(incline::State s, double psi, double x0, double y0) {
  const double c = std::cos(psi), n = std::sin(psi);
  const auto turn = [&](double& u, double& v) {
    const double a = c * u - n * v, b = n * u + c * v;
    u = a;
    v = b;
  };
  turn(s.x, s.y);
  turn(s.vx, s.vy);
  turn(s.ax, s.ay);
  s.x += x0;
  s.y += y0;
  return s;
}

}  // namespace tribolab::analysis
