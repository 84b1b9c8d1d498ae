#include "incline/inverse.hpp"

#include "incline/closed_form.hpp"
#include "numerics/error.hpp"
#include "numerics/roots.hpp"

#include <boost/math/tools/minima.hpp>

#include <cmath>
#include <limits>
#include <string>

namespace tribolab::incline {

std::string StopMeasurement::validate() const {
  if (!std::isfinite(phi) || !(phi > 0) || !(phi < M_PI / 2))
    return "phi must be in (0, 90) degrees (at phi = 0 the stop carries no information on mu)";
  if (!std::isfinite(x_stop) || !(x_stop > 0))
    return "x_stop must be > 0 (the launch is along +x)";
  if (!std::isfinite(y_stop) || !(y_stop < 0))
    return "y_stop must be < 0 (the disc ends below the launch line); no physical root otherwise";
  if (!std::isfinite(sigma_phi) || sigma_phi < 0) return "sigma_phi must be >= 0";
  if (!std::isfinite(sigma_pos) || sigma_pos < 0) return "sigma_pos must be >= 0";
  if (!std::isfinite(g) || !(g > 0)) return "g must be > 0";
  return {};
}

double k_from_ratio(double r, std::uintmax_t* iterations) {
  if (!std::isfinite(r) || !(r > 0))
    throw InputError("|x_stop/y_stop| must be a finite number > 0, got " + std::to_string(r));
  // Q(k) = 8(1 - k^2) - r k (4 - k^2): Q(0) = 8 > 0, Q(1) = -3r < 0, one root in between.
  auto Q = [r](double k) { return 8 * (1 - k) * (1 + k) - r * k * (4 - k * k); };
  const auto root = numerics::find_root(Q, 0.0, 1.0);
  TRIBOLAB_ASSERT(root.converged, "cubic root for r = " + std::to_string(r));
  if (iterations) *iterations = root.iterations;
  return root.x;
}

double k_from_ratio_seed_formula(double r, bool as_printed_in_main_text) {
  // Seed 000, appendix 十 (10.6) and 陸-四 (十A): with q = 1/r,
  // k = 8q/3 + 2 sqrt(B) cos{(1/3)[acos(A / B^{3/2}) - 2 pi]}, A = 4q/3 + 512 q^3/27,
  // B = 4/3 + 64 q^2/9.
  const double q = 1 / r;
  const double B = 4.0 / 3 + 64.0 / 9 * q * q;
  const double A = 4.0 / 3 * q + 512.0 / 27 * q * q * q;
  const double theta = std::acos(A / std::pow(B, 1.5));
  const double angle = as_printed_in_main_text ? theta / 3 - 2 * M_PI : (theta - 2 * M_PI) / 3;
  return 8 * q / 3 + 2 * std::sqrt(B) * std::cos(angle);
}

MuFromStopResult mu_from_stop(const StopMeasurement& m) {
  const std::string msg = m.validate();
  if (!msg.empty()) throw InputError(msg);
  MuFromStopResult out;
  out.r = -m.x_stop / m.y_stop;
  out.k = k_from_ratio(out.r, &out.iterations);
  const double k = out.k, r = out.r, t = std::tan(m.phi);
  out.mu = t / k;
  // Implicit differentiation of Q(k, r) = r k^3 - 8k^2 - 4rk + 8 = 0.
  const double Q_r = k * k * k - 4 * k;
  const double Q_k = 3 * r * k * k - 16 * k - 4 * r;  // < 0 on (0, 1)
  const double dk_dr = -Q_r / Q_k;
  const double dmu_dr = -t / (k * k) * dk_dr;
  out.dmu_dphi = 1 / (k * std::cos(m.phi) * std::cos(m.phi));
  out.dmu_dx = dmu_dr * (-1 / m.y_stop);
  out.dmu_dy = dmu_dr * (m.x_stop / (m.y_stop * m.y_stop));
  out.sigma_mu = std::sqrt(std::pow(out.dmu_dphi * m.sigma_phi, 2) +
                           (out.dmu_dx * out.dmu_dx + out.dmu_dy * out.dmu_dy) * m.sigma_pos *
                               m.sigma_pos);
  // eq 八: x_stop = 2 v0^2 / (alpha (4 - k^2)).
  const double alpha = m.g * out.mu * std::cos(m.phi);
  out.v0 = std::sqrt(0.5 * m.x_stop * alpha * (2 - k) * (2 + k));
  return out;
}

namespace {

/// Predicted stop point at angle phi under the given constraint.
std::pair<double, double> stop_point(double mu, double phi, double scale,
                                     SetupConstraint constraint, double g) {
  Parameters p;
  p.mu = mu;
  p.phi = phi;
  p.v0 = 1.0;
  p.g = g;
  const Prediction pr = ClosedForm(p).predict();
  double x = *pr.x_stop, y = *pr.y_stop;
  const double f = constraint == SetupConstraint::launch_speed ? scale * scale
                                                                : scale / std::hypot(x, y);
  return {x * f, y * f};
}

double sigma_at(double mu, double phi, double scale, SetupConstraint c, double sigma_phi,
                double sigma_pos, double g) {
  const auto [x, y] = stop_point(mu, phi, scale, c, g);
  StopMeasurement m;
  m.phi = phi;
  m.x_stop = x;
  m.y_stop = y;
  m.sigma_phi = sigma_phi;
  m.sigma_pos = sigma_pos;
  m.g = g;
  return mu_from_stop(m).sigma_mu;
}

}  // namespace

double stop_method_sigma_mu(double mu, double phi, double v0, double sigma_phi,
                            double sigma_pos, double g) {
  return sigma_at(mu, phi, v0, SetupConstraint::launch_speed, sigma_phi, sigma_pos, g);
}

AngleAdvice best_angle(double mu, double scale, SetupConstraint constraint, double sigma_phi,
                       double sigma_pos, double max_stop_distance, double g) {
  if (!std::isfinite(mu) || !(mu > 0)) throw InputError("mu must be > 0");
  if (!std::isfinite(scale) || !(scale > 0))
    throw InputError(constraint == SetupConstraint::launch_speed ? "v0 must be > 0"
                                                                 : "stop distance must be > 0");
  if (!std::isfinite(sigma_phi) || sigma_phi < 0 || !std::isfinite(sigma_pos) || sigma_pos < 0 ||
      !(sigma_phi > 0 || sigma_pos > 0))
    throw InputError("sigma_phi and sigma_pos must be >= 0 and not both 0");
  if (!(max_stop_distance > 0)) throw InputError("max stop distance must be > 0");
  // The disc stops only for phi < atan(mu); stay a hair inside (0, atan(mu)).
  double hi = std::atan(mu) * (1 - 1e-6);
  const double lo = hi * 1e-6;
  if (constraint == SetupConstraint::launch_speed && std::isfinite(max_stop_distance)) {
    // The stop distance grows with phi at fixed v0 (both |x_stop| and |y_stop| do).
    auto excess = [&](double phi) {
      const auto [x, y] = stop_point(mu, phi, scale, constraint, g);
      return std::hypot(x, y) - max_stop_distance;
    };
    if (excess(lo) >= 0)
      throw InputError("the disc cannot stop within the maximum stop distance at any angle");
    if (excess(hi) > 0) hi = numerics::find_root(excess, lo, hi).x;
  }
  auto f = [&](double phi) { return sigma_at(mu, phi, scale, constraint, sigma_phi, sigma_pos, g); };
  // Coarse scan (sigma_mu may have several local minima), then Brent around the best cell.
  constexpr int n = 400;
  int best = 0;
  double best_val = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= n; ++i) {
    const double v = f(lo + (hi - lo) * i / n);
    if (v < best_val) {
      best_val = v;
      best = i;
    }
  }
  const double a = lo + (hi - lo) * std::max(0, best - 1) / n;
  const double b = lo + (hi - lo) * std::min(n, best + 1) / n;
  std::uintmax_t iters = 200;
  const auto [phi, val] = boost::math::tools::brent_find_minima(f, a, b, 40, iters);
  AngleAdvice out;
  out.phi = phi;
  out.phi_max = hi;
  out.at_boundary = phi > hi * (1 - 1e-6);
  out.sigma_mu = val;
  out.iterations = iters;
  const auto [x, y] = stop_point(mu, phi, scale, constraint, g);
  out.x_stop = x;
  out.y_stop = y;
  return out;
}

}  // namespace tribolab::incline
