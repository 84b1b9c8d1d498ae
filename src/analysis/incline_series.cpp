#include "analysis/incline_series.hpp"

#include "incline/inverse.hpp"
#include "numerics/error.hpp"

#include <boost/math/distributions/normal.hpp>

#include <algorithm>
#include <cmath>
#include <set>

namespace tribolab::analysis {
namespace {

/// Angles closer than this are one angle (the CLI parses the same text to the same double;
/// 1e-9 rad is far below any measured angle's precision).
constexpr double kSameAngle = 1e-9;

/// Names outliers by iterative rejection: the value with the largest |pull| beyond `limit`
/// is named and left out, the weighted mean recomputed without it, until no value is beyond.
/// (One wild run pulls the mean of a few runs so far that every pull about the full mean
/// exceeds the limit; removing it first names only the culprit.) The reported mean keeps
/// every run: this only names them.
void name_outliers(const std::vector<double>& x, const std::vector<double>& s, const std::vector<int>& index,
                   const std::vector<std::string>& sources, double limit, std::vector<std::string>& out) {
  std::vector<bool> kept(x.size(), true);
  while (true) {
    std::vector<double> xk, sk;
    std::vector<std::size_t> pos;
    for (std::size_t j = 0; j < x.size(); ++j)
      if (kept[j]) {
        xk.push_back(x[j]);
        sk.push_back(s[j]);
        pos.push_back(j);
      }
    if (xk.size() < 3) return;  // with two values neither can be told to be the outlier
    const WeightedMean m = weighted_mean(xk, sk);
    std::size_t worst = 0;
    for (std::size_t j = 1; j < m.pulls.size(); ++j)
      if (std::abs(m.pulls[j]) > std::abs(m.pulls[worst])) worst = j;
    if (!(std::abs(m.pulls[worst]) > limit)) return;
    kept[pos[worst]] = false;
    out.push_back(sources[static_cast<std::size_t>(index[pos[worst]])]);
  }
}

}  // namespace

std::string InclineSeriesOptions::validate() const {
  if (!(g > 0 && std::isfinite(g))) return "g must be > 0";
  if (!(level > 0 && level < 1)) return "level must be in (0, 1)";
  if (!(outlier_pull > 0)) return "outlier_pull must be > 0";
  return {};
}

InclineRunPoint incline_run_point(const InclineAnalysis& a, const std::string& source) {
  InclineRunPoint p;
  p.source = source;
  p.phi = a.phi;
  const ModelBFit& b = a.model_b;
  p.mu = b.mu.value;
  p.sigma_mu = b.mu.sigma;
  p.v0 = b.v0.value;
  p.sigma_v0 = b.v0.sigma;
  if (b.t_stop && b.x_stop && b.y_stop) {
    p.t_stop = *b.t_stop - b.t0.value;
    p.x_stop = *b.x_stop - b.x0.value;
    p.y_stop = *b.y_stop - b.y0.value;
  }
  if (a.theta_c) {
    p.cos_theta_c = a.theta_c->cos_theta_c;
    p.sigma_cos_theta_c = a.theta_c->sigma_cos_theta_c;
  }
  if (a.model_a) {
    p.normal_accel = a.model_a->normal_accel.value;
    p.sigma_normal_accel = a.model_a->normal_accel.sigma;
  }
  p.verdict = a.verdict;
  return p;
}

std::string stop_relation_key(StopRelation r) {
  switch (r) {
    case StopRelation::t_vs_v0: return "t_stop_v0";
    case StopRelation::x_vs_v0sq: return "x_stop_v0sq";
    case StopRelation::y_vs_v0sq: return "y_stop_v0sq";
    case StopRelation::y_vs_x: return "y_stop_x_stop";
  }
  return {};
}

// With m = mu cos(phi), s = sin(phi), alpha = g m and k = s/m (docs/theory.md#series-of-runs):
//   t_stop/v0   = 1/(alpha(1-k^2))        = m/(g(m^2 - s^2))         (eq 七)
//   x_stop/v0^2 = 2/(alpha(4-k^2))        = 2m/(g(4m^2 - s^2))       (eq 八)
//   y_stop/v0^2 = -k/(4 alpha (1-k^2))    = -s/(4g(m^2 - s^2))       (eq 九)
//   y_stop/x_stop = -k(4-k^2)/(8(1-k^2))                             (eq 十)
std::optional<double> stop_slope(StopRelation r, double mu, double phi, double g) {
  const double m = mu * std::cos(phi), s = std::sin(phi);
  if (!(m > s) || !(g > 0)) return std::nullopt;
  const double k = s / m;
  switch (r) {
    case StopRelation::t_vs_v0: return m / (g * (m - s) * (m + s));
    case StopRelation::x_vs_v0sq: return 2 * m / (g * (4 * m * m - s * s));
    case StopRelation::y_vs_v0sq: return -s / (4 * g * (m - s) * (m + s));
    case StopRelation::y_vs_x: return -k * (4 - k * k) / (8 * (1 - k) * (1 + k));
  }
  return std::nullopt;
}

std::optional<double> mu_from_stop_slope(StopRelation r, double slope, double phi, double g) {
  if (!std::isfinite(slope) || !(g > 0) || !(phi >= 0 && phi < M_PI / 2)) return std::nullopt;
  const double c = std::cos(phi), s = std::sin(phi);
  double m = 0;  // mu cos(phi)
  switch (r) {
    case StopRelation::t_vs_v0:  // g S (m^2 - s^2) = m, positive root (always > s)
      if (!(slope > 0)) return std::nullopt;
      m = (1 + std::sqrt(1 + 4 * g * g * slope * slope * s * s)) / (2 * g * slope);
      break;
    case StopRelation::x_vs_v0sq:  // g S (4m^2 - s^2) = 2m, positive root; a stop needs m > s
      if (!(slope > 0)) return std::nullopt;
      m = (1 + std::sqrt(1 + 4 * g * g * slope * slope * s * s)) / (4 * g * slope);
      if (!(m > s)) return std::nullopt;
      break;
    case StopRelation::y_vs_v0sq:  // m^2 = s^2 + s/(4 g |S|)
      if (!(slope < 0) || !(s > 0)) return std::nullopt;
      m = std::sqrt(s * s + s / (4 * g * -slope));
      break;
    case StopRelation::y_vs_x: {  // eq 十A: k from r = |x/y|
      if (!(slope < 0) || !(s > 0)) return std::nullopt;
      const double k = incline::k_from_ratio(-1 / slope);
      return std::tan(phi) / k;
    }
  }
  return m / c;
}

InclineSeriesSummary summarize_incline_series(const std::vector<InclineRunPoint>& runs,
                                              const InclineSeriesOptions& o) {
  TRIBOLAB_ASSERT(o.validate().empty(), o.validate());
  InclineSeriesSummary r;
  std::vector<std::string> sources;
  for (const auto& p : runs) sources.push_back(p.source);

  // Weighted mu (model B), and the runs whose mu lies beyond outlier_pull of it.
  std::vector<double> mu, smu;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (std::isfinite(runs[i].mu) && std::isfinite(runs[i].sigma_mu) && runs[i].sigma_mu > 0) {
      mu.push_back(runs[i].mu);
      smu.push_back(runs[i].sigma_mu);
      r.mu_index.push_back(static_cast<int>(i));
    }
  }
  if (!mu.empty()) {
    r.mu = weighted_mean(mu, smu);
    name_outliers(mu, smu, r.mu_index, sources, o.outlier_pull, r.outliers);
  }

