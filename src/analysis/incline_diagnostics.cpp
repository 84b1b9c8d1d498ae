#include "analysis/incline_diagnostics.hpp"

#include "numerics/error.hpp"
#include "numerics/units.hpp"

#include <algorithm>
#include <cmath>
#include <span>

namespace tribolab::analysis {
namespace {

/// Local quadratic (or cubic) fit of one coordinate over points [b, e) in tau = t - tc.
numerics::PolyFit local_fit(const std::vector<double>& tau, const std::vector<double>& v, int degree) {
  return numerics::fit_polynomial(tau, v, degree, "local fit");
}

}  // namespace

namespace {

/// The eq b line from local quadratics on non-overlapping blocks of `w` points of `sel`.
std::optional<NormalAccelDiagnostic> a_n_line(const std::vector<const track::TrackPoint*>& sel, int w) {
  const int n = static_cast<int>(sel.size());
  const int blocks = n / w;
  if (blocks < 3 || w < 4) return std::nullopt;
  NormalAccelDiagnostic d;
  d.block = w;
  for (int b = 0; b < blocks; ++b) {
    std::vector<double> tau(w), x(w), y(w);
    double tm = 0;
    for (int i = 0; i < w; ++i) tm += sel[b * w + i]->t;
    tm /= w;
    for (int i = 0; i < w; ++i) {
      tau[i] = sel[b * w + i]->t - tm;
      x[i] = sel[b * w + i]->x;
      y[i] = sel[b * w + i]->y;
    }
    const auto fx = local_fit(tau, x, 2), fy = local_fit(tau, y, 2);
    const double vx = fx.coef[1], vy = fy.coef[1], ax = 2 * fx.coef[2], ay = 2 * fy.coef[2];
    const double v = std::hypot(vx, vy);
    if (!(v > 0)) continue;
    d.t.push_back(tm);
    d.sin_theta.push_back(vx / v);                 // seed eq 1.3
    d.a_n.push_back((ax * vy - ay * vx) / v);      // toward the centre of curvature (eq b)
  }
  if (d.t.size() < 3) return std::nullopt;
  // All sin(theta) equal (a straight slide along y or x): the line is undetermined.
  const auto [lo, hi] = std::minmax_element(d.sin_theta.begin(), d.sin_theta.end());
  if (!(*hi - *lo > 1e-9)) return std::nullopt;
  d.line = numerics::fit_polynomial(d.sin_theta, d.a_n, 1, "a_N against sin(theta)");
  d.intercept = d.line.coef[0];
  d.sigma_intercept = d.line.sigma[0];
  d.slope = d.line.coef[1];
  d.sigma_slope = d.line.sigma[1];
  return d;
}

std::vector<const track::TrackPoint*> points_between(const track::Track& track, double t0, double t_end) {
  std::vector<const track::TrackPoint*> sel;
  for (const auto& p : track.points)
    if (p.t > t0 && p.t <= t_end) sel.push_back(&p);
  return sel;
}

}  // namespace

std::optional<NormalAccelDiagnostic> normal_accel_diagnostic(const track::Track& track, double t0,
                                                             double t_end, double phi, double g,
                                                             int block, double level,
                                                             const NormalAccelReference* reference) {
  const std::vector<const track::TrackPoint*> sel = points_between(track, t0, t_end);
  const int n = static_cast<int>(sel.size());
  // Automatic block: about 8 blocks, of at least 6 points and at most 25 points or 25 ms,
  // whichever is more (docs/theory.md#incline-analysis). The time bound keeps the blocks of
  // a fast camera long enough to see the acceleration: 25 frames at 50 kHz span 0.5 ms,
  // over which 10 um of noise gives a_N errors of ~1e3 m/s^2 (issue 26). Up to 1000 fps the
  // bound is the 25 points.
  const double span = n > 1 ? sel.back()->t - sel.front()->t : 0;
  const int per_25ms = span > 0 ? static_cast<int>(0.025 * (n - 1) / span) : 0;
  const int w = block > 0 ? block : std::clamp(n / 8, 6, std::max(25, per_25ms));
  std::optional<NormalAccelDiagnostic> result = a_n_line(sel, w);
  if (!result) return std::nullopt;
  NormalAccelDiagnostic& d = *result;
  d.slope_expected = g * std::sin(phi);
  // docs/theory.md#incline-analysis, "a_N truncation": the local quadratics are biased by the
  // path's higher derivatives, a smooth error the line's scatter does not see. The same blocks
  // on the fitted model's noise-free path at the data's times measure that bias (the model's
  // own line is exactly intercept -f_N/m, slope g sin(phi)), and it is subtracted.
  if (reference) {
    const std::vector<const track::TrackPoint*> ref_sel = points_between(reference->path, t0, t_end);
    const std::optional<NormalAccelDiagnostic> r =
        ref_sel.size() == sel.size() ? a_n_line(ref_sel, w) : std::nullopt;
    if (r && r->t.size() == d.t.size()) {
      d.truncation_intercept = r->intercept - reference->intercept;
      d.truncation_slope = r->slope - d.slope_expected;
      d.intercept -= d.truncation_intercept;
      d.slope -= d.truncation_slope;
      d.line.coef[0] = d.intercept;
      d.line.coef[1] = d.slope;
    }
  }
  const double h = d.line.ci_half_width(0, level);  // Student t on the line's n - 2 dof
  d.intercept_ci_low = d.intercept - h;
  d.intercept_ci_high = d.intercept + h;
  d.intercept_excludes_zero = d.intercept_ci_low > 0 || d.intercept_ci_high < 0;
  return d;
}

namespace {

/// Value of the k-th derivative of the polynomial c0 + c1 t + ... at t.
double derivative(const std::vector<double>& c, int k, double t) {
  double v = 0;
  for (int j = static_cast<int>(c.size()) - 1; j >= k; --j) {
    double f = 1;
    for (int m = 0; m < k; ++m) f *= j - m;
    v = v * t + f * c[j];
  }
  return v;
}

/// Root of y''(t) near `start` by Newton's method on the polynomial (converges in a few
/// steps from the bracketed root); NaN when it does not.
double inflection(const std::vector<double>& cy, double start) {
  double t = start;
  for (int it = 0; it < 50; ++it) {
    const double f = derivative(cy, 2, t), df = derivative(cy, 3, t);
    if (!(df != 0)) return NAN;
    const double step = f / df;
    t -= step;
    if (std::abs(step) < 1e-15 * (1 + std::abs(t))) return t;
  }
  return std::abs(derivative(cy, 2, t)) < 1e-9 ? t : NAN;
}

}  // namespace

const char* to_string(Verdict v) { return v == Verdict::present ? "present" : "absent"; }

namespace {

/// The eq c estimate from fits of one degree over the points (tau, x, y) of the window.
std::optional<ThetaC> theta_c_of_degree(const std::vector<double>& tau, const std::vector<double>& x,
                                        const std::vector<double>& y, double t_guess, double window_low,
                                        double window_high, int degree) {
  if (static_cast<int>(tau.size()) < degree + 4) return std::nullopt;
  ThetaC r;
  r.degree = degree;
  r.points = static_cast<int>(tau.size());
  r.t_guess = t_guess;
  r.window_low = window_low;
  r.window_high = window_high;
  r.fit_x = local_fit(tau, x, degree);
  r.fit_y = local_fit(tau, y, degree);
  const int nc = degree + 1;

  // The extremum of v_y: the sign change of y'' from - to + (a_y increases through zero,
  // eq c) nearest the guess, bracketed on a 400-point scan of the window, then Newton.
  const double lo = window_low - t_guess, hi = window_high - t_guess;
  double best = NAN;
  double prev_t = lo, prev = derivative(r.fit_y.coef, 2, lo);
  for (int i = 1; i <= 400; ++i) {
    const double tt = lo + (hi - lo) * i / 400;
    const double v = derivative(r.fit_y.coef, 2, tt);
    if (prev < 0 && v >= 0) {
      const double mid = 0.5 * (prev_t + tt);
      if (std::isnan(best) || std::abs(mid) < std::abs(best)) best = mid;
    }
    prev_t = tt;
    prev = v;
  }
  if (std::isnan(best)) return std::nullopt;
  // cos(theta_c) as a function of all coefficients (x fit then y fit).
  auto evaluate = [&](const std::vector<double>& cx, const std::vector<double>& cy, double* tc_out) {
    const double tc = inflection(cy, best);
    const double vx = derivative(cx, 1, tc), vy = derivative(cy, 1, tc);
    if (tc_out) *tc_out = tc;
    return -vy / std::hypot(vx, vy);
  };
  double tc = 0;
  r.cos_theta_c = evaluate(r.fit_x.coef, r.fit_y.coef, &tc);
  if (!std::isfinite(tc) || tc < lo || tc > hi || !std::isfinite(r.cos_theta_c)) return std::nullopt;
  best = tc;
  r.t_c = t_guess + tc;
  r.vx = derivative(r.fit_x.coef, 1, tc);
  r.vy = derivative(r.fit_y.coef, 1, tc);
  r.theta_c_deg = to_deg(std::acos(std::clamp(r.cos_theta_c, -1.0, 1.0)));

  // Delta method with central differences; the x and y fits are independent.
  std::vector<double> g_cos(2 * nc), g_t(2 * nc);
  for (int k = 0; k < 2 * nc; ++k) {
    std::vector<double> cxp = r.fit_x.coef, cxm = cxp, cyp = r.fit_y.coef, cym = cyp;
    double& up = k < nc ? cxp[k] : cyp[k - nc];
    double& dn = k < nc ? cxm[k] : cym[k - nc];
    const double h = 1e-6 * (std::abs(up) + 1e-6);
    up += h;
    dn -= h;
    double tp = 0, tm = 0;
    g_cos[k] = (evaluate(cxp, cyp, &tp) - evaluate(cxm, cym, &tm)) / (2 * h);
    g_t[k] = (tp - tm) / (2 * h);
  }
  double var_cos = 0, var_t = 0;
  for (int i = 0; i < nc; ++i)
    for (int j = 0; j < nc; ++j) {
      var_cos += g_cos[i] * r.fit_x.covariance(i, j) * g_cos[j] +
                 g_cos[nc + i] * r.fit_y.covariance(i, j) * g_cos[nc + j];
      var_t += g_t[nc + i] * r.fit_y.covariance(i, j) * g_t[nc + j];
    }
  r.sigma_cos_theta_c = std::sqrt(std::max(0.0, var_cos));
  r.sigma_t_c = std::sqrt(std::max(0.0, var_t));
  return r;
}

}  // namespace

std::optional<ThetaC> theta_c_diagnostic(const track::Track& track, double t_guess,
                                         double window_low, double window_high, int degree) {
  std::vector<double> tau, x, y;
  for (const auto& p : track.points) {
    if (p.t < window_low || p.t > window_high) continue;
    tau.push_back(p.t - t_guess);
    x.push_back(p.x);
    y.push_back(p.y);
  }
  const int n = static_cast<int>(tau.size());
  if (degree > 0) return theta_c_of_degree(tau, x, y, t_guess, window_low, window_high, degree);
  // Automatic (docs/theory.md#incline-analysis, "theta_c truncation"): quartics or sextics,
  // whichever states the smaller sigma once the truncation error of its polynomial model,
  // estimated from the fits one and two degrees higher, is added.
  // At least 10 points (a sextic): with fewer, lower degrees were 6 sd off on exact data.
  if (n < 10) return std::nullopt;
  std::optional<ThetaC> best;
  for (int d : {4, 6}) {
    std::optional<ThetaC> r = theta_c_of_degree(tau, x, y, t_guess, window_low, window_high, d);
    if (!r) continue;
    // Truncation: the largest change to the fits one and two degrees higher (either can agree
    // by chance), squared bias estimated without the noise: E (c_d - c_h)^2 = bias^2 +
    // var(c_h) - var(c_d) for nested least-squares fits of the same points. The estimate fell
    // short of the true error by at most 1.3 in the noise-free grid: doubled to bound it.
    double bias2 = 0;
    for (int dh : {d + 1, d + 2}) {
      const std::optional<ThetaC> hi = theta_c_of_degree(tau, x, y, t_guess, window_low, window_high, dh);
      if (!hi) continue;
      const double diff = r->cos_theta_c - hi->cos_theta_c;
      const double noise2 = std::abs(hi->sigma_cos_theta_c * hi->sigma_cos_theta_c -
                                     r->sigma_cos_theta_c * r->sigma_cos_theta_c);
      bias2 = std::max(bias2, diff * diff - noise2);
    }
    r->sigma_truncation = 2 * std::sqrt(bias2);
    r->sigma_cos_theta_c = std::hypot(r->sigma_cos_theta_c, r->sigma_truncation);
    if (!best || r->sigma_cos_theta_c < best->sigma_cos_theta_c) best = r;
  }
  return best;
}

NormalFrictionTest normal_friction_test(const std::vector<ThetaCPoint>& points, double level) {
  if (points.size() < 3)
    throw InputError("normal-friction-test", "needs at least 3 runs (a line with a noise estimate), got " +
                                                 std::to_string(points.size()));
  if (!(level > 0 && level < 1)) throw InputError("level", "must be in (0, 1)");
  NormalFrictionTest r;
  r.points = points;
  std::vector<double> tx, cy;
  for (const auto& p : points) {
    if (!(std::isfinite(p.phi) && p.phi > 0 && p.phi < M_PI / 2))
      throw InputError(p.source, "incline angle must be in (0, 90) degrees");
    if (!(std::isfinite(p.cos_theta_c) && p.cos_theta_c >= 0 && p.cos_theta_c <= 1))
      throw InputError(p.source, "cos(theta_c) must be in [0, 1]");
    tx.push_back(std::tan(p.phi));
    cy.push_back(p.cos_theta_c);
  }
  const auto [lo, hi] = std::minmax_element(tx.begin(), tx.end());
  if (!(*hi - *lo > 1e-12))
    throw InputError("normal-friction-test", "all runs have the same angle; the test needs several angles");
  r.line = numerics::fit_polynomial(tx, cy, 1, "cos(theta_c) against tan(phi)");
  r.intercept = r.line.coef[0];
  r.sigma_intercept = r.line.sigma[0];
  r.slope = r.line.coef[1];
  r.sigma_slope = r.line.sigma[1];
  if (!(r.slope > 0))
    throw InputError("normal-friction-test", "cos(theta_c) does not grow with tan(phi) (slope " +
                                                 std::to_string(r.slope) + "); no friction coefficient follows");
  r.mu = 1 / r.slope;  // eq c'
  r.sigma_mu = r.sigma_slope / (r.slope * r.slope);
  const double h = r.line.ci_half_width(0, level);
  r.intercept_ci_low = r.intercept - h;
  r.intercept_ci_high = r.intercept + h;
  r.verdict = verdict_from(r.intercept_ci_low > 0 || r.intercept_ci_high < 0);
  return r;
}

}  // namespace tribolab::analysis
