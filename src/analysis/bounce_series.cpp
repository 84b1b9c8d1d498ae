// A series of analysed bounces. docs/theory.md#bounce-series.
#include "analysis/bounce_series.hpp"

#include "analysis/series_plausibility.hpp"

#include "numerics/error.hpp"
#include "numerics/message_number.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace tribolab::analysis {

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

BounceSeriesPoint point_of(const BounceAnalysis& r) {
  BounceSeriesPoint p;
  // The state bounce simulate, sweep and fit start from (first touch) and end at (separation),
  // docs/theory.md#bounce-analysis: the angle and orientation at t_touch, the centre's vy at
  // t_touch (pre fit) and t_separation (post fit). vx and omega are constant in flight, so the
  // segments' values are also those at touch and separation.
  p.collision_angle_deg = r.collision_angle_deg;
  p.sigma_collision_angle_deg = r.sigma_collision_angle_deg;
  p.theta_deg = r.theta_touch_deg;
  p.e_velocity = r.e_velocity;
  p.sigma_e_velocity = r.sigma_e_velocity;
  p.e_height = r.e_height;
  p.sigma_e_height = r.sigma_e_height;
  p.vx_in = r.pre.vx;
  p.vy_in = r.vy_touch;
  p.omega_in = r.pre.omega;
  p.vx_out = r.post.vx;
  p.vy_out = r.vy_separation;
  p.omega_out = r.post.omega;
  p.sigma_theta_deg = r.sigma_theta_touch_deg;
  p.sigma_vx_in = r.pre.sigma_vx;
  p.sigma_vy_in = r.sigma_vy_touch;
  p.sigma_omega_in = r.pre.sigma_omega;
  p.sigma_vx_out = r.post.sigma_vx;
  p.sigma_vy_out = r.sigma_vy_separation;
  p.sigma_omega_out = r.post.sigma_omega;
  p.energy_pre = r.pre.energy;    // at t_touch
  p.energy_post = r.post.energy;  // at t_separation
  p.mean_normal_force = r.mean_normal_force.value_or(NAN);
  p.sigma_mean_normal_force = r.sigma_mean_normal_force.value_or(NAN);
  // The analysis's own contact-point velocity at t_touch (its sigma includes the touch
  // instant's and the orientation's errors).
  p.contact_point_vx = r.contact_point_vx;
  p.contact_point_vy = r.contact_point_vy;
  p.contact_point_speed = r.contact_point_speed;
  p.sigma_contact_point_speed = r.sigma_contact_point_speed;
  return p;
}

BounceRow bounce_row_of(const BounceSeriesPoint& p) {
  BounceRow row{p.theta_deg, p.vx_in, p.vy_in, p.omega_in, p.vx_out, p.vy_out, p.omega_out};
  row.sigma_theta_deg = p.sigma_theta_deg;
  row.sigma_vx_in = p.sigma_vx_in;
  row.sigma_vy_in = p.sigma_vy_in;
  row.sigma_omega_in = p.sigma_omega_in;
  row.sigma_vx_out = p.sigma_vx_out;
  row.sigma_vy_out = p.sigma_vy_out;
  row.sigma_omega_out = p.sigma_omega_out;
  return row;
}

std::string BounceSeriesOptions::validate() const {
  if (!(bin_width_deg >= 1 && bin_width_deg <= 180)) return "bin-width-deg: must lie in 1..180";
  if (!(z_above_one > 0 && std::isfinite(z_above_one))) return "z-above-one: must be positive";
  if (!(outlier_z > 0 && std::isfinite(outlier_z))) return "outlier-z: must be positive";
  if (outlier_min_bin < 3) return "outlier-min-bin: must be 3 or more";
  return {};
}

WeightedMean weighted_mean_of_finite(const std::vector<double>& x, const std::vector<double>& sigma) {
  std::vector<double> xs, ss;
  for (std::size_t i = 0; i < x.size() && i < sigma.size(); ++i) {
    if (!std::isfinite(x[i]) || !(sigma[i] > 0) || !std::isfinite(sigma[i])) continue;
    xs.push_back(x[i]);
    ss.push_back(sigma[i]);
  }
  if (xs.empty()) {
    WeightedMean m;
    m.mean = m.sigma = m.sigma_scaled = m.p_value = m.birge_ratio = m.chi2 = NAN;
    return m;
  }
  return weighted_mean(xs, ss);
}

