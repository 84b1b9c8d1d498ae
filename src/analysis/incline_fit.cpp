#include "analysis/incline_fit.hpp"

#include "numerics/message_number.hpp"
#include "track/outliers.hpp"

#include "analysis/frame_rotation.hpp"
#include "incline/inverse.hpp"
#include "incline/numeric.hpp"
#include "numerics/error.hpp"
#include "numerics/units.hpp"

#include <boost/math/distributions/fisher_f.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace tribolab::analysis {
namespace {

Estimate estimate(const numerics::FitResult& f, std::size_t i, double level) {
  const double h = f.ci_half_width(i, level);
  return {f.values[i], f.sigma[i], f.values[i] - h, f.values[i] + h};
}

incline::Parameters launch(double mu, double phi, double v0, double g, double normal_accel = 0) {
  incline::Parameters p;
  p.mu = mu;
  p.phi = phi;
  p.v0 = v0;
  p.g = g;
  p.normal_accel = normal_accel;
  return p;
}

std::string where(const track::Track& t) { return "track '" + t.name + "'"; }

/// Bound of the fitted frame rotation, rad (20 deg): a camera turned further is not a small
/// misalignment (and the launch would not be "along +x").
constexpr double kMaxFrameRotation = 0.35;

/// Rough starting values read off the data: launch time and point, speed, friction.
struct Guess {
  double t0, x0, y0, v0;
  std::optional<double> mu_from_stop;
  double noise;
};

Guess initial_guess(const track::Track& track, const InclineFitOptions& o, double noise) {
  const auto& p = track.points;
  const std::size_t n = p.size();
  double range = 0;
  for (const auto& q : p) range = std::max(range, std::hypot(q.x - p[0].x, q.y - p[0].y));
  const double threshold = std::max(5 * noise, 0.01 * range);
  std::size_t m = 0;  // first moving point
  while (m < n && std::hypot(p[m].x - p[0].x, p[m].y - p[0].y) <= threshold) ++m;
  Guess g{};
  g.noise = noise;
  if (m >= n) m = n - 1;
  if (m >= 1) {
    double sx = 0, sy = 0;
    for (std::size_t i = 0; i < m; ++i) sx += p[i].x, sy += p[i].y;
    g.x0 = sx / m;
    g.y0 = sy / m;
    g.t0 = p[m - 1].t;
  } else {
    g.x0 = p[0].x;
    g.y0 = p[0].y;
    g.t0 = p[0].t;
  }
  const std::size_t q = std::min(n - 1, m + 4);
  g.v0 = q > m ? std::hypot(p[q].x - p[m].x, p[q].y - p[m].y) / (p[q].t - p[m].t) : 1.0;
  if (!(g.v0 > 0) || !std::isfinite(g.v0)) g.v0 = 1.0;
  // Stopped: the last points agree within the threshold; eq 十A from the stop point.
  const auto& last = p[n - 1];
  const auto& before = p[n >= 4 ? n - 4 : 0];
  if (o.phi > 0 && std::hypot(last.x - before.x, last.y - before.y) <= threshold) {
    incline::StopMeasurement sm;
    sm.phi = o.phi;
    sm.x_stop = last.x - g.x0;
    sm.y_stop = last.y - g.y0;
    sm.g = o.g;
    if (sm.x_stop > 0 && sm.y_stop < 0) {
      try {
        g.mu_from_stop = incline::mu_from_stop(sm).mu;
      } catch (const Error&) {  // no stop estimate: the fit starts elsewhere
      }
    }
  }
  return g;
}

std::vector<double> times_of(const track::Track& t) {
  std::vector<double> v;
  for (const auto& p : t.points) v.push_back(p.t);
  return v;
}

std::vector<double> fine_grid(const std::vector<double>& t, int n = 400) {
  std::vector<double> g(n);
  for (int i = 0; i < n; ++i) g[i] = t.front() + (t.back() - t.front()) * i / (n - 1);
  return g;
}

}  // namespace

std::string InclineFitOptions::validate() const {
  if (!(std::isfinite(phi) && phi >= 0 && phi < M_PI / 2)) return "phi must be in [0, 90) degrees";
  if (!(std::isfinite(g) && g > 0)) return "g must be > 0";
  if (!(level > 0 && level < 1)) return "level must be in (0, 1)";
  if (!(significance > 0 && significance < 1)) return "significance must be in (0, 1)";
  if (min_points < 8) return "min_points must be >= 8";
  if (diagnostic_block != 0 && diagnostic_block < 5) return "diagnostic block must be 0 (auto) or >= 5 points";
  if (!(ode_tolerance > 0 && ode_tolerance < 1e-4)) return "ode_tolerance must be in (0, 1e-4)";
  return {};
}

std::vector<incline::State> model_b_states(const incline::Parameters& p, double t0, double x0,
                                           double y0, const std::vector<double>& t, double psi) {
  const incline::ClosedForm cf(p);
  std::vector<incline::State> out;
  out.reserve(t.size());
  for (double ti : t) {
    incline::State s;  // at rest before the launch
    if (ti > t0) s = cf.at(ti - t0);
    s.t = ti;
    out.push_back(rotate_state(s, psi, x0, y0));
  }
  return out;
}