  // One angle or several?
  std::vector<double> angles;
  for (const auto& p : runs) {
    if (std::none_of(angles.begin(), angles.end(), [&](double a) { return std::abs(a - p.phi) <= kSameAngle; }))
      angles.push_back(p.phi);
  }
  if (angles.size() == 1) r.common_phi = angles.front();

  // Figure 八: the stop point against v0 across runs at one angle.
  if (runs.empty()) {
    r.scaling_note = "no runs were analysed";
  } else if (!r.common_phi) {
    r.scaling_note = "the runs have " + std::to_string(angles.size()) +
                     " different angles; the stop-point slopes of eqs 7-10 (七-十) depend on the angle, so they are "
                     "fitted only over runs at one angle";
  } else {
    std::vector<const InclineRunPoint*> stopped;
    for (const auto& p : runs)
      if (p.t_stop && p.x_stop && p.y_stop) stopped.push_back(&p);
    if (stopped.size() < 3) {
      r.scaling_note = std::to_string(stopped.size()) + " run(s) stopped in view; the stop-point slopes need at least 3";
    } else {
      const double phi = *r.common_phi;
      std::vector<StopRelation> rels{StopRelation::t_vs_v0, StopRelation::x_vs_v0sq};
      if (phi > 0) {
        rels.push_back(StopRelation::y_vs_v0sq);
        rels.push_back(StopRelation::y_vs_x);
      } else {
        r.scaling_note = "on a level plane (phi = 0) y_stop = 0: only the t_stop and x_stop slopes are fitted";
      }
      for (StopRelation rel : rels) {
        StopScaling sc;
        sc.relation = rel;
        for (const auto* p : stopped) {
          const double v0 = p->v0;
          switch (rel) {
            case StopRelation::t_vs_v0: sc.x.push_back(v0); sc.y.push_back(*p->t_stop); break;
            case StopRelation::x_vs_v0sq: sc.x.push_back(v0 * v0); sc.y.push_back(*p->x_stop); break;
            case StopRelation::y_vs_v0sq: sc.x.push_back(v0 * v0); sc.y.push_back(*p->y_stop); break;
            case StopRelation::y_vs_x: sc.x.push_back(*p->x_stop); sc.y.push_back(*p->y_stop); break;
          }
          sc.sources.push_back(p->source);
        }
        sc.fit = fit_proportional(sc.x, sc.y, o.level, stop_relation_key(rel));
        sc.mu = mu_from_stop_slope(rel, sc.fit.slope, phi, o.g);
        // Every slope is monotonic in mu: t and x fall as mu grows, y and y/x rise (toward 0).
        const bool falling = rel == StopRelation::t_vs_v0 || rel == StopRelation::x_vs_v0sq;
        sc.mu_ci_low = mu_from_stop_slope(rel, falling ? sc.fit.ci_high : sc.fit.ci_low, phi, o.g);
        sc.mu_ci_high = mu_from_stop_slope(rel, falling ? sc.fit.ci_low : sc.fit.ci_high, phi, o.g);
        if (r.mu) sc.slope_model = stop_slope(rel, r.mu->mean, phi, o.g);
        r.scaling.push_back(std::move(sc));
      }
    }
  }

