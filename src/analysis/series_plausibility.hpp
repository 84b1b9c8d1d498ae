// Plausibility checks across the runs of a series: runs that contradict each other where
// physics says they must agree (one friction coefficient for one surface, one gravity and one
// ball length for every throw filmed of one ball). docs/theory.md#plausibility-checks.
#pragma once

#include "analysis/bounce_analyze.hpp"
#include "analysis/series_stats.hpp"

#include <string>
#include <vector>

namespace tribolab::analysis {

/// p-value of the chi-square test below which the runs are said to contradict each other.
constexpr double kContradictionP = 1e-3;

/// A warning when the weighted mean's chi-square test rejects one common value of `what`
/// (p < kContradictionP): the runs scatter beyond their stated uncertainties. `outliers`
/// (plain text, may be empty) are named. Empty string when they agree or dof = 0.
std::string disagreement_warning(const WeightedMean& m, const std::string& what,
                                 const std::vector<std::string>& outliers);

/// Runs of one bounce series (`files[i]` analysed as `runs[i]`; a null run failed) whose
/// gravity or tip distance stands apart from the others' median: a different time scale or
/// length calibration for that file (5 % and 5 sd for gravity, 3 % for the tip distance).
std::vector<std::string> bounce_series_warnings(const std::vector<const BounceAnalysis*>& runs,
                                                const std::vector<std::string>& files);

}  // namespace tribolab::analysis