track::Track derotate_track(const track::Track& track, double psi, double x0, double y0) {
  track::Track r = track;
  const double c = std::cos(psi), n = std::sin(psi);
  for (auto& q : r.points) {
    const double u = q.x - x0, v = q.y - y0;
    q.x = x0 + c * u + n * v;
    q.y = y0 - n * u + c * v;
  }
  return r;
}

std::vector<incline::State> model_a_states(const incline::Parameters& p, double t0, double x0,
                                           double y0, const std::vector<double>& t, double tol,
                                           double psi) {
  std::vector<double> rel;
  for (double ti : t)
    if (ti > t0) rel.push_back(ti - t0);
  incline::NumericOptions no;
  no.model = incline::Model::A;
  no.abs_tol = tol;
  no.rel_tol = tol;
  std::vector<incline::State> moving;
  if (!rel.empty()) {
    const auto r = incline::simulate(p, rel, no);
    if (r.status == incline::NumericStatus::failed)
      throw SolverError("model A", "integration failed: " + r.message);
    moving = r.samples;
  }
  std::vector<incline::State> out;
  out.reserve(t.size());
  std::size_t m = 0;
  for (double ti : t) {
    incline::State s;
    if (ti > t0) s = moving.at(m++);
    s.t = ti;
    out.push_back(rotate_state(s, psi, x0, y0));
  }
  return out;
}

namespace {

/// Model B's residuals (data - model, x then y) for q = (mu, v0, x0, y0, t0, psi) at gravity g;
/// false where the model is undefined (the least squares then shortens its step).
bool model_b_residuals(const std::vector<track::TrackPoint>& pts, const std::vector<double>& t, double phi,
                       const double* q, double g, double* r) {
  if (!(q[0] > 0 && q[1] > 0) || !std::isfinite(q[4]) || !std::isfinite(q[5])) return false;
  try {
    const auto s = model_b_states(launch(q[0], phi, q[1], g), q[4], q[2], q[3], t, q[5]);
    const std::size_t n = pts.size();
    for (std::size_t i = 0; i < n; ++i) {
      r[i] = pts[i].x - s[i].x;
      r[n + i] = pts[i].y - s[i].y;
    }
  } catch (const std::exception&) {
    return false;
  }
  return true;
}

// Residuals r[0..n) (x) and r[n..2n) (y), each in time order: correlated in time (a tracker's
// smooth error, a model that misses part of the motion), they widen the covariance
// (docs/theory.md#fitting, "Serially correlated residuals").
void widen_for_correlated_residuals(numerics::FitResult& f, int n) {
  const auto& r = f.residuals;
  if (r.size() != static_cast<std::size_t>(2 * n)) return;
  const std::vector<std::vector<double>> series{{r.begin(), r.begin() + n}, {r.begin() + n, r.end()}};
  numerics::widen_for_serial_correlation(f, numerics::serial_correlation_factor(series));
}

}  // namespace

ModelBFit fit_model_b(const track::Track& track, const InclineFitOptions& o) {
  if (const std::string e = o.validate(); !e.empty()) throw InputError("incline analyze", e);
  track::validate_track(track, where(track));
  const auto& pts = track.points;
  const int n = static_cast<int>(pts.size());
  if (n < o.min_points)
    throw InputError(where(track), "has " + std::to_string(n) + " points; the model fit needs at least " +
                                       std::to_string(o.min_points));
  const track::Kinematics kin = track::differentiate(track);
  const double noise = std::max({kin.noise_x, kin.noise_y, 1e-6});
  double range = 0;
  for (const auto& q : pts) range = std::max(range, std::hypot(q.x - pts[0].x, q.y - pts[0].y));
  if (!(range > 10 * noise))
    throw InputError(where(track), "shows no motion (largest displacement " + message_number(range, 4) +
                                       " m, position noise " + message_number(noise, 4) + " m)");
  if (!(pts.back().x > pts.front().x + 5 * noise))
    throw InputError(where(track), "does not move toward +x; the analysis assumes the launch along +x "
                                   "(mirror the x axis)");
  const Guess g = initial_guess(track, o, noise);
  const std::vector<double> t = times_of(track);

  auto residuals = [&](const double* q, double* r) { return model_b_residuals(pts, t, o.phi, q, o.g, r); };
  // Starting friction values: the stop point (eq 十A) first, then a spread of k.
  std::vector<double> mu_starts;
  if (g.mu_from_stop) mu_starts.push_back(*g.mu_from_stop);
  for (double k : {0.5, 0.85, 0.2, 1.5})
    mu_starts.push_back(o.phi > 0 ? std::tan(o.phi) / k : 0.3 / k);
  numerics::FitResult best;
  bool have = false;
  for (double mu0 : mu_starts) {
    std::vector<numerics::FitParameter> params{
        {"mu", mu0, 1e-6, 20.0, false},
        {"v0", g.v0, 1e-6, 100.0, false},
        {"x0", g.x0, std::nullopt, std::nullopt, false},
        {"y0", g.y0, std::nullopt, std::nullopt, false},
        {"t0", g.t0, t.front() - 5.0, t.back(), false},
        {"frame_rotation", 0.0, -kMaxFrameRotation, kMaxFrameRotation, !o.fit_frame_rotation},
    };
    numerics::FitResult f = numerics::fit_least_squares(residuals, 2 * n, params);
    // Keep the best: a converged fit over any other, then the lower cost.
    const bool better = !have || (f.ok() != best.ok() ? f.ok() : f.cost < best.cost);
    if (better) {
      best = std::move(f);
      have = true;
    }
    // A fit at the noise level is the global minimum for practical purposes.
    if (best.ok() && best.rms < 2.0 * noise) break;
  }
  if (!best.ok())
    numerics::throw_fit_failure(best, where(track), "model B cannot be fitted: " + best.message);
  widen_for_correlated_residuals(best, n);
  ModelBFit r;
  r.fit = best;
  r.mu = estimate(best, 0, o.level);
  r.v0 = estimate(best, 1, o.level);
  r.x0 = estimate(best, 2, o.level);
  r.y0 = estimate(best, 3, o.level);
  r.t0 = estimate(best, 4, o.level);
  r.frame_rotation = estimate(best, 5, o.level);
  r.rms_residual = best.rms;
  r.rss = 2 * best.cost;
  r.dof = best.dof;
  r.iterations = best.iterations;
  const incline::ClosedForm cf(launch(r.mu.value, o.phi, r.v0.value, o.g));
  const incline::Prediction pr = cf.predict();
  if (pr.t_stop) {
    incline::State stop;
    stop.x = *pr.x_stop;
    stop.y = *pr.y_stop;
    stop = rotate_state(stop, r.frame_rotation.value, r.x0.value, r.y0.value);
    r.t_stop = r.t0.value + *pr.t_stop;
    r.x_stop = stop.x;
    r.y_stop = stop.y;
  }
  return r;
}