  // Eq c' over the angles: cos(theta_c) against tan(phi), slope 1/mu.
  std::vector<ThetaCPoint> tc;
  std::set<double> tc_angles;
  for (const auto& p : runs) {
    if (p.cos_theta_c && p.phi > 0) {
      tc.push_back({p.phi, *p.cos_theta_c, p.sigma_cos_theta_c.value_or(0), p.source});
      tc_angles.insert(p.phi);
    }
  }
  if (runs.empty()) {
    r.theta_c_note = "no runs were analysed";
  } else if (angles.size() < 2) {
    r.theta_c_note = "the runs share one angle; the cos(theta_c)-tan(phi) test (eq c') needs runs at several angles";
  } else if (tc.size() < 3 || tc_angles.size() < 2) {
    r.theta_c_note = std::to_string(tc.size()) + " run(s) at " + std::to_string(tc_angles.size()) +
                     " angle(s) > 0 have theta_c; the test needs at least 3 runs at 2 or more angles";
  } else {
    r.theta_c_test = normal_friction_test(tc, o.level);
  }

  // Model A's normal friction pooled: weighted f_N/m, interval from the scaled sigma.
  std::vector<double> fn, sfn;
  int n_present = 0;
  for (const auto& p : runs) {
    if (p.normal_accel && p.sigma_normal_accel && *p.sigma_normal_accel > 0 && std::isfinite(*p.normal_accel)) {
      fn.push_back(*p.normal_accel);
      sfn.push_back(*p.sigma_normal_accel);
      n_present += p.verdict == Verdict::present;
    }
  }
  if (fn.size() < 2) {
    r.normal_friction_note = std::to_string(fn.size()) + " run(s) have a model A fit; pooling needs at least 2";
  } else {
    PooledNormalFriction pn;
    pn.mean = weighted_mean(fn, sfn);
    const double z = boost::math::quantile(boost::math::normal(), 0.5 + o.level / 2);
    pn.ci_low = pn.mean.mean - z * pn.mean.sigma_scaled;
    pn.ci_high = pn.mean.mean + z * pn.mean.sigma_scaled;
    pn.verdict = verdict_from(pn.ci_low > 0 || pn.ci_high < 0);
    pn.n_present = n_present;
    r.normal_friction = pn;
  }
  return r;
}

SlideSeriesSummary summarize_slide_series(const std::vector<std::optional<double>>& mu,
                                          const std::vector<std::optional<double>>& sigma_mu,
                                          const std::vector<std::string>& sources, double outlier_pull) {
  TRIBOLAB_ASSERT(mu.size() == sigma_mu.size() && mu.size() == sources.size(), "sizes differ");
  SlideSeriesSummary r;
  std::vector<double> x, s;
  for (std::size_t i = 0; i < mu.size(); ++i) {
    if (mu[i] && sigma_mu[i] && std::isfinite(*mu[i]) && std::isfinite(*sigma_mu[i]) && *sigma_mu[i] > 0) {
      x.push_back(*mu[i]);
      s.push_back(*sigma_mu[i]);
      r.mu_index.push_back(static_cast<int>(i));
    }
  }
  if (x.empty()) {
    r.note = "no run has mu with an uncertainty (give " + field("phi_deg") + ")";
    return r;
  }
  r.mu = weighted_mean(x, s);
  name_outliers(x, s, r.mu_index, sources, outlier_pull, r.outliers);
  return r;
}

}  // namespace tribolab::analysis
