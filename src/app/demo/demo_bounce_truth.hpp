// A bounce analysed from film beside the truth of the simulation that made the film: each
// quantity's value ± sigma, the truth, and whether the truth lies inside the 95 % interval
// value ± 1.96 sigma. Shared by the demo's case studies on shipped and rendered throws.
#pragma once

#include "analysis/bounce_analyze.hpp"
#include "analysis/bounce_synth.hpp"
#include "bounce/geometry.hpp"
#include "report/report.hpp"

#include <string>
#include <vector>

namespace tribolab::app {

inline constexpr double kZ95 = 1.959964;  ///< two-sided 95 % normal quantile

/// One analysed quantity and its truth.
struct TruthCheck {
  std::string quantity;  ///< with unit, e.g. "v_x before (m/s)"
  double value = 0, sigma = 0, truth = 0;
  /// |value - truth| <= 1.96 sigma (false when value or sigma is not finite).
  bool covered() const;
};

/// v_x, v_y, ω before and after (v_y at the analysed impact time, the truth's free flights
/// there), e from velocities and heights, apex heights, first touch, separation, collision
/// angle at the touch, e at one instant.
std::vector<TruthCheck> bounce_truth_checks(const analysis::BounceAnalysis& r, const analysis::SynthVideoTruth& t,
                                            const bounce::Ball& ball);

/// The checks as a table ("quantity", "tribolab (± 1 s.u.)", "truth", "truth in the 95%
/// interval"), with the orientation and the impact time (no interval) at the end.
report::Table bounce_truth_table(const analysis::BounceAnalysis& r, const analysis::SynthVideoTruth& t,
                                 const bounce::Ball& ball);

}  // namespace tribolab::app