BounceSeriesSummary summarize_bounce_series(const std::vector<BounceSeriesPoint>& points,
                                            const BounceSeriesOptions& o) {
  if (auto e = o.validate(); !e.empty()) throw InputError(e);
  if (points.empty()) throw InputError("a bounce series needs at least one analysed run");
  BounceSeriesSummary s;
  s.n_runs = static_cast<int>(points.size());
  std::vector<double> ev, sev, eh, seh;
  for (const auto& p : points) {
    ev.push_back(p.e_velocity);
    sev.push_back(p.sigma_e_velocity);
    eh.push_back(p.e_height);
    seh.push_back(p.sigma_e_height);
  }
  s.e_velocity = weighted_mean_of_finite(ev, sev);
  s.e_height = weighted_mean_of_finite(eh, seh);
  // e > 1: counted over runs with a value; significant when one-sided (e - 1)/sigma > z.
  auto above = [&](const std::vector<double>& e, const std::vector<double>& se) {
    AboveOne a;
    for (std::size_t i = 0; i < e.size(); ++i) {
      if (!std::isfinite(e[i])) continue;
      ++a.n;
      if (e[i] > 1) ++a.above;
      if (e[i] > 1 && se[i] > 0 && (e[i] - 1) / se[i] > o.z_above_one) ++a.significant;
    }
    return a;
  };
  s.above_one_velocity = above(ev, sev);
  s.above_one_height = above(eh, seh);

  // Bins of collision angle [k w, (k + 1) w), the last closed at 180 deg.
  const int n_bins = static_cast<int>(std::ceil(180.0 / o.bin_width_deg - 1e-9));
  std::vector<std::vector<std::size_t>> members(n_bins);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double a = points[i].collision_angle_deg;
    if (!std::isfinite(a)) continue;
    const int k = std::clamp(static_cast<int>(std::floor(a / o.bin_width_deg)), 0, n_bins - 1);
    members[k].push_back(i);
  }
  for (int k = 0; k < n_bins; ++k) {
    if (members[k].empty()) continue;
    AngleBin b;
    b.low_deg = k * o.bin_width_deg;
    b.high_deg = std::min(180.0, (k + 1) * o.bin_width_deg);
    b.n = static_cast<int>(members[k].size());
    std::vector<double> x, sx;
    double sum_a = 0;
    b.e_min = INFINITY;
    b.e_max = -INFINITY;
    for (std::size_t i : members[k]) {
      x.push_back(points[i].e_velocity);
      sx.push_back(points[i].sigma_e_velocity);
      sum_a += points[i].collision_angle_deg;
      b.e_min = std::min(b.e_min, points[i].e_velocity);
      b.e_max = std::max(b.e_max, points[i].e_velocity);
      if (points[i].e_velocity > 1) ++b.n_above_one;
    }
    b.centre_deg = sum_a / b.n;
    b.e_velocity = weighted_mean_of_finite(x, sx);
    s.bins.push_back(b);
    // Outliers of the bin: modified z = 0.6745 |e - median| / MAD > outlier_z.
    if (b.n >= o.outlier_min_bin) {
      const double med = median(x);
      std::vector<double> dev;
      for (double v : x) dev.push_back(std::abs(v - med));
      const double mad = median(dev);
      if (mad > 0) {
        for (std::size_t j = 0; j < x.size(); ++j) {
          const double z = 0.6745 * std::abs(x[j] - med) / mad;
          if (z > o.outlier_z) {
            s.outliers.push_back({members[k][j], "e_velocity " + message_number(x[j], 3) + " far from the median " + message_number(med, 3) +
                                                     " of its collision-angle bin " + message_number(b.low_deg, 3) + "–" +
                                                     message_number(b.high_deg, 3) + " deg (modified z " + message_number(z, 3) + ")"});
          }
        }
      }
    }
  }
  std::sort(s.outliers.begin(), s.outliers.end(), [](const auto& a, const auto& b) { return a.run < b.run; });

  // Energies (figure 49): ratio after/before and runs that gained.
  double sum_ratio = 0;
  for (const auto& p : points) {
    const double before = p.energy_pre.total(), after = p.energy_post.total();
    sum_ratio += after / before;
    if (after > before) ++s.n_energy_gain;
  }
  s.energy_ratio_mean = sum_ratio / s.n_runs;

  // Mean normal force (figure 50) and its correlation with e.
  std::vector<double> f, fe;
  for (const auto& p : points)
    if (std::isfinite(p.mean_normal_force)) {
      f.push_back(p.mean_normal_force);
      fe.push_back(p.e_velocity);
    }
  s.n_force = static_cast<int>(f.size());
  s.force_mean = s.force_sd = s.force_e_correlation = NAN;
  if (!f.empty()) {
    double mf = 0, me = 0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      mf += f[i];
      me += fe[i];
    }
    mf /= f.size();
    me /= f.size();
    double sff = 0, see = 0, sfe = 0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      sff += (f[i] - mf) * (f[i] - mf);
      see += (fe[i] - me) * (fe[i] - me);
      sfe += (f[i] - mf) * (fe[i] - me);
    }
    s.force_mean = mf;
    if (f.size() >= 2) s.force_sd = std::sqrt(sff / (f.size() - 1));
    if (f.size() >= 3 && sff > 0 && see > 0) s.force_e_correlation = sfe / std::sqrt(sff * see);
  }

  // Contact-point speed (figure 52): fastest and slowest runs.
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (points[i].contact_point_speed > points[s.fastest_contact_run].contact_point_speed) s.fastest_contact_run = i;
    if (points[i].contact_point_speed < points[s.slowest_contact_run].contact_point_speed) s.slowest_contact_run = i;
  }
  return s;
}

