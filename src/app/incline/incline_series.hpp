// The JSON of the series summaries of `incline analyze` and `incline mu-from-slide` over
// several files (docs/cli.md#several-runs). The keys of every run's own object are those of
// the single-file command.
#pragma once

#include "analysis/incline_series.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace tribolab::app {

/// The incline analyze summary's own keys (added to series_counts()): mu, sigma_mu, chi2,
/// dof, p_value, ..., stop_scaling, theta_c_test, normal_friction. `n_runs` = all runs
/// (failed included): mu_pulls has one entry per run, null where a run gave no mu;
/// `run_of_point[j]` is the run index of the j-th point given to the summary.
nlohmann::json incline_series_json(const analysis::InclineSeriesSummary& s, std::size_t n_runs,
                                   const std::vector<std::size_t>& run_of_point);

/// The mu-from-slide summary's own keys: mu, sigma_mu, chi2, dof, p_value, mu_pulls, outliers.
nlohmann::json slide_series_json(const analysis::SlideSeriesSummary& s, std::size_t n_runs,
                                 const std::vector<std::size_t>& run_of_point);

/// The weighted-mean keys of `m` under names "<prefix>", "sigma_<prefix>", ... as used by both.
void add_weighted_mean(nlohmann::json& j, const std::optional<analysis::WeightedMean>& m, const std::string& name);

/// The series' plausibility warnings (the JSON key "warnings" of its summary): runs that
/// contradict each other on mu (docs/theory.md#plausibility-checks).
std::vector<std::string> series_warnings(const std::optional<analysis::WeightedMean>& mu,
                                         const std::vector<std::string>& outliers);

}  // namespace tribolab::app