ModelAFit fit_model_a(const track::Track& track, const InclineFitOptions& o, const ModelBFit& start) {
  if (const std::string e = o.validate(); !e.empty()) throw InputError("incline analyze", e);
  const auto& pts = track.points;
  const int n = static_cast<int>(pts.size());
  const std::vector<double> t = times_of(track);
  auto residuals = [&](const double* q, double* r) {
    if (!(q[0] > 0 && q[1] > 0) || !std::isfinite(q[4]) || !std::isfinite(q[5]) || !std::isfinite(q[6]))
      return false;
    try {
      const auto s = model_a_states(launch(q[0], o.phi, q[1], o.g, q[5]), q[4], q[2], q[3], t,
                                    o.ode_tolerance, q[6]);
      for (int i = 0; i < n; ++i) {
        r[i] = pts[i].x - s[i].x;
        r[n + i] = pts[i].y - s[i].y;
      }
    } catch (const std::exception&) {
      return false;
    }
    return true;
  };
  const double accel_bound = 10 * o.g;
  std::vector<numerics::FitParameter> params{
      {"mu", start.mu.value, 1e-6, 20.0, false},
      {"v0", start.v0.value, 1e-6, 100.0, false},
      {"x0", start.x0.value, std::nullopt, std::nullopt, false},
      {"y0", start.y0.value, std::nullopt, std::nullopt, false},
      {"t0", start.t0.value, t.front() - 5.0, t.back(), false},
      {"normal_accel", 0.0, -accel_bound, accel_bound, false},
      {"frame_rotation", start.frame_rotation.value, -kMaxFrameRotation, kMaxFrameRotation,
       !o.fit_frame_rotation},
  };
  numerics::FitOptions fo;
  // The integrator's error (~tolerance) limits how flat the cost can be resolved.
  fo.function_tolerance = 1e-10;
  fo.parameter_tolerance = 1e-9;
  fo.gradient_tolerance = 1e-12;
  fo.max_iterations = 100;
  numerics::FitResult f = numerics::fit_least_squares(residuals, 2 * n, params, fo);
  if (!f.ok()) numerics::throw_fit_failure(f, where(track), "model A cannot be fitted: " + f.message);
  widen_for_correlated_residuals(f, n);
  ModelAFit r;
  r.fit = f;
  r.mu = estimate(f, 0, o.level);
  r.v0 = estimate(f, 1, o.level);
  r.x0 = estimate(f, 2, o.level);
  r.y0 = estimate(f, 3, o.level);
  r.t0 = estimate(f, 4, o.level);
  r.normal_accel = estimate(f, 5, o.level);
  r.frame_rotation = estimate(f, 6, o.level);
  if (o.fit_frame_rotation) {
    const double v55 = f.covariance(5, 5), v66 = f.covariance(6, 6);
    if (v55 > 0 && v66 > 0) r.rotation_correlation = f.covariance(5, 6) / std::sqrt(v55 * v66);
  }
  r.rms_residual = f.rms;
  r.rss = 2 * f.cost;
  r.dof = f.dof;
  r.iterations = f.iterations;
  return r;
}

