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

namespace {

/// The points' times about their mean and positions (the fit's data).
struct PivotSamples {
  double t_ref = 0;           ///< s, mean time
  std::vector<double> u;      ///< t - t_ref, s
  std::vector<double> x, y;   ///< m
};

/// A start of the pivot: at t_ref and its velocity, m and m/s.
struct PivotStart {
  double px = 0, py = 0, vx = 0, vy = 0;
};

/// The angles about the starting pivot, unwrapped, their mean radius and the line through them.
struct AngleStart {
  std::vector<double> th;  ///< rad
  double r0 = 0;           ///< m
  double th0 = 0, w0 = 0;  ///< rad at t_ref, rad/s
};

/// The joint fit, and the circle's (made for a fitted fixed pivot; its pivot used when
/// out.pivot_from_circle).
struct PivotFits {
  numerics::FitResult fit, circle;
};

/// Throws unless the track has enough points for the model.
void check_enough_points(const Track& track, const PivotOptions& options) {
  const std::size_t n = track.points.size();
  const std::size_t least = options.moving_pivot ? 8 : 6;
  if (n < least) {
    throw InputError("track '" + track.name + "' has " + std::to_string(n) + " point(s); at least " +
                     std::to_string(least) + " are needed for a rotation about " +
                     (options.moving_pivot ? "a moving pivot" : "a pivot"));
  }
}

/// The track's times about their mean and its positions.
PivotSamples samples_of(const Track& track) {
  const std::size_t n = track.points.size();
  PivotSamples s;
  s.u.resize(n), s.x.resize(n), s.y.resize(n);
  for (const auto& p : track.points) s.t_ref += p.t;
  s.t_ref /= static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i) {
    s.u[i] = track.points[i].t - s.t_ref;
    s.x[i] = track.points[i].x;
    s.y[i] = track.points[i].y;
  }
  return s;
}

/// The pivot given, or Kasa's circle of the points (detrended when the pivot moves, `kasa` set).
PivotStart start_pivot(const Track& track, const PivotOptions& options, const PivotSamples& s, Circle& kasa) {
  const std::size_t n = s.u.size();
  const std::vector<double>& u = s.u;
  const std::vector<double>& x = s.x;
  const std::vector<double>& y = s.y;
  PivotStart p;
  p.px = options.pivot_x, p.py = options.pivot_y;
  if (!options.pivot_given()) {
    std::vector<double> dx = x, dy = y;
    double ax = 0, ay = 0;
    if (options.moving_pivot) {
      std::tie(ax, p.vx) = line(u, x);
      std::tie(ay, p.vy) = line(u, y);
      for (std::size_t i = 0; i < n; ++i) {
        dx[i] = x[i] - (ax + p.vx * u[i]);
        dy[i] = y[i] - (ay + p.vy * u[i]);
      }
    }
    kasa = kasa_circle(dx, dy);
    if (!std::isfinite(kasa.r)) {
      throw InputError("track '" + track.name + "' lies on a straight line: it turns about no pivot");
    }
    p.px = ax + kasa.x;
    p.py = ay + kasa.y;
  }
  return p;
}

/// The angles about the starting pivot, unwrapped to the nearest branch, and a line through them.
AngleStart angles_about(const PivotSamples& s, const PivotStart& p) {
  const std::size_t n = s.u.size();
  const std::vector<double>& u = s.u;
  AngleStart a;
  a.th.resize(n);
  std::vector<double>& th = a.th;
  for (std::size_t i = 0; i < n; ++i) {
    const double ex = s.x[i] - (p.px + p.vx * u[i]), ey = s.y[i] - (p.py + p.vy * u[i]);
    th[i] = std::atan2(ey, ex);
    if (i > 0) th[i] += 2 * std::numbers::pi * std::round((th[i - 1] - th[i]) / (2 * std::numbers::pi));
    a.r0 += std::hypot(ex, ey);
  }
  a.r0 /= static_cast<double>(n);
  std::tie(a.th0, a.w0) = line(u, th);
  return a;
}

/// The joint fit of pivot and angle model; for a swinging pendulum, refitted about the circle's pivot.
PivotFits fit_rotation(const PivotSamples& s, const PivotOptions& options, const PivotStart& p, const AngleStart& a,
                       bool& pivot_from_circle) {
  const std::size_t n = s.u.size();
  const bool fit_pivot = !options.pivot_given();
  std::vector<numerics::FitParameter> params{
      {"pivot_x", p.px, {}, {}, !fit_pivot},          {"pivot_y", p.py, {}, {}, !fit_pivot},
      {"pivot_vx", p.vx, {}, {}, !options.moving_pivot}, {"pivot_vy", p.vy, {}, {}, !options.moving_pivot},
      {"radius", a.r0, 0.0, {}, false},               {"theta_ref", a.th0, {}, {}, false},
      {"omega", a.w0, {}, {}, false},                 {"alpha", 0, {}, {}, false}};
  PivotFits f;
  f.fit = numerics::fit_least_squares_autodiff(PivotModel{&s.u, &s.x, &s.y}, static_cast<int>(2 * n), params);
  // A pendulum's angle swings: no quadratic theta(t) follows it and the joint fit's residuals
  // exceed the noise. The circle alone (geometric fit, no time) then places the pivot, and the
  // angle model is refitted about it (omega, alpha only summarise; the local spins hold).
  if (fit_pivot && !options.moving_pivot) {
    f.circle = numerics::fit_least_squares_autodiff(
        CircleModel{&s.x, &s.y}, static_cast<int>(n),
        {{"pivot_x", p.px, {}, {}, false}, {"pivot_y", p.py, {}, {}, false}, {"radius", a.r0, 0.0, {}, false}});
    const auto rms = [](const numerics::FitResult& r) { return r.dof > 0 ? std::sqrt(2 * r.cost / r.dof) : kNaN; };
    // per coordinate and radially both estimate the noise sigma; twice it is a clear misfit
    if (f.circle.ok() && (!f.fit.ok() || rms(f.fit) > 2 * rms(f.circle))) {
      pivot_from_circle = true;
      for (auto& q : params) {
        if (q.name == "pivot_x" || q.name == "pivot_y" || q.name == "radius") q.initial = f.circle.value(q.name);
        if (q.name == "pivot_x" || q.name == "pivot_y") q.fixed = true;
      }
      f.fit = numerics::fit_least_squares_autodiff(PivotModel{&s.u, &s.x, &s.y}, static_cast<int>(2 * n), params);
    }
  }
  return f;
}

