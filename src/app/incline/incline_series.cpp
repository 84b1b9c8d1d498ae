#include "app/incline/incline_series.hpp"
#include "app/common/json_number.hpp"
#include "app/common/result_keys.hpp"

#include "analysis/series_plausibility.hpp"

#include "numerics/units.hpp"
#include "incline/params.hpp"

#include <cmath>

namespace tribolab::app {
namespace {

using nlohmann::json;

json pulls_by_run(const std::optional<analysis::WeightedMean>& m, const std::vector<int>& index, std::size_t n_runs,
                  const std::vector<std::size_t>& run_of_point) {
  json out = json::array();
  for (std::size_t i = 0; i < n_runs; ++i) out.push_back(nullptr);
  if (!m) return out;
  for (std::size_t j = 0; j < index.size(); ++j)
    out[run_of_point[static_cast<std::size_t>(index[j])]] = json_number(m->pulls[j]);
  return out;
}

}  // namespace

std::vector<std::string> series_warnings(const std::optional<analysis::WeightedMean>& mu,
                                         const std::vector<std::string>& outliers) {
  std::vector<std::string> w;
  if (mu) {
    // One surface has one mu: runs that disagree beyond their uncertainties are said
    // (docs/theory.md#plausibility-checks).
    if (auto x = analysis::disagreement_warning(*mu, "mu", outliers); !x.empty()) w.push_back(x);
  }
  return w;
}

void add_weighted_mean(json& j, const std::optional<analysis::WeightedMean>& m, const std::string& name) {
  j[name] = m ? json(m->mean) : json(nullptr);
  j["sigma_" + name] = m ? json(m->sigma) : json(nullptr);
  j["sigma_" + name + "_scaled"] = m ? json(m->sigma_scaled) : json(nullptr);
  j["chi2"] = m ? json(m->chi2) : json(nullptr);
  j["dof"] = m ? json(m->dof) : json(nullptr);
  j["p_value"] = m ? json_number(m->p_value) : json(nullptr);
  j["birge_ratio"] = m ? json_number(m->birge_ratio) : json(nullptr);
  j["n_" + name] = m ? m->n : 0;
}

json incline_series_json(const analysis::InclineSeriesSummary& s, std::size_t n_runs,
                         const std::vector<std::size_t>& run_of_point) {
  json j;
  add_weighted_mean(j, s.mu, "mu");
  j["mu_pulls"] = pulls_by_run(s.mu, s.mu_index, n_runs, run_of_point);
  j["outliers"] = s.outliers;
  j["phi_deg"] = s.common_phi ? json(to_deg(*s.common_phi)) : json(nullptr);
  if (s.scaling.empty()) {
    j["stop_scaling"] = nullptr;
  } else {
    json sc;
    for (const auto& r : s.scaling) {
      sc[analysis::stop_relation_key(r.relation)] = {
          {"slope", r.fit.slope},          {"sigma_slope", r.fit.sigma},
          {"slope_ci95", json::array({r.fit.ci_low, r.fit.ci_high})},
          {"n", r.fit.n},                  {"rms", r.fit.rms},
          {"mu", json_number(r.mu)},               {"mu_ci95", json::array({json_number(r.mu_ci_low), json_number(r.mu_ci_high)})},
          {"slope_model", json_number(r.slope_model)}};
    }
    j["stop_scaling"] = sc;
  }
  j["stop_scaling_note"] = s.scaling_note;
  if (s.theta_c_test) {
    const auto& t = *s.theta_c_test;
    j["theta_c_test"] = {{"slope", t.slope},
                         {"sigma_slope", t.sigma_slope},
                         {"mu", t.mu},
                         {"sigma_mu", t.sigma_mu},
                         {"intercept", t.intercept},
                         {"intercept_ci95", json::array({t.intercept_ci_low, t.intercept_ci_high})},
                         {"verdict", to_string(t.verdict)},
                         {"n_runs", t.points.size()}};
  } else {
    j["theta_c_test"] = nullptr;
  }
  j["theta_c_note"] = s.theta_c_note;
  if (s.normal_friction) {
    const auto& n = *s.normal_friction;
    j["normal_friction"] = {{"normal_accel", n.mean.mean},
                            {"sigma_normal_accel", n.mean.sigma},
                            {"sigma_normal_accel_scaled", n.mean.sigma_scaled},
                            {"normal_accel_ci95", json::array({n.ci_low, n.ci_high})},
                            {"chi2", n.mean.chi2},
                            {"dof", n.mean.dof},
                            {"p_value", json_number(n.mean.p_value)},
                            {"verdict", to_string(n.verdict)},
                            {"n_runs", n.mean.n},
                            {"n_runs_present", n.n_present}};
  } else {
    j["normal_friction"] = nullptr;
  }
  j["normal_friction_note"] = s.normal_friction_note;
  j["warnings"] = series_warnings(s.mu, s.outliers);
  return j;
}

json slide_series_json(const analysis::SlideSeriesSummary& s, std::size_t n_runs,
                       const std::vector<std::size_t>& run_of_point) {
  json j;
  add_weighted_mean(j, s.mu, "mu");
  j["mu_pulls"] = pulls_by_run(s.mu, s.mu_index, n_runs, run_of_point);
  j["outliers"] = s.outliers;
  j["note"] = s.note;
  j["warnings"] = series_warnings(s.mu, s.outliers);
  return j;
}

const ResultKeys& incline_analyze_series_result_keys() {
  // The stop relations (eq d): t_stop against v0, x_stop and y_stop against v0^2 (slopes in
  // s^2/m), y_stop against x_stop (a pure number); each rms is in its ordinate's unit.
  static const ResultKeys k = [] {
    ResultKeys keys = {
        {"mu", "", "weighted mean of the runs' mu (model B)"}, {"sigma_mu_scaled", "", "sigma_mu times the Birge ratio when above 1"},
        {"chi2", "", "of the runs about the mean"}, {"dof", "", ""}, {"p_value", "", ""}, {"birge_ratio", "", "sqrt(chi2/dof)"},
        {"n_mu", "", "runs in the mean"}, {"mu_pulls", "", "(mu_i - mean) / sigma_i, per run"}, {"outliers", "", ""},
        {"phi_deg", "deg", "the runs' common angle (null: several)"}, {"stop_scaling", "", "null: fewer than 2 stopping runs"},
        {"stop_scaling_note", "", ""}, {"theta_c_test", "", "eq c': cos(theta_c) against tan(phi), null: one angle"},
        {"theta_c_test.slope", "", "1/mu"}, {"theta_c_test.mu", "", ""}, {"theta_c_test.intercept", "", "0 for model B"},
        {"theta_c_test.verdict", "", ""}, {"theta_c_test.n_runs", "", ""}, {"theta_c_note", "", ""},
        {"normal_friction", "", "eq b over the runs, null: no run tested"}, {"normal_friction.normal_accel", "m/s^2", "f_N/m, weighted mean"},
        {"normal_friction.sigma_normal_accel_scaled", "m/s^2", ""}, {"normal_friction.chi2", "", ""},
        {"normal_friction.dof", "", ""}, {"normal_friction.p_value", "", ""}, {"normal_friction.verdict", "", ""},
        {"normal_friction.n_runs", "", ""}, {"normal_friction.n_runs_present", "", ""}, {"normal_friction_note", "", ""},
        {"warnings", "", ""}, {"n_runs", "", ""}, {"n_ok", "", ""}, {"n_failed", "", ""}, {"failed", "", "files that failed"},
    };
    const std::pair<const char*, const char*> relations[] = {
        {"t_stop_v0", "s"}, {"x_stop_v0sq", "m"}, {"y_stop_v0sq", "m"}, {"y_stop_x_stop", "m"}};
    for (const auto& [name, ordinate] : relations) {
      const std::string r = std::string("stop_scaling.") + name + ".";
      const std::string slope_unit = std::string(name) == "y_stop_x_stop" ? "" : "s^2/m";
      keys.push_back({r + "slope", slope_unit, "fitted through the origin"});
      keys.push_back({r + "slope_model", slope_unit, "the slope model B gives with the mean mu"});
      keys.push_back({r + "n", "", "stopping runs"});
      keys.push_back({r + "rms", ordinate, "of the residuals"});
      keys.push_back({r + "mu", "", "from the slope"});
    }
    return keys;
  }();
  return k;
}

const ResultKeys& incline_mu_from_slide_series_result_keys() {
  static const ResultKeys k = {
      {"mu", "", "weighted mean of the runs' mu"}, {"sigma_mu_scaled", "", "sigma_mu times the Birge ratio when above 1"},
      {"chi2", "", ""}, {"dof", "", ""}, {"p_value", "", ""}, {"birge_ratio", "", "sqrt(chi2/dof)"}, {"n_mu", "", ""},
      {"mu_pulls", "", "(mu_i - mean) / sigma_i, per run"}, {"outliers", "", ""}, {"note", "", ""}, {"warnings", "", ""},
      {"n_runs", "", ""}, {"n_ok", "", ""}, {"n_failed", "", ""}, {"failed", "", "files that failed"},
  };
  return k;
}

}  // namespace tribolab::app
