// docs/theory.md#bounce-fit.
#include "analysis/bounce_fit.hpp"
#include "analysis/bounce_plausibility.hpp"
#include "bounce/impact.hpp"

#include "numerics/error.hpp"
#include "numerics/units.hpp"
#include "numerics/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <string>
#include <utility>

namespace tribolab::analysis {

namespace {
const char* const kNames[] = {"K", "n", "D", "e", "mu"};
}  // namespace

namespace {

/// Weights of the 3 N residuals (vx, vy, b omega of each row) from the rows' own sigmas:
/// var = sigma_out^2 + sum over the inputs q (theta, vx_in, vy_in, omega_in) of the mean
/// square change of the prediction for q moved by ±sigma_q (= (d pred / d q  sigma_q)^2 where
/// it is smooth), at `law` and `friction`; weight = median sd / sd, so that the residuals keep
/// their unit (m/s) and the robust loss's scale its meaning.
void weigh_by_uncertainties(const std::vector<BounceRow>& rows, const BounceFitOptions& o,
                            const bounce::NormalLawSpec& law, const bounce::FrictionModel& friction,
                            std::vector<double>& weight) {
  std::vector<double> sd(weight.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const BounceRow& row = rows[i];
    const BounceFitRow p0 = predict_bounce(row, o.ball, law, friction, o.tolerance);
    double var[3] = {row.sigma_vx_out * row.sigma_vx_out, row.sigma_vy_out * row.sigma_vy_out,
                     o.ball.b * o.ball.b * row.sigma_omega_out * row.sigma_omega_out};
    const std::pair<double BounceRow::*, double> inputs[] = {{&BounceRow::theta_deg, row.sigma_theta_deg},
                                                              {&BounceRow::vx_in, row.sigma_vx_in},
                                                              {&BounceRow::vy_in, row.sigma_vy_in},
                                                              {&BounceRow::omega_in, row.sigma_omega_in}};
    for (const auto& [member, sigma] : inputs) {
      if (!(sigma > 0)) continue;
      // The change over the input's own uncertainty, one sigma each way: (Δ+² + Δ-²)/2 is
      // (dpred/dq σ)² where the prediction is smooth, and keeps a row whose outcome turns or
      // jumps within ±σ (a second touch that comes and goes with θ) from being trusted as if
      // it were smooth: a derivative at a point missed that (seed 7003 of the coverage study
      // below: mu 5.7 of its sigmas off).
      double sum[3] = {}, n[3] = {};
      for (int sign = -1; sign <= 1; sign += 2) {
        BounceRow moved = row;
        moved.*member += sign * sigma;
        const BounceFitRow p1 = predict_bounce(moved, o.ball, law, friction, o.tolerance);
        const double d[3] = {p1.vx_pred - p0.vx_pred, p1.vy_pred - p0.vy_pred, o.ball.b * (p1.omega_pred - p0.omega_pred)};
        for (int c = 0; c < 3; ++c)
          if (std::isfinite(d[c])) sum[c] += d[c] * d[c], n[c] += 1;
      }
      for (int c = 0; c < 3; ++c)
        if (n[c] > 0) var[c] += sum[c] / n[c];
    }
    for (int c = 0; c < 3; ++c) sd[3 * i + static_cast<std::size_t>(c)] = std::sqrt(var[c]);
  }
  const double ref = upper_median(sd);
  for (std::size_t k = 0; k < sd.size(); ++k) weight[k] = ref / sd[k];
}

}  // namespace

std::string BounceFitOptions::validate() const {
  if (auto e = ball.validate(); !e.empty()) return e;
  if (auto e = friction.validate(); !e.empty()) return e;
  for (const auto& [name, v] : fixed) {
    bool known = false;
    for (const char* k : kNames) known = known || name == k;
    if (!known) return "fix: unknown parameter '" + name + "' (K, n, D, e, mu)";
    if (restitution_model && name == "D") return "fix: D is not a parameter of a restitution-based fit (use e)";
    if (!restitution_model && name == "e") return "fix: e is a parameter only with " + field("restitution");
    if (!std::isfinite(v)) return "fix: " + name + " must be finite";
    if ((name == "K" || name == "D") && !(v > 0)) return "fix: " + name + " must be positive";
    if (name == "n" && !(v >= 1 && v <= 3)) return "fix: n must lie in [1, 3]";
    if (name == "e" && !(v > 0 && v <= 1)) return "fix: e must lie in (0, 1]";
    if (name == "mu" && !(v >= 0 && v <= 3)) return "fix: mu must lie in [0, 3]";
  }
  if (model == bounce::NormalModel::hertz && !restitution_model && !fixed.count("D"))
    return "model: the hertz law has no damping to fit; use hunt-crossley or fix D";
  if (!(loss_scale > 0 && std::isfinite(loss_scale))) return "loss-scale: must be positive";
  if (!(tolerance > 0 && tolerance < 1e-3)) return "tol: must lie in (0, 1e-3)";
  return {};
}

bool BounceRow::has_sigmas() const {
  for (double v : {sigma_theta_deg, sigma_vx_in, sigma_vy_in, sigma_omega_in})
    if (!(std::isfinite(v) && v >= 0)) return false;
  for (double v : {sigma_vx_out, sigma_vy_out, sigma_omega_out})
    if (!(std::isfinite(v) && v > 0)) return false;
  return true;
}

BounceFitRow predict_bounce(const BounceRow& row, const bounce::Ball& ball,
                            const bounce::NormalLawSpec& law, const bounce::FrictionModel& friction,
                            double tolerance) {
  BounceFitRow p;
  bounce::BodyState s;
  s.theta = row.theta_deg / kDegPerRad;  // not to_rad(): the same bits as before
  s.vx = row.vx_in;
  s.vy = row.vy_in;
  s.omega = row.omega_in;
  // The whole impact (every contact until the ball flies free), what a film measures and what
  // simulate, drop and the maps report; it is the first contact phase unless the ball touches
  // the floor again, and it varies continuously where a second touch begins (a grazing touch
  // takes no impulse). docs/theory.md#bounce-fit.
  bounce::ImpactOptions io;
  io.contact = bounce::contact_options_with_tolerance(tolerance);
  const bounce::ImpactResult r = bounce::simulate_impact(ball, law, friction, s, io);
  if (r.first.status != bounce::ContactStatus::separated || r.status != bounce::ImpactStatus::free_flight) {
    p.vx_pred = p.vy_pred = p.omega_pred = NAN;
  } else {
    p.vx_pred = r.whole.out.vx;
    p.vy_pred = r.whole.out.vy;
    p.omega_pred = r.whole.out.omega;
    p.contacts = r.contacts;
  }
  p.r_vx = p.vx_pred - row.vx_out;
  p.r_vy = p.vy_pred - row.vy_out;
  p.r_b_omega = ball.b * (p.omega_pred - row.omega_out);
  return p;
}

WholeImpactDifference whole_impact_differences(const std::vector<BounceRow>& rows, const bounce::Ball& ball,
                                               const bounce::NormalLawSpec& law, const bounce::FrictionModel& friction,
                                               double tolerance, double threshold) {
  WholeImpactDifference d;
  bounce::ImpactOptions io;
  io.contact = bounce::contact_options_with_tolerance(tolerance);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    bounce::BodyState s;
    s.theta = rows[i].theta_deg / kDegPerRad;  // as predict_bounce
    s.vx = rows[i].vx_in;
    s.vy = rows[i].vy_in;
    s.omega = rows[i].omega_in;
    const bounce::ImpactResult r = bounce::simulate_impact(ball, law, friction, s, io);
    if (r.contacts < 2 || r.first.status != bounce::ContactStatus::separated) continue;
    const double diff = std::max({std::abs(r.whole.out.vx - r.first.out.vx), std::abs(r.whole.out.vy - r.first.out.vy),
                                  ball.b * std::abs(r.whole.out.omega - r.first.out.omega)});
    if (!(diff > threshold)) continue;
    d.rows.push_back(i + 1);
    d.worst = std::max(d.worst, diff);
  }
  return d;
}