/// The fitted values and standard errors into `out` (the pivot's errors from the circle when it placed it).
void take_fit(PivotRotation& out, const PivotFits& f) {
  const numerics::FitResult& fit = f.fit;
  out.pivot_x = fit.value("pivot_x");
  out.pivot_y = fit.value("pivot_y");
  out.sigma_pivot_x = out.pivot_from_circle ? f.circle.sigma_of("pivot_x") : fit.sigma_of("pivot_x");
  out.sigma_pivot_y = out.pivot_from_circle ? f.circle.sigma_of("pivot_y") : fit.sigma_of("pivot_y");
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
}

/// The rows: angle about the fitted pivot, on the branch of the fitted theta(t), local spins, arc and largest turn.
void add_rows(PivotRotation& out, const Track& track, const PivotSamples& s, int window) {
  const std::size_t n = s.u.size();
  const std::vector<double>& u = s.u;
  std::vector<RigidBodyRow> spin(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = track.points[i];
    const double ex = s.x[i] - (out.pivot_x + out.pivot_vx * u[i]), ey = s.y[i] - (out.pivot_y + out.pivot_vy * u[i]);
    const double model = out.theta_ref + out.omega * u[i] + 0.5 * out.alpha * u[i] * u[i];
    const double theta = model + std::remainder(std::atan2(ey, ex) - model, 2 * std::numbers::pi);
    out.rows.push_back({p.frame, p.t, p.x, p.y, theta, std::hypot(ex, ey), kNaN, kNaN});
    spin[i].t = p.t;
    spin[i].theta = theta;
    spin[i].omega = spin[i].sigma_omega = kNaN;
  }
  local_spins(spin, window);
  for (std::size_t i = 0; i < n; ++i) {
    out.rows[i].omega = spin[i].omega;
    out.rows[i].sigma_omega = spin[i].sigma_omega;
    if (i > 0) out.max_turn = std::max(out.max_turn, std::abs(out.rows[i].theta - out.rows[i - 1].theta));
  }
  out.arc = out.rows.back().theta - out.rows.front().theta;
}

/// Throws unless the data determine the fitted pivot (`where`: the track, for the message).
void check_pivot_determined(const PivotRotation& out, const PivotOptions& options, const std::string& where) {
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

}  // namespace

PivotRotation rotation_about_pivot(const Track& track, const PivotOptions& options) {
  if (const auto err = options.validate(); !err.empty()) throw InputError(err);
  validate_track(track, "");
  check_enough_points(track, options);
  PivotRotation out;
  out.track = track.name;
  const PivotSamples s = samples_of(track);
  out.t_ref = s.t_ref;
  // start: the pivot (given, or Kasa's circle of the points, detrended when the pivot moves)
  const PivotStart start = start_pivot(track, options, s, out.kasa);
  // angles about the starting pivot, unwrapped to the nearest branch, and a line through them
  const AngleStart angles = angles_about(s, start);
  const bool fit_pivot = !options.pivot_given();
  const PivotFits fits = fit_rotation(s, options, start, angles, out.pivot_from_circle);
  const numerics::FitResult& fit = fits.fit;
  const std::string where = "track '" + track.name + "'";
  const double arc_start = angles.th.back() - angles.th.front();
  if (!fit.ok()) {
    throw InputError(where, std::string("the rotation about ") + (fit_pivot ? "a fitted pivot" : "the given pivot") +
                                " could not be fitted (" + fit.message + "); the arc covers " +
                                message_number(std::round(to_deg(std::abs(arc_start))), 6) + " deg" +
                                (fit_pivot ? ": give the pivot with " + field("pivot_x") + "/" + field("pivot_y")
                                           : std::string()));
  }
  take_fit(out, fits);
  // rows: angle about the fitted pivot, on the branch of the fitted theta(t)
  add_rows(out, track, s, options.window);
  // the data must determine the pivot: a short arc fits circles of any radius nearly as well
  if (fit_pivot) check_pivot_determined(out, options, where);
  return out;
}

}  // namespace tribolab::track