namespace {

/// The check from the fitted g (m/s^2, in the file's time) and the refit's rms (m).
GravityCheck make_check(const Estimate& g, double rms, const InclineFitOptions& o) {
  constexpr double kMinPhi = to_rad(3.0);  // below, g sin(phi) is too small to separate g from mu
  GravityCheck c;
  c.g = g;
  c.ratio = c.g.value / o.g;
  c.time_factor = std::sqrt(c.ratio);
  c.g_identifiable = o.phi >= kMinPhi;
  c.implausible = c.g_identifiable && std::abs(c.ratio - 1) > 0.25 && std::abs(c.g.value - o.g) > 3 * c.g.sigma;
  // sin(phi_fit) = (g_fit / g) sin(phi): the same fit read with g held and phi free.
  auto angle = [&](double g_fit) {
    const double s = g_fit / o.g * std::sin(o.phi);
    return s >= 0 && s <= 1 ? std::asin(s) : NAN;
  };
  c.phi.value = angle(c.g.value);
  c.phi.ci_low = angle(c.g.ci_low);
  c.phi.ci_high = angle(c.g.ci_high);
  c.phi.sigma = std::sin(o.phi) * c.g.sigma / o.g / std::cos(c.phi.value);
  c.rms = rms;
  return c;
}

/// Model B refitted with g free from the starts `q` = (mu, v0, x0, y0, t0, psi, g0) (several:
/// the best converged fit is kept); g0 = 0 tries the g given scaled by the usual slow-motion
/// factors; see check_gravity.
std::optional<GravityCheck> gravity_refit(const track::Track& track, const InclineFitOptions& o,
                                          const std::vector<std::array<double, 7>>& starts) {
  if (!(o.phi > 0)) return std::nullopt;  // g sin(phi) = 0: g only scales mu g cos(phi)
  const auto& pts = track.points;
  const int n = static_cast<int>(pts.size());
  const std::vector<double> t = times_of(track);
  const track::Kinematics kin = track::differentiate(track);
  const double noise = std::max({kin.noise_x, kin.noise_y, 1e-6});
  auto residuals = [&](const double* q, double* r) {
    return q[6] > 0 && model_b_residuals(pts, t, o.phi, q, q[6], r);
  };
  numerics::FitResult best;
  bool have = false;
  // Time wrong by a factor c scales every acceleration by 1/c^2: start at the g given and at
  // the usual slow-motion factors both ways (64: a slow-motion factor 8 applied the wrong way),
  // and keep the best converged fit.
  for (const auto& q : starts) {
    const std::vector<double> factors = q[6] > 0 ? std::vector<double>{1.0}
                                                 : std::vector<double>{1.0, 8.0, 0.125, 4.0, 0.25, 16.0, 0.0625, 2.0, 0.5};
    for (double c : factors) {
      const double g0 = (q[6] > 0 ? q[6] : o.g) / (c * c);
      std::vector<numerics::FitParameter> params{
          {"mu", q[0], 1e-6, 1e3, false},
          {"v0", q[1], 1e-9, 1e4, false},
          {"x0", q[2], std::nullopt, std::nullopt, false},
          {"y0", q[3], std::nullopt, std::nullopt, false},
          {"t0", q[4], t.front() - 5.0, t.back(), false},
          {"frame_rotation", q[5], -kMaxFrameRotation, kMaxFrameRotation, !o.fit_frame_rotation},
          {"g", g0, 1e-6 * o.g, 1e6 * o.g, false},
      };
      numerics::FitResult f = numerics::fit_least_squares(residuals, 2 * n, params);
      if (f.ok() && (!have || f.cost < best.cost)) {
        best = std::move(f);
        have = true;
      }
      if (have && best.rms < 2.0 * noise) break;  // at the noise level: the global minimum in practice
    }
    if (have && best.rms < 2.0 * noise) break;
  }
  if (!have) return std::nullopt;
  widen_for_correlated_residuals(best, n);
  return make_check(estimate(best, 6, o.level), best.rms, o);
}

}  // namespace

std::optional<GravityCheck> check_gravity(const track::Track& track, const InclineFitOptions& o,
                                          const ModelBFit& b) {
  auto c = gravity_refit(track, o, {{b.mu.value, b.v0.value, b.x0.value, b.y0.value, b.t0.value, b.frame_rotation.value, 0.0}});
  // g not determined (sigma above the value): model B with the g given found no real minimum
  // (times 64x off: g = 1.5 +- 44); the refit from the time-scaled fits below may do better.
  if (c && c->g.sigma < c->g.value) return c;
  auto d = check_gravity(track, o);
  return d && (!c || d->rms < c->rms) ? d : c;
}