std::string rows_text(const WholeImpactDifference& d, std::size_t n_rows) {
  std::string list;
  for (std::size_t k = 0; k < d.rows.size() && k < 8; ++k) list += (k ? ", " : "") + std::to_string(d.rows[k]);
  if (d.rows.size() > 8) list += ", ...";
  return std::to_string(d.rows.size()) + " of " + std::to_string(n_rows) + " rows (" + list + ")";
}


namespace {

/// The solver's parameters, 0 log K, 1 n, 2 log D or e, 3 mu: start, bounds and which are fixed.
std::vector<numerics::FitParameter> fit_parameters(const BounceFitOptions& o) {
  const bool hooke = o.model == bounce::NormalModel::hooke;
  const bool hertz = o.model == bounce::NormalModel::hertz;
  auto fixed_or = [&](const char* name, double v) {
    auto it = o.fixed.find(name);
    return it == o.fixed.end() ? v : it->second;
  };
  std::vector<numerics::FitParameter> params(4);
  params[0] = {"log_K", std::log(fixed_or("K", o.K0)), std::log(1e1), std::log(1e10), o.fixed.count("K") > 0};
  params[1] = {"n", hooke ? 1.0 : fixed_or("n", o.n0), 1.0, 3.0, hooke || o.fixed.count("n") > 0};
  if (o.restitution_model) {
    params[2] = {"e", fixed_or("e", o.e0), 0.02, 1.0, o.fixed.count("e") > 0};
  } else {
    const double D = hertz ? 1.0 : fixed_or("D", o.D0);
    params[2] = {"log_D", std::log(D), std::log(1e-6), std::log(1e10), hertz || o.fixed.count("D") > 0};
  }
  params[3] = {"mu", fixed_or("mu", o.mu0), 0.0, 3.0, o.fixed.count("mu") > 0};
  if (hooke && o.fixed.count("n") && o.fixed.at("n") != 1.0)
    throw InputError(field("fix"), "the hooke law is linear (n = 1)");
  return params;
}

/// The normal law of the solver's parameters `p`.
bounce::NormalLawSpec spec_of(const BounceFitOptions& o, const double* p) {
  const bool hertz = o.model == bounce::NormalModel::hertz;
  bounce::NormalLawSpec s;
  s.model = o.model;
  s.K = std::exp(p[0]);
  s.n = p[1];
  if (o.restitution_model) {
    s.restitution = p[2];
  } else {
    s.D = hertz ? 0.0 : std::exp(p[2]);
  }
  return s;
}

/// The friction law of the solver's parameters `p`.
bounce::FrictionModel friction_of(const BounceFitOptions& o, const double* p) {
  bounce::FrictionModel f = o.friction;
  f.mu = p[3];
  return f;
}

/// The solver's settings.
numerics::FitOptions solver_options(const BounceFitOptions& o) {
  numerics::FitOptions fo;
  fo.loss = o.loss;
  fo.loss_scale = o.loss_scale;
  fo.max_iterations = 100;
  fo.function_tolerance = 1e-10;
  fo.parameter_tolerance = 1e-8;
  fo.gradient_tolerance = 1e-12;
  fo.covariance = o.covariance;  // docs/theory.md#bounce-fit: which estimator and why
  return fo;
}

/// The parameters started from the data: parameter 2 (damping or e) from the median rebound.
std::vector<numerics::FitParameter> start_from_data(const std::vector<BounceRow>& rows, const BounceFitOptions& o,
                                                    const std::vector<numerics::FitParameter>& params) {
  const bool hooke = o.model == bounce::NormalModel::hooke;
  std::vector<double> e_rows, v_rows;
  for (const auto& r : rows) {
    e_rows.push_back(-r.vy_out / r.vy_in);
    v_rows.push_back(std::abs(r.vy_in));
  }
  const double e_med = std::clamp(upper_median(e_rows), 0.05, 0.99);
  auto second = params;
  if (o.restitution_model) {
    second[2].initial = e_med;
  } else if (hooke) {
    double zeta = 0.9;  // heavily damped but still separating when e_med is out of reach
    try {
      zeta = bounce::hooke_damping_ratio(e_med);
    } catch (const Error&) {
    }
    const double D = 2 * zeta * std::sqrt(std::exp(params[0].initial) * o.ball.mass);
    second[2].initial = std::clamp(std::log(D), std::log(1e-6), std::log(1e10));
  } else {
    const double chi = bounce::hunt_crossley_chi_v(e_med) / upper_median(v_rows);
    second[2].initial = std::clamp(std::log(chi * std::exp(params[0].initial)), std::log(1e-6), std::log(1e10));
  }
  return second;
}

/// The law's parameters and standard errors from the solver's values (out.fit).
void take_parameters(BounceFitResult& out, const BounceFitOptions& o) {
  const bool hertz = o.model == bounce::NormalModel::hertz;
  const auto& f = out.fit;
  const auto& v = f.values;
  const auto& s = f.sigma;
  out.K = std::exp(v[0]);
  out.sigma_K = out.K * s[0];  // d K = K d log K
  out.n = v[1];
  out.sigma_n = s[1];
  if (o.restitution_model) {
    out.e = v[2];
    out.sigma_e = s[2];
    out.D = out.sigma_D = NAN;
  } else {
    out.D = hertz ? 0.0 : std::exp(v[2]);
    out.sigma_D = out.D * s[2];
    out.e = out.sigma_e = NAN;
  }
  out.mu = v[3];
  out.sigma_mu = s[3];
  out.rms = f.rms;
}

/// The free parameters' names and the warnings: parameters at a bound, rows a second touch changes.
void add_warnings(BounceFitResult& out, const std::vector<BounceRow>& rows, const BounceFitOptions& o,
                  const std::vector<numerics::FitParameter>& params, const bounce::NormalLawSpec& spec,
                  const bounce::FrictionModel& fr) {
  const auto& v = out.fit.values;
  const char* shown[] = {"K", "n", o.restitution_model ? "e" : "D", "mu"};
  for (int k = 0; k < 4; ++k)
    if (!params[k].fixed) out.free_parameters.push_back(shown[k]);
  std::vector<std::string> names;
  std::vector<double> lower, upper;
  std::vector<bool> free;
  for (int k = 0; k < 4; ++k) {
    names.push_back(shown[k]);
    lower.push_back(params[k].lower.value_or(-HUGE_VAL));
    upper.push_back(params[k].upper.value_or(HUGE_VAL));
    free.push_back(!params[k].fixed);
  }
  out.warnings = bound_warnings(names, v, lower, upper, free);  // docs/theory.md#plausibility-checks
  // The rows whose impact under the fitted law has more than one contact (predicted as such).
  out.touching_again = whole_impact_differences(rows, o.ball, spec, fr, o.tolerance, 0).rows;
}

}  // namespace

