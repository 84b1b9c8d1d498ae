// The JSON of `bounce analyze` over several files (docs/cli.md#bounce-analyze): the summary's
// own keys (e against the collision angle, e > 1, energies, mean force, contact-point speed,
// outliers, and the per-run points the figures draw). Each run's own object is the single-file
// command's.
#pragma once

#include "analysis/bounce_analyze.hpp"
#include "analysis/bounce_series.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace tribolab::app {

/// The bounce summary's own keys (series_counts() adds n_runs, n_ok, n_failed, failed).
/// `files[j]` is the file of points[j] (names the fastest/slowest runs, outliers, points).
nlohmann::json bounce_series_json(const analysis::BounceSeriesSummary& s,
                                  const std::vector<analysis::BounceSeriesPoint>& points,
                                  const std::vector<std::string>& files,
                                  const analysis::BounceSeriesOptions& options);

}  // namespace tribolab::app
