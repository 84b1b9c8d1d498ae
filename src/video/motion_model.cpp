#include "video/motion_model.hpp"

#include "numerics/error.hpp"
#include "numerics/units.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace tribolab::video {
namespace {

// Rotations below this spread over the history leave the rigid-turn model undetermined
// (its lever arm is then confounded with the centre): the parabola is used.
constexpr double kMinSpread = to_rad(15);

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
  const double dt = frame - t0;  // prediction horizon, frames; times are measured from t0

  // Angle: constant rate of turn over the last `na` angles (least squares).
  {
    const int n = std::min(total, angle_history_);
    Eigen::MatrixXd a(n, n > 1 ? 2 : 1);
    Eigen::VectorXd f(n);
    for (int i = 0; i < n; ++i) {
      const Sample& h = history_[total - n + i];
      a(i, 0) = 1;
      if (n > 1) a(i, 1) = h.frame - t0;
      f(i) = h.angle;
    }
    const Eigen::VectorXd c = a.colPivHouseholderQr().solve(f);
    s.turn_rad = n > 1 ? c(1) : 0;
    s.angle_rad = c(0) + s.turn_rad * dt;
  }

  // Position, model 1: a parabola in time through the last np positions (a line through
  // two, the point itself for one): x = c0 + c1 t + c2 t^2, the same for y.
  const int np = std::min(total, position_history_);
  const int m = std::min(np, 3);  // polynomial terms
  Eigen::MatrixXd a(np, m);
  Eigen::MatrixXd f(np, 2);
  for (int i = 0; i < np; ++i) {
    const Sample& h = history_[total - np + i];
    const double t = h.frame - t0;
    for (int k = 0; k < m; ++k) a(i, k) = std::pow(t, k);
    f(i, 0) = h.x;
    f(i, 1) = h.y;
  }
  const Eigen::MatrixXd c = a.colPivHouseholderQr().solve(f);
  const double tp[3] = {1, dt, dt * dt}, dtp[3] = {0, 1, 2 * dt};
  for (int k = 0; k < m; ++k) {
    s.x_px += c(k, 0) * tp[k];
    s.y_px += c(k, 1) * tp[k];
    s.vx_px += c(k, 0) * dtp[k];
    s.vy_px += c(k, 1) * dtp[k];
  }
  if (np < 4) return s;

  // Model 2: a point on a turning body whose centre moves uniformly (a mark on a wheel, on a
  // spinning ball): p_i = c0 + c1 t_i + R(theta_i) r, R turning counter-clockwise on screen
  // (image y down), theta_i the measured pattern angles, r the lever arm at theta = 0.
  // Linear least squares in (c0, c1, r); used when the pattern turned enough to determine r
  // and it fits the same positions better than the parabola.
  double lo = history_[total - np].angle, hi = lo;
  for (int i = total - np; i < total; ++i) {
    lo = std::min(lo, history_[i].angle);
    hi = std::max(hi, history_[i].angle);
  }
  if (hi - lo < kMinSpread) return s;
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(2 * np, 6);
  Eigen::VectorXd g(2 * np);
  for (int i = 0; i < np; ++i) {
    const Sample& h = history_[total - np + i];
    const double t = h.frame - t0, co = std::cos(h.angle), si = std::sin(h.angle);
    b.row(2 * i) << 1, 0, t, 0, co, si;
    b.row(2 * i + 1) << 0, 1, 0, t, -si, co;
    g(2 * i) = h.x;
    g(2 * i + 1) = h.y;
  }
  const Eigen::VectorXd q = b.colPivHouseholderQr().solve(g);
  const double turning_rss = (b * q - g).squaredNorm();
  const double parabola_rss = (a * c - f).squaredNorm();
  // Compared per degree of freedom left: 2 np - 6 for both models (np >= 4).
  if (!(turning_rss < parabola_rss)) return s;
  const double th = s.angle_rad, co = std::cos(th), si = std::sin(th), w = s.turn_rad;
  s.x_px = q(0) + q(2) * dt + q(4) * co + q(5) * si;
  s.y_px = q(1) + q(3) * dt - q(4) * si + q(5) * co;
  s.vx_px = q(2) + w * (-q(4) * si + q(5) * co);
  s.vy_px = q(3) + w * (-q(4) * co - q(5) * si);
  return s;
}

}  // namespace tribolab::video
