// A series of runs (seed 000 launched many discs; seed 001 threw the ball 120 times): the same
// analysis applied to N inputs in parallel, each run's outcome kept - its result, or the
// error that stopped it - so one bad file never loses the others. Outcomes come back in input
// order whatever the thread count. See docs/design.md#series-of-runs.
//
//   analysis::SeriesOptions o;
//   o.progress = [](const analysis::SeriesProgress& p) { ... };   // optional
//   auto runs = analysis::run_series<MyResult>(files, [&](std::size_t i, const std::string& f) {
//     return analyse(read(f), options[i]);                           // may throw InputError
//   }, o);
//   for (const auto& r : runs) r.ok() ? use(*r.result) : report(r.error);
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tribolab::analysis {

/// Where a series stands, reported after every finished run.
struct SeriesProgress {
  std::size_t done = 0;    ///< runs finished (succeeded or failed)
  std::size_t failed = 0;  ///< of which failed
  std::size_t total = 0;   ///< runs in the series
  std::size_t last = 0;    ///< index of the run that just finished
  double elapsed_s = 0;    ///< wall time since the series started, s
};

struct SeriesOptions {
  /// Worker threads; 0 = all cores (std::thread::hardware_concurrency()).
  int threads = 0;
  /// Called after each run finishes, from the worker that ran it; calls are serialised
  /// (never two at once), so the callback needs no lock of its own. May be empty.
  std::function<void(const SeriesProgress&)> progress;

  /// Empty when valid (threads >= 0).
  std::string validate() const;
};

/// Why one run failed: the exception's whole message, its fields still marked (field("max_gap"),
/// numerics/error.hpp: each front end spells them), and, for an InputError, where it points
/// ("file.csv:12", "phi_deg"; empty when it named no place).
struct RunError {
  std::string message;
  std::string where;
};

/// One run of a series: its input's name and either its result or its error.
template <class Result>
struct RunOutcome {
  std::string source;             ///< the input (usually a file path)
  std::optional<Result> result;   ///< set when the run succeeded
  std::optional<RunError> error;  ///< set when it failed

  bool ok() const { return result.has_value(); }
  /// One line naming the input and what went wrong, e.g. "b.csv: no motion" or
  /// "b.csv:12: malformed number" (the source is not repeated when the message starts with
  /// it). Empty for a run that succeeded.
  std::string located_error() const;
};

/// The untyped core of run_series: calls job(i) for every i in [0, n) on the option's
/// threads and returns, per index, the error it threw (empty optional: it returned).
/// Any std::exception (and anything else thrown) is caught and kept; nothing is rethrown.
std::vector<std::optional<RunError>> run_each(std::size_t n, const std::function<void(std::size_t)>& job,
                                              const SeriesOptions& options = {});

/// "source: message" unless the message already starts with the source.
std::string locate(const std::string& source, const std::string& message);

/// Runs `run(i, sources[i])` (returning a Result, or throwing: typically InputError) for
/// every input, in parallel, and returns the outcomes in input order. `run` is called
/// concurrently from several threads: it must not share mutable state between runs.
template <class Result, class Run>
std::vector<RunOutcome<Result>> run_series(const std::vector<std::string>& sources, Run&& run,
                                           const SeriesOptions& options = {}) {
  std::vector<RunOutcome<Result>> out(sources.size());
  const auto errors = run_each(
      sources.size(), [&](std::size_t i) { out[i].result.emplace(run(i, sources[i])); }, options);
  for (std::size_t i = 0; i < sources.size(); ++i) {
    out[i].source = sources[i];
    if (errors[i]) {
      out[i].result.reset();
      out[i].error = errors[i];
    }
  }
  return out;
}

template <class Result>
std::string RunOutcome<Result>::located_error() const {
  return error ? locate(source, error->message) : std::string();
}

/// Number of outcomes that failed.
template <class Result>
std::size_t count_failed(const std::vector<RunOutcome<Result>>& runs) {
  std::size_t n = 0;
  for (const auto& r : runs) n += r.ok() ? 0 : 1;
  return n;
}

}  // namespace tribolab::analysis
