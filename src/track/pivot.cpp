#include "track/pivot.hpp"

#include "numerics/error.hpp"
#include "numerics/least_squares.hpp"
#include "numerics/message_number.hpp"
#include "numerics/units.hpp"
#include "track/local_spin.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace tribolab::track {

namespace {

/// Residuals of the joint model (pivot.hpp) for p = [x_p, y_p, v_x, v_y, r, theta_0, omega, alpha].
struct PivotModel {
  const std::vector<double>* u;  ///< t - t_ref, s
  const std::vector<double>* x;  ///< m
  const std::vector<double>* y;  ///< m
  template <class T>
  bool operator()(const T* p, T* res) const {
    using std::cos, std::sin;
    for (std::size_t i = 0; i < u->size(); ++i) {
      const double ui = (*u)[i];
      const T th = p[5] + p[6] * ui + 0.5 * p[7] * ui * ui;
      res[2 * i] = (*x)[i] - (p[0] + p[2] * ui + p[4] * cos(th));
      res[2 * i + 1] = (*y)[i] - (p[1] + p[3] * ui + p[4] * sin(th));
    }
    return true;
  }
};

/// Geometric circle: residuals |p_i - c| - r for p = [x_c, y_c, r] (no time dependence).
struct CircleModel {
  const std::vector<double>* x;  ///< m
  const std::vector<double>* y;  ///< m
  template <class T>
  bool operator()(const T* p, T* res) const {
    using std::sqrt;
    for (std::size_t i = 0; i < x->size(); ++i) {
      const T dx = (*x)[i] - p[0], dy = (*y)[i] - p[1];
      res[i] = sqrt(dx * dx + dy * dy) - p[2];
    }
    return true;
  }
};

/// Slope and intercept (at u = 0, the mean time) of v against u.
std::pair<double, double> line(const std::vector<double>& u, const std::vector<double>& v) {
  double su = 0, sv = 0, suu = 0, suv = 0;
  const double n = static_cast<double>(u.size());
  for (std::size_t i = 0; i < u.size(); ++i) {
    su += u[i];
    sv += v[i];
    suu += u[i] * u[i];
    suv += u[i] * v[i];
  }
  const double slope = (n * suv - su * sv) / (n * suu - su * su);
  return {sv / n - slope * su / n, slope};
}

}  // namespace

std::string PivotOptions::validate() const {
  if ((pivot_x == pivot_x) != (pivot_y == pivot_y)) {
    return field("pivot_x") + " and " + field("pivot_y") + " go together: give both or neither";
  }
  if (pivot_given() && !(std::isfinite(pivot_x) && std::isfinite(pivot_y))) {
    return field("pivot_x") + "/" + field("pivot_y") + " must be finite numbers of m";
  }
  if (pivot_given() && moving_pivot) {
    return field("moving_pivot") + " fits the pivot: it cannot go with a given " + field("pivot_x") + "/" +
           field("pivot_y");
  }
  if (window < 3) return field("window") + " must be at least 3 points, got " + std::to_string(window);
  if (!(max_pivot_sigma > 0 && max_pivot_sigma <= 1)) {
    return field("max_pivot_sigma") + " must lie in (0, 1] (a fraction of the radius), got " +
           message_number(max_pivot_sigma, 17);
  }
  return "";
}