namespace {

/// The fit of `rows` alone (fit_bounces without the rows at a jump).
BounceFitResult fit_rows(const std::vector<BounceRow>& rows, const BounceFitOptions& o);

/// Indices (0-based) of the rows whose prediction is not smooth across the fit's interval: for
/// a free parameter k (log K, n, log D or e, mu) moved by s = sigma_k either way (at least
/// kJumpStep, at most kMaxStep, within the search's bounds), the impact gains or loses a contact, and the second
/// difference |pred(p+s) + pred(p-s) - 2 pred(p)| / 2 of vx, vy or b omega exceeds the loss
/// scale. A touch that begins at the apex (where simulate_impact cuts the impact) makes a jump;
/// one that begins with a lower mu a steep bend: either way the fit's linearisation, and so its
/// sigma, does not hold over that interval. (The contact count and the largest step keep rows
/// whose outcome merely curves over the wide interval of a poorly determined K or n from being
/// taken: at ±2 sigma with no largest step, 8 of the demo table's 40 rows went and its K fell 2
/// sigmas below the truth; at ±sigma up to 0.05, one.)
std::vector<std::size_t> rows_at_a_jump(const std::vector<BounceRow>& rows, const BounceFitOptions& o,
                                        const std::vector<numerics::FitParameter>& params, const std::vector<double>& p,
                                        const std::vector<double>& sigma) {
  constexpr double kJumpStep = 1e-4, kMaxStep = 0.05;
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const BounceFitRow c = predict_bounce(rows[i], o.ball, spec_of(o, p.data()), friction_of(o, p.data()), o.tolerance);
    bool jumps = false;
    for (std::size_t k = 0; k < params.size() && !jumps; ++k) {
      if (params[k].fixed) continue;
      const double step = std::isfinite(sigma[k]) ? std::clamp(sigma[k], kJumpStep, kMaxStep) : kJumpStep;
      std::vector<double> lo = p, hi = p;  // within the search's bounds (a parameter may sit on one)
      lo[k] = std::max(p[k] - step, params[k].lower.value_or(-HUGE_VAL));
      hi[k] = std::min(p[k] + step, params[k].upper.value_or(HUGE_VAL));
      BounceFitRow a, b;
      try {
        a = predict_bounce(rows[i], o.ball, spec_of(o, lo.data()), friction_of(o, lo.data()), o.tolerance);
        b = predict_bounce(rows[i], o.ball, spec_of(o, hi.data()), friction_of(o, hi.data()), o.tolerance);
      } catch (const Error&) {
        continue;  // a law the step makes impossible (a restitution out of reach): no measured jump
      }
      // Weights of the two sides when one was cut short by a bound: the second difference of
      // unequal steps, (b - c)/(hi - p) - (c - a)/(p - lo), times the mean step / 2.
      const double h1 = p[k] - lo[k], h2 = hi[k] - p[k];
      if (!(h1 > 0 && h2 > 0)) continue;
      const auto bend = [&](double fa, double fc, double fb) {
        return std::abs((fb - fc) / h2 - (fc - fa) / h1) * 0.5 * (h1 + h2) / 2;
      };
      if (a.contacts == c.contacts && b.contacts == c.contacts) continue;
      const double change = std::max({bend(a.vx_pred, c.vx_pred, b.vx_pred), bend(a.vy_pred, c.vy_pred, b.vy_pred),
                                      o.ball.b * bend(a.omega_pred, c.omega_pred, b.omega_pred)});
      jumps = change > o.loss_scale;  // NaN (a side without a bounce) is not a measured jump
    }
    if (jumps) out.push_back(i);
  }
  return out;
}

}  // namespace

