// First touch and separation of an analysed bounce, located on the fitted flights and the
// ball's geometry, and the quantities taken there (collision angle, e as `bounce simulate`
// defines it, contact-point velocity, contact duration, mean normal force), with uncertainties
// propagated from the fit covariances and the floor. Internal to analyze_bounce.
// docs/theory.md#bounce-analysis.
#pragma once

#include "analysis/bounce_analyze.hpp"

namespace tribolab::analysis::detail {

/// Fills the touch/separation fields of `r` (and e_velocity, collision_angle_deg, energies,
/// mean normal force). Needs r's segment fits, impact_time, floor_y and floor_method.
/// `t1`, `t4`: the floor bracket's sure-flight frames; `frame_dt`: median frame period, s.
/// Throws InputError when the floor lies above the ball in a flight (a wrong floor_y).
void locate_touch(const BounceAnalyzeOptions& options, double frame_dt, double t1, double t4,
                  BounceAnalysis& r);

}  // namespace tribolab::analysis::detail