bool is_one_value(const WeightedMean& m) {
  return m.dof < 1 || !std::isfinite(m.p_value) || m.p_value >= kContradictionP;
}

std::string e_velocity_headline(const BounceSeriesSummary& s) {
  const WeightedMean& m = s.e_velocity;
  char buf[512];
  if (m.n == 0) return "no run has e_velocity with an uncertainty";
  if (is_one_value(m)) {
    std::snprintf(buf, sizeof buf, "e_velocity = %.4f +- %.4f, weighted mean of %d runs (one value: p = %.3g)", m.mean,
                  m.sigma_scaled, m.n, m.dof > 0 ? m.p_value : 1.0);
    return buf;
  }
  // The bins with the lowest and the highest weighted e: the span of the relation.
  const AngleBin* lo = nullptr;
  const AngleBin* hi = nullptr;
  int n_bins = 0;
  for (const auto& b : s.bins) {
    if (b.e_velocity.n == 0 || !std::isfinite(b.e_velocity.mean)) continue;
    ++n_bins;
    if (!lo || b.e_velocity.mean < lo->e_velocity.mean) lo = &b;
    if (!hi || b.e_velocity.mean > hi->e_velocity.mean) hi = &b;
  }
  std::snprintf(buf, sizeof buf, "the runs are not one value (chi2 = %.3g on %d dof, p = %.2g): no mean is meaningful", m.chi2,
                m.dof, m.p_value);
  std::string out = buf;
  if (n_bins >= 2 && lo != hi) {
    std::snprintf(buf, sizeof buf,
                  "; e_velocity depends on the collision angle, from %.3f +- %.3f at %.0f deg (bin %.0f-%.0f) to %.3f +- "
                  "%.3f at %.0f deg (bin %.0f-%.0f) over %d bins",
                  lo->e_velocity.mean, lo->e_velocity.sigma_scaled, lo->centre_deg, lo->low_deg, lo->high_deg,
                  hi->e_velocity.mean, hi->e_velocity.sigma_scaled, hi->centre_deg, hi->low_deg, hi->high_deg, n_bins);
    out += buf;
  } else {
    out += "; the runs scatter beyond their uncertainties within one collision-angle bin: check that they are throws "
           "of one ball on one floor, analysed alike";
  }
  return out;
}

}  // namespace tribolab::analysis