BounceFitResult fit_bounces(const std::vector<BounceRow>& rows, const BounceFitOptions& o) {
  BounceFitResult out = fit_rows(rows, o);
  // The whole impact is cut at the apex: where a touch of the floor begins just after it, the
  // outcome jumps with the law. A fit that ends on such a jump has a meaningless linearisation
  // (a sigma of log K of 5e-7 was seen, the error 3 %): those rows are left out and the rest
  // fitted again (from the law found), at most three times.
  std::vector<std::size_t> kept(rows.size());
  for (std::size_t i = 0; i < kept.size(); ++i) kept[i] = i;
  std::vector<std::size_t> left_out;
  const std::vector<numerics::FitParameter> params = fit_parameters(o);
  for (int round = 0; round < 3; ++round) {
    std::vector<BounceRow> fitted;
    for (std::size_t i : kept) fitted.push_back(rows[i]);
    const std::vector<std::size_t> jumps = rows_at_a_jump(fitted, o, params, out.fit.values, out.fit.sigma);
    if (jumps.empty()) break;
    std::vector<std::size_t> still;
    for (std::size_t j = 0; j < kept.size(); ++j) {
      if (std::find(jumps.begin(), jumps.end(), j) != jumps.end()) left_out.push_back(kept[j] + 1);
      else still.push_back(kept[j]);
    }
    kept = std::move(still);
    std::vector<BounceRow> rest;
    for (std::size_t i : kept) rest.push_back(rows[i]);
    BounceFitOptions again = o;  // from the law found; fixed parameters stay fixed
    const auto& v = out.fit.values;
    again.K0 = std::exp(v[0]);
    if (!params[1].fixed) again.n0 = v[1];
    if (o.restitution_model) again.e0 = v[2];
    else if (!params[2].fixed) again.D0 = std::exp(v[2]);
    again.mu0 = v[3];
    out = fit_rows(rest, again);
  }
  if (left_out.empty()) return out;
  std::sort(left_out.begin(), left_out.end());
  // Every row predicted with the final law, the left-out ones included, in the table's order.
  const auto spec = spec_of(o, out.fit.values.data());
  const auto fr = friction_of(o, out.fit.values.data());
  out.rows.clear();
  for (const auto& row : rows) out.rows.push_back(predict_bounce(row, o.ball, spec, fr, o.tolerance));
  out.touching_again = whole_impact_differences(rows, o.ball, spec, fr, o.tolerance, 0).rows;
  out.left_out = left_out;
  WholeImpactDifference named;
  named.rows = left_out;
  out.warnings.push_back(rows_text(named, rows.size()) + " left out of the fit: with the fitted law their outcome "
                         "changes abruptly (a touch of the floor that begins or ends at the apex of the rebound), so "
                         "the fit could not rest on them (docs/theory.md#bounce-fit)");
  return out;
}