std::optional<GravityCheck> check_gravity(const track::Track& track, const InclineFitOptions& o) {
  // Model B with the g given, fitted to the track with its times multiplied by c (the usual
  // slow-motion factors and their squares both ways): a wrong time scale c is exactly g given
  // as g c^2 in the file's time, so the fit that reaches the noise level names the start of the
  // g-free refit. Plain starts read off the data come last.
  // The refit runs on the scaled track (sane units for the solver) and its g is taken back to
  // the file's time: g_file = g_scaled c^2 (the model is exactly covariant under t -> c t).
  // 64 first: with times 8x off model B still fits (mu at its bound), so a fit that fails
  // outright has the times further off, most often 8x applied the wrong way.
  for (double c : {1 / 64.0, 64.0, 0.125, 8.0, 0.25, 4.0, 0.0625, 16.0, 0.5, 2.0}) {
    track::Track scaled = track;
    for (auto& p : scaled.points) p.t *= c;
    try {
      const ModelBFit f = fit_model_b(scaled, o);
      // The noise as the scaled track shows it (the kinematics' windows are in seconds).
      const track::Kinematics k = track::differentiate(scaled);
      if (!(f.rms_residual < 2.0 * std::max({k.noise_x, k.noise_y, 1e-6}))) continue;
      const auto r = gravity_refit(scaled, o, {{f.mu.value, f.v0.value, f.x0.value, f.y0.value, f.t0.value,
                                                f.frame_rotation.value, o.g}});
      if (!r) continue;
      const double c2 = c * c;
      return make_check({r->g.value * c2, r->g.sigma * c2, r->g.ci_low * c2, r->g.ci_high * c2}, r->rms, o);
    } catch (const Error&) {  // not this factor
    }
  }
  const track::Kinematics kin = track::differentiate(track);
  const Guess g = initial_guess(track, o, std::max({kin.noise_x, kin.noise_y, 1e-6}));
  std::vector<std::array<double, 7>> starts;
  for (double k : {0.5, 0.85, 0.2}) starts.push_back({std::tan(o.phi) / k, g.v0, g.x0, g.y0, g.t0, 0.0, 0.0});
  return gravity_refit(track, o, starts);
}


std::string gravity_warning(const GravityCheck& c, const InclineFitOptions& o, bool frame_turned) {
  const double given_deg = to_deg(o.phi);
  const bool angle_known = std::isfinite(c.phi.value) && std::isfinite(c.phi.sigma);
  // The angle the data show, and whether the given one contradicts it: 3 sd and half a degree
  // (a protractor's reading) apart.
  const bool angle_contradicted = angle_known && std::abs(c.phi.value - o.phi) > 3 * c.phi.sigma + to_rad(0.5);
  // The angle to the sigma's second significant digit (20.996 +- 0.086, 0.005013 +- 0.000020).
  auto angle_text = [&] {
    const double v = to_deg(c.phi.value), sd = to_deg(c.phi.sigma);
    const int decimals = sd > 0 ? std::clamp(1 - static_cast<int>(std::floor(std::log10(sd))), 0, 9) : 4;
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.*f +- %.*f deg", decimals, v, decimals, sd);
    return std::string(buf);
  };
  const std::string angle_fit = angle_known ? angle_text() : std::string("no angle (g sin(phi) exceeds g)");
  // Radians typed as degrees: a value below pi/2 whose reading as radians the data support
  // better than its reading as degrees.
  if (angle_contradicted && given_deg <= M_PI / 2 &&
      std::abs(c.phi.value - given_deg) < std::abs(c.phi.value - o.phi)) {
    return "the incline angle " + field("phi_deg") + " = " + message_number(given_deg, 4) + " deg contradicts the data, which show phi = " + angle_fit +
           " (with g = " + message_number(o.g, 4) + " m/s^2, from the pull down the slope): " + message_number(given_deg, 4) +
           " looks like the angle in radians (" + message_number(given_deg, 4) + " rad = " + message_number(to_deg(given_deg), 4) +
           " deg). Give " + field("phi_deg") + " in degrees; mu, v0 and the normal friction verdict are fitted with " + message_number(given_deg, 4) +
           " deg and are wrong until then";
  }
  if (c.implausible)
    return "the data show gravity g = " + message_number(c.g.value, 4) + " +- " + message_number(c.g.sigma, 4) + " m/s^2, not " + message_number(o.g, 4) +
           ": the times, the lengths or the incline angle are wrong. If lengths and angle are right, the file's times "
           "must be multiplied by " + message_number(c.time_factor, 3) + " (e.g. " + field("time_scale") + " " + message_number(c.time_factor, 3) +
           " times the one used; slow motion analysed as real time gives 1/8 at 240 fps played at 30); if times and "
           "lengths are right, " +
           (angle_known ? "the incline is at " + angle_fit + ", not " + message_number(given_deg, 4) + " deg"
                        : std::string("no incline angle explains them (the pull down the slope exceeds g)"));
  if (c.g_identifiable && std::abs(c.g.value - o.g) > 3 * c.g.sigma + 0.03)
    // Not gross but significant (3 sd, and beyond the 9.78-9.83 m/s^2 of the Earth's
    // surface): a frame rate off by k % moves g by 2k % and mu with it, by more than its
    // stated uncertainty (docs/theory.md#plausibility-checks).
    return "the data show gravity g = " + message_number(c.g.value, 4) + " +- " + message_number(c.g.sigma, 4) + " m/s^2, not " + message_number(o.g, 4) +
           ": check the frame rate (" + field("time_scale") + "; an error of k % in it changes g by 2k %), the length calibration "
           "and the incline angle (with g = " + message_number(o.g, 4) + " m/s^2 the data show phi = " + angle_fit + ", not " +
           message_number(given_deg, 4) + " deg); mu and v0 are fitted with g = " + message_number(o.g, 4) +
           " and are off by more than their uncertainties until this is fixed" +
           (frame_turned ? std::string(" (or the turned camera frame warned about above)") : std::string());
  if (angle_contradicted)  // below 3 deg: g is not told apart from mu, but the angle is
    return "the incline angle " + field("phi_deg") + " = " + message_number(given_deg, 4) + " deg contradicts the data, which show phi = " + angle_fit +
           " (with g = " + message_number(o.g, 4) + " m/s^2, from the pull down the slope): check the angle (or the time scale "
           "and the length calibration); mu, v0 and the normal friction verdict are off until this is fixed";
  return {};
}