Circle kasa_circle(const std::vector<double>& x, const std::vector<double>& y) {
  // centred coordinates keep the normal equations well conditioned far from the origin
  const std::size_t n = x.size();
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= static_cast<double>(n);
  my /= static_cast<double>(n);
  Eigen::MatrixXd A(n, 3);
  Eigen::VectorXd b(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = x[i] - mx, dy = y[i] - my;
    A.row(static_cast<Eigen::Index>(i)) << dx, dy, 1;
    b(static_cast<Eigen::Index>(i)) = -(dx * dx + dy * dy);
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  Circle c;
  if (qr.rank() < 3) {
    c.x = c.y = c.r = kNaN;
    return c;
  }
  const Eigen::Vector3d s = qr.solve(b);
  c.x = mx - s(0) / 2;
  c.y = my - s(1) / 2;
  const double r2 = s(0) * s(0) / 4 + s(1) * s(1) / 4 - s(2);
  c.r = r2 > 0 ? std::sqrt(r2) : kNaN;
  return c;
}

PivotRotation rotation_about_pivot(const Track& track, const PivotOptions& options) {
  if (const auto err = options.validate(); !err.empty()) throw InputError(err);
  validate_track(track, "");
  const std::size_t n = track.points.size();
  const std::size_t least = options.moving_pivot ? 8 : 6;
  if (n < least) {
    throw InputError("track '" + track.name + "' has " + std::to_string(n) + " point(s); at least " +
                     std::to_string(least) + " are needed for a rotation about " +
                     (options.moving_pivot ? "a moving pivot" : "a pivot"));
  }
  PivotRotation out;
  out.track = track.name;
  std::vector<double> u(n), x(n), y(n);
  for (const auto& p : track.points) out.t_ref += p.t;
  out.t_ref /= static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i) {
    u[i] = track.points[i].t - out.t_ref;
    x[i] = track.points[i].x;
    y[i] = track.points[i].y;
  }
  // start: the pivot (given, or Kasa's circle of the points, detrended when the pivot moves)
  double px = options.pivot_x, py = options.pivot_y, vx = 0, vy = 0;
  if (!options.pivot_given()) {
    std::vector<double> dx = x, dy = y;
    double ax = 0, ay = 0;
    if (options.moving_pivot) {
      std::tie(ax, vx) = line(u, x);
      std::tie(ay, vy) = line(u, y);
      for (std::size_t i = 0; i < n; ++i) {
        dx[i] = x[i] - (ax + vx * u[i]);
        dy[i] = y[i] - (ay + vy * u[i]);
      }
    }
    out.kasa = kasa_circle(dx, dy);
    if (!std::isfinite(out.kasa.r)) {
      throw InputError("track '" + track.name + "' lies on a straight line: it turns about no pivot");
    }
    px = ax + out.kasa.x;
    py = ay + out.kasa.y;
  }
  // angles about the starting pivot, unwrapped to the nearest branch, and a line through them
  std::vector<double> th(n);
  double r0 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double ex = x[i] - (px + vx * u[i]), ey = y[i] - (py + vy * u[i]);
    th[i] = std::atan2(ey, ex);
    if (i > 0) th[i] += 2 * std::numbers::pi * std::round((th[i - 1] - th[i]) / (2 * std::numbers::pi));
    r0 += std::hypot(ex, ey);
  }
  r0 /= static_cast<double>(n);
  const auto [th0, w0] = line(u, th);

  const bool fit_pivot = !options.pivot_given();
  std::vector<numerics::FitParameter> params{
      {"pivot_x", px, {}, {}, !fit_pivot},          {"pivot_y", py, {}, {}, !fit_pivot},
      {"pivot_vx", vx, {}, {}, !options.moving_pivot}, {"pivot_vy", vy, {}, {}, !options.moving_pivot},
      {"radius", r0, 0.0, {}, false},               {"theta_ref", th0, {}, {}, false},
      {"omega", w0, {}, {}, false},                 {"alpha", 0, {}, {}, false}};
  numerics::FitResult fit =
      numerics::fit_least_squares_autodiff(PivotModel{&u, &x, &y}, static_cast<int>(2 * n), params);
  // A pendulum's angle swings: no quadratic theta(t) follows it and the joint fit's residuals
  // exceed the noise. The circle alone (geometric fit, no time) then places the pivot, and the
  // angle model is refitted about it (omega, alpha only summarise; the local spins hold).
  numerics::FitResult circle;
  if (fit_pivot && !options.moving_pivot) {
    circle = numerics::fit_least_squares_autodiff(
        CircleModel{&x, &y}, static_cast<int>(n),
        {{"pivot_x", px, {}, {}, false}, {"pivot_y", py, {}, {}, false}, {"radius", r0, 0.0, {}, false}});
    const auto rms = [](const numerics::FitResult& f) { return f.dof > 0 ? std::sqrt(2 * f.cost / f.dof) : kNaN; };
    // per coordinate and radially both estimate the noise sigma; twice it is a clear misfit
    if (circle.ok() && (!fit.ok() || rms(fit) > 2 * rms(circle))) {
      out.pivot_from_circle = true;
      for (auto& q : params) {
        if (q.name == "pivot_x" || q.name == "pivot_y" || q.name == "radius") q.initial = circle.value(q.name);
        if (q.name == "pivot_x" || q.name == "pivot_y") q.fixed = true;
      }
      fit = numerics::fit_least_squares_autodiff(PivotModel{&u, &x, &y}, static_cast<int>(2 * n), params);
    }
  }
  const std::string where = "track '" + track.name + "'";
  const double arc_start = th.back() - th.front();
  if (!fit.ok()) {
    throw InputError(where, std::string("the rotation about ") + (fit_pivot ? "a fitted pivot" : "the given pivot") +
                                " could not be fitted (" + fit.message + "); the arc covers " +
                                message_number(std::round(to_deg(std::abs(arc_start))), 6) + " deg" +
                                (fit_pivot ? ": give the pivot with " + field("pivot_x") + "/" + field("pivot_y")
                                           : std::string()));
  }
  out.pivot_x = fit.value("pivot_x");
  out.pivot_y = fit.value("pivot_y");
  out.sigma_pivot_x = out.pivot_from_circle ? circle.sigma_of("pivot_x") : fit.sigma_of("pivot_x");
  out.sigma_pivot_y = out.pivot_from_circle ? circle.sigma_of("pivot_y") : fit.sigma_of("pivot_y");
  out.pivot_vx = fit.value("pivot_vx");
  out.pivot_vy = fit.value("pivot_vy");
  out.sigma_pivot_vx = fit.sigma_of("pivot_vx");
  out.sigma_pivot_vy = fit.sigma_of("pivot_vy");
  out.radius = fit.value("radius");
  out.sigma_radius = fit.sigma_of("radius");
  out.theta_ref = fit.value("theta_ref");
  out.sigma_theta_ref = fit.sigma_of("theta_ref");
  out.omega = fit.value("omega");
  out.sigma_omega = fit.sigma_of("omega");
  out.alpha = fit.value("alpha");
  out.sigma_alpha = fit.sigma_of("alpha");
  out.dof = fit.dof;
  out.rms_residual = fit.dof > 0 ? std::sqrt(2 * fit.cost / fit.dof) : kNaN;

  // rows: angle about the fitted pivot, on the branch of the fitted theta(t)
  std::vector<RigidBodyRow> spin(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = track.points[i];
    const double ex = x[i] - (out.pivot_x + out.pivot_vx * u[i]), ey = y[i] - (out.pivot_y + out.pivot_vy * u[i]);
    const double model = out.theta_ref + out.omega * u[i] + 0.5 * out.alpha * u[i] * u[i];
    const double theta = model + std::remainder(std::atan2(ey, ex) - model, 2 * std::numbers::pi);
    out.rows.push_back({p.frame, p.t, p.x, p.y, theta, std::hypot(ex, ey), kNaN, kNaN});
    spin[i].t = p.t;
    spin[i].theta = theta;
    spin[i].omega = spin[i].sigma_omega = kNaN;
  }
  local_spins(spin, options.window);
  for (std::size_t i = 0; i < n; ++i) {
    out.rows[i].omega = spin[i].omega;
    out.rows[i].sigma_omega = spin[i].sigma_omega;
    if (i > 0) out.max_turn = std::max(out.max_turn, std::abs(out.rows[i].theta - out.rows[i - 1].theta));
  }
  out.arc = out.rows.back().theta - out.rows.front().theta;

  // the data must determine the pivot: a short arc fits circles of any radius nearly as well
  if (fit_pivot) {
    const double worst = std::max({out.sigma_pivot_x, out.sigma_pivot_y, out.sigma_radius});
    if (!(worst <= options.max_pivot_sigma * out.radius) && out.rms_residual > 0.3 * out.radius) {
      throw InputError(where, "its points do not lie on a circle about one pivot: they stray from the best one by " +
                                  message_number(out.rms_residual, 2) + " m rms, " + message_number(100 * out.rms_residual / out.radius, 2) +
                                  " % of its radius " + message_number(out.radius, 3) + " m (a point that does not turn, or " +
                                  "moves otherwise); with a pivot known, give it with " + field("pivot_x") + "/" +
                                  field("pivot_y"));
    }
    if (!(worst <= options.max_pivot_sigma * out.radius)) {
      throw InputError(where, "the arc of " + message_number(std::round(to_deg(std::abs(out.arc))), 6) +
                                  " deg it covers does not determine its pivot: the fitted radius " + message_number(out.radius, 3) +
                                  " +- " + message_number(out.sigma_radius, 2) + " m, pivot (" + message_number(out.pivot_x, 3) + " +- " +
                                  message_number(out.sigma_pivot_x, 2) + ", " + message_number(out.pivot_y, 3) + " +- " +
                                  message_number(out.sigma_pivot_y, 2) + ") m (standard errors above " +
                                  message_number(100 * options.max_pivot_sigma, 3) + " % of the radius); give the pivot with " + field("pivot_x") + "/" + field("pivot_y") +
                                  ", or track more of the turn");
    }
  }
  return out;
}

}  // namespace tribolab::track