namespace {

BounceFitResult fit_rows(const std::vector<BounceRow>& rows, const BounceFitOptions& o) {
  if (auto e = o.validate(); !e.empty()) throw input_error_of(e);
  // Solver parameters: 0 log K, 1 n, 2 log D or e, 3 mu.
  const std::vector<numerics::FitParameter> params = fit_parameters(o);
  const int N = static_cast<int>(rows.size());
  int n_free = 0;
  for (const auto& p : params) n_free += p.fixed ? 0 : 1;
  if (3 * N <= n_free) {
    throw InputError(std::to_string(N) + " bounce(s) give " + std::to_string(3 * N) + " residuals; " +
                     std::to_string(n_free) + " free parameters need more rows");
  }
  const numerics::FitOptions fo = solver_options(o);
  // Residual weights: 1 (unweighted) until the rows' own uncertainties are carried in below.
  std::vector<double> weight(static_cast<std::size_t>(3 * N), 1.0);
  int with_sigmas = 0;
  for (const auto& row : rows) with_sigmas += row.has_sigmas();
  if (with_sigmas != 0 && with_sigmas != N)
    throw InputError(std::to_string(with_sigmas) + " of " + std::to_string(N) +
                     " bounces have uncertainties (sigma columns): give them for every row or for none");
  auto residuals = [&](const double* p, double* r) {
    const auto spec = spec_of(o, p);
    const auto fr = friction_of(o, p);
    for (int i = 0; i < N; ++i) {
      BounceFitRow q;
      try {
        q = predict_bounce(rows[i], o.ball, spec, fr, o.tolerance);
      } catch (const Error&) {
        return false;  // e.g. a restitution the law cannot reach: the solver backs off
      }
      r[3 * i] = weight[3 * i] * q.r_vx;
      r[3 * i + 1] = weight[3 * i + 1] * q.r_vy;
      r[3 * i + 2] = weight[3 * i + 2] * q.r_b_omega;
      if (!std::isfinite(q.r_vx) || !std::isfinite(q.r_vy) || !std::isfinite(q.r_b_omega)) return false;
    }
    return true;
  };
  BounceFitResult out;
  out.fit = numerics::fit_least_squares(residuals, 3 * N, params, fo);
  // A second start from the data: the median restitution -vy_out/vy_in and the central-impact
  // relation of the law — Hunt–Crossley e(chi v_in), or for Hooke's linear spring-dashpot
  // e(zeta) with zeta = D / (2 sqrt(K m)) — give the damping (or e) that matches the typical
  // rebound. This avoids the local minima a poor damping start falls into (friction
  // branches), and for Hooke a default D0 that overdamps the contact so that no bounce ends.
  // The start with the lower cost wins.
  if (!params[2].fixed) {
    auto alt = numerics::fit_least_squares(residuals, 3 * N, start_from_data(rows, o, params), fo);
    if (alt.ok() && (!out.fit.ok() || alt.cost < out.fit.cost)) out.fit = std::move(alt);
  }
  if (with_sigmas == N && out.fit.ok()) {
    weigh_by_uncertainties(rows, o, spec_of(o, out.fit.values.data()), friction_of(o, out.fit.values.data()), weight);
    auto start = params;
    for (std::size_t k = 0; k < start.size(); ++k) start[k].initial = out.fit.values[k];
    out.fit = numerics::fit_least_squares(residuals, 3 * N, start, fo);
  }
  const auto& f = out.fit;
  if (!f.ok()) {
    std::string why = f.message;
    if (f.status == numerics::FitStatus::not_identifiable)
      why = "the data cannot determine all free parameters (" + f.message + "); fix some with " + field("fix");
    numerics::throw_fit_failure(f, "", "bounce fit failed: " + why);
  }
  take_parameters(out, o);
  const auto spec = spec_of(o, f.values.data());
  const auto fr = friction_of(o, f.values.data());
  for (const auto& row : rows) out.rows.push_back(predict_bounce(row, o.ball, spec, fr, o.tolerance));
  add_warnings(out, rows, o, params, spec, fr);
  // The robust loss takes residuals beyond its scale as outliers: it needs most of them within
  // it. When most are beyond, the law does not describe the table (outgoing speeds in another
  // unit or time scale, another ball), or the noise is larger than the scale says; either way
  // the numbers above are not a measurement. (Measured: `bounce synth-table --rows 20
  // --outlier-fraction 0.1`, seeds 1-6, 4 to 10 of the 60 residuals beyond.)
  int beyond = 0;
  for (std::size_t i = 0; i < out.rows.size(); ++i) {
    const double r[3] = {out.rows[i].r_vx, out.rows[i].r_vy, out.rows[i].r_b_omega};
    for (int c = 0; c < 3; ++c) beyond += !(std::abs(weight[3 * i + static_cast<std::size_t>(c)] * r[c]) <= o.loss_scale);
  }
  if (2 * beyond > 3 * N) {
    char scale[32], rms[32];
    std::snprintf(scale, sizeof scale, "%.3g", o.loss_scale);
    std::snprintf(rms, sizeof rms, "%.3g", out.rms);
    out.warnings.push_back(std::to_string(beyond) + " of " + std::to_string(3 * N) + " residuals exceed the loss scale " +
                           scale + " m/s (rms " + rms + " m/s): the law does not follow these bounces, so its "
                           "parameters and sigmas are not a measurement; check the outgoing velocities' unit and time "
                           "scale and the ball, or give the data's noise as " + field("loss_scale"));
  }
  return out;
}

}  // namespace

}  // namespace tribolab::analysis