std::optional<Estimate> check_frame_rotation(const track::Track& track, const InclineFitOptions& o) {
  if (o.fit_frame_rotation) return std::nullopt;
  InclineFitOptions free = o;
  free.fit_frame_rotation = true;
  try {
    const ModelBFit b = fit_model_b(track, free);
    // Model A nests B, so its psi is unbiased with or without normal friction; B's absorbs
    // part of one (docs/theory.md#incline-analysis).
    if (o.fit_model_a) return fit_model_a(track, free, b).frame_rotation;
    return b.frame_rotation;
  } catch (const Error&) {
    return std::nullopt;
  }
}

const char* to_string(VerdictSource s) {
  switch (s) {
    case VerdictSource::model_a_test: return "model_a_test";
    case VerdictSource::a_n_intercept: return "a_n_intercept";
    case VerdictSource::none: break;
  }
  return "none";
}

namespace {

/// Model A fitted after B (`b`), its curves and residuals at the data's times `t` and on the
/// plotting grid `fine`, and the nested F test of A against B; a failed fit is a note.
void add_model_a(InclineAnalysis& a, const track::Track& track, const InclineFitOptions& o, const ModelBFit& b,
                 const std::vector<double>& t, const std::vector<double>& fine) {
  try {
    ModelAFit fa = fit_model_a(track, o, b);
    const incline::Parameters pa =
        launch(fa.mu.value, o.phi, fa.v0.value, o.g, fa.normal_accel.value);
    const double psi_a = fa.frame_rotation.value;
    a.model_a_at_data =
        model_a_states(pa, fa.t0.value, fa.x0.value, fa.y0.value, t, o.ode_tolerance, psi_a);
    a.model_a_fine =
        model_a_states(pa, fa.t0.value, fa.x0.value, fa.y0.value, fine, o.ode_tolerance, psi_a);
    for (std::size_t i = 0; i < t.size(); ++i) {
      a.residual_x_a.push_back(track.points[i].x - a.model_a_at_data[i].x);
      a.residual_y_a.push_back(track.points[i].y - a.model_a_at_data[i].y);
    }
    ModelTest test;
    // Nested models, one extra parameter: F = (RSS_B - RSS_A) / (RSS_A / dof_A).
    test.f_statistic = std::max(0.0, (b.rss - fa.rss) / (fa.rss / fa.dof));
    const boost::math::fisher_f dist(1.0, static_cast<double>(fa.dof));
    test.p_value = boost::math::cdf(boost::math::complement(dist, test.f_statistic));
    test.ci_excludes_zero = fa.normal_accel.ci_low > 0 || fa.normal_accel.ci_high < 0;
    test.significant = test.p_value < o.significance;
    test.size = o.significance;
    test.present = test.ci_excludes_zero && test.significant;
    a.model_a = std::move(fa);
    a.test = test;
  } catch (const Error& e) {
    a.notes.push_back(std::string("model A not fitted: ") + e.what());
  }
}

/// The diagnostics of eqs b (a_N over blocks of the moving part) and c (theta_c at the v_y
/// extremum); `pb` is fitted model B's launch, `t` the data's times.
void add_diagnostics(InclineAnalysis& a, const track::Track& track, const InclineFitOptions& o,
                     const incline::Parameters& pb, const std::vector<double>& t) {
  const ModelBFit& b = a.model_b;
  const double psi_b = b.frame_rotation.value;
  // Diagnostics: eq b on the moving part short of the stop (theta undefined at v = 0), in the
  // incline's frame: the points turned back by the fitted rotation. Model A's rotation, launch
  // and stop when it is fitted: A nests B, so they are unbiased whether or not a normal friction
  // component is present, whereas model B's psi absorbs part of one (f_N/m = 1 m/s^2 turned
  // B's psi by 4.7 deg and took 0.4 m/s^2 off the eq b intercept).
  double t0_d = b.t0.value, x0_d = b.x0.value, y0_d = b.y0.value, psi_d = psi_b;
  std::optional<double> t_stop_d = b.t_stop;
  if (a.model_a) {
    const ModelAFit& fa = *a.model_a;
    t0_d = fa.t0.value, x0_d = fa.x0.value, y0_d = fa.y0.value, psi_d = fa.frame_rotation.value;
    incline::NumericOptions no;
    no.model = incline::Model::A;
    no.t_max = 60.0;
    const auto r = incline::simulate(launch(fa.mu.value, o.phi, fa.v0.value, o.g, fa.normal_accel.value), {}, no);
    t_stop_d = r.t_stop ? std::optional<double>(t0_d + *r.t_stop) : std::nullopt;
  }
  const double t_move_end = t_stop_d ? t0_d + 0.9 * (*t_stop_d - t0_d) : t.back();
  const track::Track incline_frame = derotate_track(track, psi_d, x0_d, y0_d);
  // The same model's noise-free path in the incline frame, at the data's times: the eq b line
  // through it measures the local fits' truncation bias (docs/theory.md#incline-analysis).
  std::optional<NormalAccelReference> ref(std::in_place);
  ref->path = incline_frame;
  try {
    std::vector<double> times;
    times.reserve(track.points.size());
    for (const auto& q : track.points) times.push_back(q.t);
    const std::vector<incline::State> states =
        a.model_a ? model_a_states(launch(a.model_a->mu.value, o.phi, a.model_a->v0.value, o.g,
                                          a.model_a->normal_accel.value),
                                   t0_d, x0_d, y0_d, times, o.ode_tolerance, 0)
                  : model_b_states(pb, t0_d, x0_d, y0_d, times, 0);
    for (std::size_t i = 0; i < states.size(); ++i) {
      ref->path.points[i].x = states[i].x;
      ref->path.points[i].y = states[i].y;
    }
    ref->intercept = a.model_a ? -a.model_a->normal_accel.value : 0.0;
  } catch (const Error& e) {
    a.notes.push_back(std::string("a_N truncation bias not subtracted: ") + e.what());
    ref.reset();
  }
  a.a_n = normal_accel_diagnostic(incline_frame, t0_d, t_move_end, o.phi, o.g, o.diagnostic_block, o.level,
                                  ref ? &*ref : nullptr);
  if (!a.a_n) a.notes.push_back("a_N diagnostic skipped: fewer than 3 blocks of moving points");

  // Eq c: the v_y extremum exists when the disc stops (k < 1); locate it from model B.
  const double k = pb.k();
  if (b.t_stop && k > 0 && k < 1) {
    a.cos_theta_c_model = k;
    const incline::ClosedForm cf(pb);
    const double s_c = std::atanh(k) / k;  // a_y = alpha tanh(k s) - beta = 0 (eq 四)
    const double t_c = b.t0.value + cf.time_at(s_c);
    // Window: 35 % of the motion's duration on each side, kept clear of the launch and of the
    // last 10 % before the stop (where the acceleration changes fastest); quartic or sextic fits
    // with their truncation error in the sigma (quartics were 0.002 = 6 sd off on exact data;
    // docs/theory.md#incline-analysis).
    const double T = *b.t_stop - b.t0.value;
    const double lo = std::max(b.t0.value + 0.02 * T, t_c - 0.35 * T);
    const double hi = std::min(*b.t_stop - 0.1 * T, t_c + 0.35 * T);
    a.theta_c = theta_c_diagnostic(incline_frame, t_c, lo, hi);
    if (!a.theta_c) a.notes.push_back("theta_c diagnostic skipped: too few points around the v_y extremum");
  } else {
    a.notes.push_back("theta_c diagnostic skipped: the fitted motion does not stop (k >= 1), so v_y has no extremum");
  }

}

/// The warnings of data that contradict the physics or the given parameters (a turned frame,
/// g, wild frames, an impossible mu) and of theta_c's optimistic sigma.
void add_plausibility_warnings(InclineAnalysis& a, const track::Track& track, const InclineFitOptions& o) {
  const ModelBFit& b = a.model_b;
  // The frame held aligned (frame_rotation none) against data that show it turned: a turned
  // frame biases mu and mimics normal friction (0.5 deg: mu +0.0045 = 13 sd, `present` in every
  // run), and the g check below then blames the frame rate. 3 sd, as the g check.
  a.frame_rotation_check = check_frame_rotation(track, o);
  const bool frame_turned = a.frame_rotation_check &&
                            std::abs(a.frame_rotation_check->value) > 3 * a.frame_rotation_check->sigma;
  if (frame_turned) {
    const Estimate& p = *a.frame_rotation_check;
    a.warnings.push_back("the camera frame is held aligned with the incline (" + field("frame_rotation") +
                         " none), but the data show it turned by " + message_number(to_deg(p.value), 3) + " +- " + message_number(to_deg(p.sigma), 2) + " deg (fitted with model " +
                         (o.fit_model_a ? "A" : "B, which also turns by any normal friction") +
                         "): a turned frame biases mu, v0 and g and is mistaken for normal friction; check the axes "
                         "against a plumb line or analyse with " + field("frame_rotation") + " fit");
  }
  a.gravity = check_gravity(track, o, b);
  if (a.gravity) {
    if (const std::string w = gravity_warning(*a.gravity, o, frame_turned); !w.empty()) a.warnings.push_back(w);
  }
  // Wild frames (a hand in the picture, the tracker jumping): model B misses them by far
  // more than the noise; they pull mu and can flip the verdict. 8 robust noise sds + 2 mm, as
  // for bounce analyze (docs/theory.md#plausibility-checks).
  {
    // Model A's residuals when it was fitted (it nests B: a real normal friction is no wild frame).
    const bool with_a = a.residual_x_a.size() == a.residual_x_b.size();
    const auto& rx = with_a ? a.residual_x_a : a.residual_x_b;
    const auto& ry = with_a ? a.residual_y_a : a.residual_y_b;
    const double noise = std::max(a.kinematics.noise_x, a.kinematics.noise_y);
    const double limit = 8 * noise + 2e-3;
    std::size_t n_wild = 0;
    double worst = 0, t_first = 0;
    for (std::size_t i = 0; i < rx.size(); ++i) {
      const double d = std::hypot(rx[i], ry[i]);
      if (d > limit) {
        if (n_wild++ == 0) t_first = track.points[i].t;
        worst = std::max(worst, d);
      }
    }
    // A few frames only (a fifth at most): when the fit misses most of them the model or the
    // time scale is wrong, which the gravity check says, not wild frames.
    if (n_wild > 0 && 5 * n_wild <= rx.size())
      a.warnings.push_back(std::to_string(n_wild) + " frame(s) from t = " + message_number(t_first, 4) + " s lie far from the fitted slide (up to " +
                           message_number(1e3 * worst, 3) + " mm; the noise is " + message_number(1e3 * noise, 2) +
                           " mm): something else was tracked there (a hand, a shadow) or the tracker jumped; mu, the "
                           "verdict and its tests are pulled by them. Correct or delete those points and analyse again");
  }
  if (b.mu.value > 2) {
    a.warnings.push_back("the fitted friction coefficient mu = " + message_number(b.mu.value, 4) +
                         " is far above any sliding contact (mu < 2): check the time scale, the length unit and the incline angle");
  }

  // theta_c from few points (short runs, low frame rates): the delta-method sigma is then too
  // small, measured in docs/theory.md ("theta_c from few points"). Last: the warnings above say
  // the data contradict the physics, this one only that theta_c's sigma is optimistic.
  if (a.theta_c && a.theta_c->points < kThetaCMinPoints)
    a.warnings.push_back("theta_c rests on only " + std::to_string(a.theta_c->points) +
                         " points around the v_y extremum (t = " + message_number(a.theta_c->window_low, 4) + " to " +
                         message_number(a.theta_c->window_high, 4) + " s; fewer than " + std::to_string(kThetaCMinPoints) +
                         "): its stated uncertainty is too small, in simulated runs with so few points the error "
                         "was 1.4 times the stated sigma on average and up to 5 times; film at a higher frame rate "
                         "or a longer stretch around the extremum");

}

/// The verdict on normal friction: model A's test, else the a_N intercept, else absent (noted).
void decide_verdict(InclineAnalysis& a) {
  if (a.test) {
    a.verdict = verdict_from(a.test->present);
    a.verdict_source = VerdictSource::model_a_test;
  } else if (a.a_n) {
    a.verdict = verdict_from(a.a_n->intercept_excludes_zero);
    a.verdict_source = VerdictSource::a_n_intercept;
  } else {
    a.verdict = Verdict::absent;
    a.verdict_source = VerdictSource::none;
    a.notes.push_back("no test could decide; verdict defaults to absent");
  }
}

}  // namespace

