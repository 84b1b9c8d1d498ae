// Velocities and accelerations of a tracked point, two ways (docs/theory.md#kinematics):
//
// * `tracker`: Tracker's own finite differences, so the numbers equal Tracker's tables:
//     v_i = (x_{i+1} - x_{i-1}) / (t_{i+1} - t_{i-1})
//     a_i = (2x_{i-2} - x_{i-1} - 2x_i - x_{i+1} + 2x_{i+2}) / (7 dt^2),  dt = (t_{i+2} - t_{i-2})/4
//   (the 5-point formula is the curvature of the least-squares parabola through 5 equally
//   spaced points). Undefined (NaN) where a needed neighbour is missing: the ends, gaps in the
//   frame sequence, and across impacts.
// * `savgol`: Savitzky–Golay derivatives generalised to uneven times and missing points: at
//   each point a polynomial of degree `order` is fitted by least squares to the `window`
//   nearest points of the same flight segment (centred, shifted at the segment ends), and
//   v = p'(t_i), a = p''(t_i). Standard errors: sigma * sqrt((A^T A)^{-1}_kk), with the noise
//   sigma pooled from all windows' residuals (sum RSS / sum dof) of the track.
#pragma once

#include "track/impacts.hpp"
#include "track/track.hpp"

#include <string>
#include <vector>

namespace tribolab::track {

enum class DerivativeMethod { tracker, savgol };

/// "tracker" or "savgol".
const char* to_string(DerivativeMethod m);

struct KinematicsOptions {
  DerivativeMethod method = DerivativeMethod::tracker;
  int window = 7;                ///< savgol: points per local fit (>= order + 2), e.g. 7
  int order = 2;                 ///< savgol: polynomial degree, 1..6, e.g. 2
  bool split_at_impacts = true;  ///< detect impacts and never difference across them
  ImpactOptions impacts;         ///< impact detector settings
  /// Empty when valid, else a message naming the bad field.
  std::string validate() const;
};

/// Kinematics at one marked point; NaN where undefined.
struct KinematicsRow {
  int frame = 0;        ///< video frame
  double t = 0;         ///< s
  double x = 0, y = 0;  ///< m
  double vx = 0, vy = 0;  ///< m/s
  double ax = 0, ay = 0;  ///< m/s^2, e.g. ay = -9.8 in flight
  double sigma_vx = 0, sigma_vy = 0;  ///< standard errors, m/s (savgol; NaN for tracker)
  double sigma_ax = 0, sigma_ay = 0;  ///< standard errors, m/s^2 (savgol; NaN for tracker)
  int segment = 0;      ///< index of the flight segment the point belongs to
};

struct Kinematics {
  std::string track;                 ///< track name
  DerivativeMethod method = DerivativeMethod::tracker;
  std::vector<KinematicsRow> rows;   ///< one per point of the track
  std::vector<Impact> impacts;       ///< impacts the derivatives were not smeared across
  int segments = 1;                  ///< number of flight segments
  double noise_x = 0, noise_y = 0;   ///< robust position noise estimate, m
  /// savgol: pooled residual standard deviation of the local fits, m (NaN for tracker).
  double residual_sigma_x = 0, residual_sigma_y = 0;
};

/// Differentiates one track. Throws InputError for invalid options or an invalid track.
Kinematics differentiate(const Track& track, const KinematicsOptions& options = {});

}  // namespace tribolab::track
