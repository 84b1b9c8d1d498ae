#include "app/demo/demo_bounce_truth.hpp"

#include "report/format.hpp"
#include "numerics/units.hpp"

#include <cmath>
#include <numbers>

namespace tribolab::app {

bool TruthCheck::covered() const {
  return std::isfinite(value) && std::isfinite(sigma) && std::abs(value - truth) <= kZ95 * sigma;
}

std::vector<TruthCheck> bounce_truth_checks(const analysis::BounceAnalysis& r, const analysis::SynthVideoTruth& t,
                                            const bounce::Ball& ball) {
  const double ti = r.impact_time;
  const double vy_pre = t.vy_flight(true, ti), vy_post = t.vy_flight(false, ti);
  return {{"v_x before (m/s)", r.pre.vx, r.pre.sigma_vx, t.touch.vx},
          {"v_y before (m/s)", r.pre.vy, r.pre.sigma_vy, vy_pre},
          {"ω before (rad/s)", r.pre.omega, r.pre.sigma_omega, t.touch.omega},
          {"v_x after (m/s)", r.post.vx, r.post.sigma_vx, t.separation.vx},
          {"v_y after (m/s)", r.post.vy, r.post.sigma_vy, vy_post},
          {"ω after (rad/s)", r.post.omega, r.post.sigma_omega, t.separation.omega},
          {"e from velocities", r.e_velocity, r.sigma_e_velocity, -t.separation.vy / t.touch.vy},
          {"e from apex heights", r.e_height, r.sigma_e_height, std::sqrt(t.post_apex / t.release_apex)},
          {"apex height before (m)", r.pre.apex_height, r.pre.sigma_apex_height, t.release_apex},
          {"apex height after (m)", r.post.apex_height, r.post.sigma_apex_height, t.post_apex},
          {"first touch (s)", r.t_touch, r.sigma_t_touch, t.t_touch},
          {"separation (s)", r.t_separation, r.sigma_t_separation, t.t_separation},
          {"collision angle at the touch (deg)", r.collision_angle_deg, r.sigma_collision_angle_deg,
           bounce::collision_angle_deg(ball, t.touch.theta, t.touch.vx < 0 ? -1 : 1)},
          {"e at one instant (impact time)", r.e_velocity_common, r.sigma_e_velocity_common, -vy_post / vy_pre}};
}

report::Table bounce_truth_table(const analysis::BounceAnalysis& r, const analysis::SynthVideoTruth& t,
                                 const bounce::Ball& ball) {
  report::Table tab;
  tab.caption = "Recovered vs the simulation's truth (v_y at the analysed impact time; e from velocities from "
                "the first touch to the separation, as the contact simulation defines it)";
  tab.header = {"quantity", "tribolab (± 1 s.u.)", "truth", "truth in the 95% interval"};
  for (const TruthCheck& c : bounce_truth_checks(r, t, ball)) {
    const bool defined = std::isfinite(c.value) && std::isfinite(c.sigma);
    tab.rows.push_back({c.quantity, report::format_uncertain(c.value, c.sigma), report::format_value(c.truth),
                        defined ? (c.covered() ? "yes" : "no") : "—"});
  }
  const double ti = r.impact_time;
  const double theta_true = bounce::wrap_angle(t.touch.theta + t.touch.omega * (ti - t.t_touch)) * kDegPerRad;
  tab.rows.push_back({"θ at the impact time (deg)", report::format_value(r.theta_impact_deg), report::format_value(theta_true), "—"});
  tab.rows.push_back({"impact time (s)", report::format_value(ti), report::format_value(t.t_touch) + " – " + report::format_value(t.t_separation),
                      ti >= t.t_touch && ti <= t.t_separation ? "within the contact" : "outside the contact"});
  return tab;
}

}  // namespace tribolab::app