InclineAnalysis analyze_incline_run(const track::Track& tracked, const InclineFitOptions& o) {
  // An isolated value far off its neighbours' motion (a lost decimal point) would pull every
  // fit: left out first and named (docs/theory.md#plausibility-checks, "isolated outliers").
  const std::vector<track::Outlier> outliers = track::isolated_outliers(tracked);
  const track::Track track = track::without(tracked, outliers);
  InclineAnalysis a;
  for (const auto& x : outliers) a.warnings.push_back(track::outlier_warning(tracked, x));
  a.phi = o.phi;
  a.g = o.g;
  try {
    a.model_b = fit_model_b(track, o);
  } catch (const Error&) {
    // Data whose g is far from the one given (a wrong time scale) defeat the fit with g held:
    // say what the data show instead of how the solver failed (docs/theory.md#incline-gravity).
    const auto c = check_gravity(track, o);
    if (!c) throw;
    const std::string w = gravity_warning(*c, o);
    if (w.empty()) throw;
    // The solver's own words ("Residual and Jacobian evaluation failed") would only distract
    // from the factor the message names (issue 27).
    throw InputError(where(track), w + " (model B with g = " + message_number(o.g, 4) + " m/s^2 and phi = " + message_number(to_deg(o.phi), 4) +
                                       " deg does not fit these data)");
  }
  if (a.model_b.fit.serial_factor > 1.5) {
    a.notes.push_back("the residuals are correlated in time (a tracker's smooth error, or motion the model misses): "
                      "the uncertainties are widened " + message_number(std::sqrt(a.model_b.fit.serial_factor), 2) +
                      " times (model B)");
  }
  a.data = track.points;
  track::KinematicsOptions ko;
  ko.method = track::DerivativeMethod::savgol;
  a.kinematics = track::differentiate(track, ko);
  const std::vector<double> t = times_of(track), fine = fine_grid(t);
  const ModelBFit& b = a.model_b;
  const incline::Parameters pb = launch(b.mu.value, o.phi, b.v0.value, o.g);
  const double psi_b = b.frame_rotation.value;
  a.model_b_at_data = model_b_states(pb, b.t0.value, b.x0.value, b.y0.value, t, psi_b);
  a.model_b_fine = model_b_states(pb, b.t0.value, b.x0.value, b.y0.value, fine, psi_b);
  for (std::size_t i = 0; i < t.size(); ++i) {
    a.residual_x_b.push_back(track.points[i].x - a.model_b_at_data[i].x);
    a.residual_y_b.push_back(track.points[i].y - a.model_b_at_data[i].y);
  }

  if (o.fit_model_a) add_model_a(a, track, o, b, t, fine);
  add_diagnostics(a, track, o, pb, t);
  add_plausibility_warnings(a, track, o);
  decide_verdict(a);
  return a;
}

}  // namespace tribolab::analysis
