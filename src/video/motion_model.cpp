#include "video/motion_model.hpp"

#include "numerics/error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace tribolab::video {
namespace {

// Least-squares polynomial of degree `degree` (0, 1 or 2) through (t_i, f_i), returned as
// coefficients of 1, t, t^2 (normal equations; t is centred by the caller, so they are
// well conditioned for the handful of samples used).
std::array<double, 3> fit_polynomial(const double* t, const double* f, int n, int degree) {
  const int m = degree + 1;
  double a[3][4] = {};
  for (int i = 0; i < n; ++i) {
    const double p[3] = {1, t[i], t[i] * t[i]};
    for (int r = 0; r < m; ++r) {
      for (int c = 0; c < m; ++c) a[r][c] += p[r] * p[c];
      a[r][m] += p[r] * f[i];
    }
  }
  // Gauss-Jordan elimination with partial pivoting on the m x (m+1) system.
  for (int c = 0; c < m; ++c) {
    int pivot = c;
    for (int r = c + 1; r < m; ++r) {
      if (std::abs(a[r][c]) > std::abs(a[pivot][c])) pivot = r;
    }
    std::swap(a[c], a[pivot]);
    TRIBOLAB_ASSERT(a[c][c] != 0, "singular motion fit, " + std::to_string(n) + " samples");
    for (int r = 0; r < m; ++r) {
      if (r == c) continue;
      const double k = a[r][c] / a[c][c];
      for (int cc = c; cc <= m; ++cc) a[r][cc] -= k * a[c][cc];
    }
  }
  std::array<double, 3> coef{0, 0, 0};
  for (int r = 0; r < m; ++r) coef[r] = a[r][m] / a[r][r];
  return coef;
}

}  // namespace

MotionModel::MotionModel(int position_history, int angle_history)
    : position_history_(std::max(1, position_history)), angle_history_(std::max(1, angle_history)) {}

void MotionModel::reset() { history_.clear(); }

int MotionModel::last_frame() const { return history_.empty() ? 0 : history_.back().frame; }

void MotionModel::add(int frame, double x_px, double y_px, double angle_rad) {
  TRIBOLAB_ASSERT(history_.empty() || frame > history_.back().frame,
                  "frame " + std::to_string(frame) + " after " + std::to_string(last_frame()));
  history_.push_back({frame, x_px, y_px, angle_rad});
  while (static_cast<int>(history_.size()) > std::max(position_history_, angle_history_)) {
    history_.pop_front();
  }
}

MotionState MotionModel::predict(int frame) const {
  TRIBOLAB_ASSERT(!history_.empty(), std::string("prediction without any observation"));
  MotionState s;
  const int total = static_cast<int>(history_.size());
  const double t0 = history_.back().frame;
  const double dt = frame - t0;  // prediction horizon, frames
  {
    // Position: parabola through the last `np` positions (a line through two, a constant
    // for one), time measured from the last observation.
    const int np = std::min(total, position_history_);
    double t[8], x[8], y[8];
    const int n = std::min(np, 8);
    for (int i = 0; i < n; ++i) {
      const Sample& h = history_[total - n + i];
      t[i] = h.frame - t0;
      x[i] = h.x;
      y[i] = h.y;
    }
    const int degree = std::min(n - 1, 2);
    const auto cx = fit_polynomial(t, x, n, degree);
    const auto cy = fit_polynomial(t, y, n, degree);
    s.x_px = cx[0] + cx[1] * dt + cx[2] * dt * dt;
    s.y_px = cy[0] + cy[1] * dt + cy[2] * dt * dt;
    s.vx_px = cx[1] + 2 * cx[2] * dt;
    s.vy_px = cy[1] + 2 * cy[2] * dt;
  }
  {
    // Angle: constant rate of turn over the last `na` angles.
    const int n = std::min({total, angle_history_, 8});
    double t[8], a[8];
    for (int i = 0; i < n; ++i) {
      const Sample& h = history_[total - n + i];
      t[i] = h.frame - t0;
      a[i] = h.angle;
    }
    const auto ca = fit_polynomial(t, a, n, std::min(n - 1, 1));
    s.angle_rad = ca[0] + ca[1] * dt;
    s.turn_rad = ca[1];
  }
  return s;
}

}  // namespace tribolab::video
