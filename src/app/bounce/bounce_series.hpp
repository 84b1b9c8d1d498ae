// `bounce analyze` over one or several files (docs/cli.md#bounce-analyze, seed 001 experiments
// 1 and 2) as one workflow: every file as the single-file workflow analyses it (in parallel),
// then the summary (e against the collision angle, e > 1, energies, mean force, contact-point
// speed, outliers, and the per-run points the figures draw), --bounces-out and the report.
// Each run's own object is the single-file command's.
#pragma once

#include "app/bounce/bounce_analyze.hpp"

#include "analysis/bounce_analyze.hpp"
#include "analysis/bounce_series.hpp"
#include "analysis/series.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace tribolab::app {

/// `bounce analyze FILE...`: one file, or several as a series.
struct BounceAnalyzeSeriesOptions {
  std::vector<std::string> files;  ///< Tracker .trk/.trz, Export Data text or tidy CSV (required); several: a series
  /// Every option shared by the files (its file, floor_y and contact_duration are not used).
  BounceAnalyzeOptions each;
  /// Floor height in the file's frame, m: one for every file, or one per file; empty = from the flights.
  std::vector<double> floor_y;
  /// Contact duration, s: one for every file, or one per file; empty = located.
  std::vector<double> contact_duration;
  analysis::SeriesOptions series;  ///< threads and progress (several files only)

  /// One BounceAnalyzeOptions per file, each checked (InputError naming the field) before any work.
  std::vector<BounceAnalyzeOptions> per_file() const;
};

/// The declaration of `bounce analyze FILE...` (the command line binds from it): the one-file
/// command's fields (bounce_analyze_fields) in their order, `file` as the list `files`, and
/// floor_y and contact_duration as one value for every file or one per file.
const Fields<BounceAnalyzeSeriesOptions>& bounce_analyze_series_fields();

/// One file of a `bounce analyze` series.
struct BounceAnalyzeRun {
  std::string file;
  std::optional<BounceAnalyzeResult> result;  ///< unset when the run failed
  std::string error;                          ///< why it failed (series only; one file throws instead)
};

struct BounceAnalyzeSeriesResult {
  /// Exactly what `bounce analyze --json` prints: the run's object for one file, else
  /// {"runs": [...], "summary": {...}}.
  nlohmann::json json;
  std::vector<BounceAnalyzeRun> runs;  ///< one per file, input order
  std::vector<std::string> errors;     ///< the failed runs' located errors (series)
};

/// `bounce analyze` over `o.files`: one file as bounce_analyze(), several as a series with a
/// summary, --bounces-out of every analysed run and the series report.
BounceAnalyzeSeriesResult bounce_analyze_series(const BounceAnalyzeSeriesOptions& o);

/// The bounce summary's own keys (series_counts() adds n_runs, n_ok, n_failed, failed).
/// `files[j]` is the file of points[j] (names the fastest/slowest runs, outliers, points).
nlohmann::json bounce_series_json(const analysis::BounceSeriesSummary& s,
                                  const std::vector<analysis::BounceSeriesPoint>& points,
                                  const std::vector<std::string>& files,
                                  const analysis::BounceSeriesOptions& options);

}  // namespace tribolab::app
