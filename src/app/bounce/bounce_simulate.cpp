#include "app/common/study_citation.hpp"
#include "app/bounce/bounce_simulate.hpp"

#include "app/common/json_number.hpp"
#include "app/common/output_paths.hpp"

#include "app/bounce/report_bounce.hpp"

#include "bounce/geometry.hpp"
#include "io/atomic_file.hpp"
#include "io/text.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"
#include "report/html.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace tribolab::app {
namespace {

using namespace tribolab::bounce;
using nlohmann::json;

json energy_parts_json(const KineticEnergy& e) {
  return {{"translational_x", e.translational_x}, {"translational_y", e.translational_y},
          {"rotational", e.rotational}, {"total", e.total()}};
}

json contact_json(const Ball& ball, const ContactResult& r, NormalModel model) {
  json phases = json::array();
  for (std::size_t i = 0; i < std::min(r.n_phases, kMaxStoredPhases); ++i) {
    phases.push_back({{"kind", std::string(to_string(r.phases[i].kind))},
                      {"t_start", r.phases[i].t_start}, {"t_end", r.phases[i].t_end}});
  }
  return {
      {"status", std::string(to_string(r.status))},
      {"vx", r.out.vx},
      {"vy", r.out.vy},
      {"omega", r.out.omega},
      {"theta_out_deg", to_deg(wrap_angle(r.out.theta))},
      {"e", json_number(r.restitution)},
      {"contact_duration", r.contact_duration},
      {"peak_force", r.peak_force},
      {"t_peak", r.t_peak},
      {"max_penetration", r.max_penetration},
      {"impulse_normal", r.impulse_normal},
      {"impulse_tangential", r.impulse_tangential},
      {"v_in_normal", r.v_in_normal},
      {"slip_velocity_in", r.v_t_in},
      {"slip_velocity_out", r.v_t_out},
      {"collision_angle_deg", collision_angle_deg(ball, r.in.theta, r.in.vx < 0 ? -1 : 1)},
      {"energy_in", r.energy_in.total()},
      {"energy_out", r.energy_out.total()},
      {"energy_in_parts", energy_parts_json(r.energy_in)},
      {"energy_out_parts", energy_parts_json(r.energy_out)},
      {"work_gravity", r.work_gravity},
      {"dissipated_normal", r.dissipated_normal},
      {"dissipated_friction", r.dissipated_friction},
      {"energy_residual", r.energy_residual},
      {"law", {{"model", std::string(to_string(model))}, {"K", r.law.K}, {"n", r.law.n}, {"D", r.law.D}}},
      {"n_phases", r.n_phases},
      {"phases", phases},
      {"steps", r.steps},
  };
}

void write_history(const std::string& path, const std::vector<ContactSample>& hist) {
  io::AtomicFile file(path);
  auto& out = file.stream();
  out << "t,x,y,theta,vx,vy,omega,d,d_dot,N,f,v_t,phase\n";
  for (const ContactSample& c : hist) {
    const BodyState& s = c.state;
    for (double v : {c.t, s.x, s.y, s.theta, s.vx, s.vy, s.omega, c.d, c.d_dot, c.N, c.f, c.v_t})
      out << io::format_number(v) << ',';
    out << to_string(c.phase) << '\n';
  }
  file.commit();
}

void write_trajectory(const std::string& path, const std::vector<TrajectorySample>& traj) {
  io::AtomicFile file(path);
  auto& out = file.stream();
  out << "t,x,y,theta,vx,vy,omega,in_contact\n";
  for (const TrajectorySample& p : traj) {
    const BodyState& s = p.state;
    for (double v : {p.t, s.x, s.y, s.theta, s.vx, s.vy, s.omega}) out << io::format_number(v) << ',';
    out << (p.in_contact ? 1 : 0) << '\n';
  }
  file.commit();
}

json drop_bounce_json(const Bounce& b) {
  return {{"t_touch", b.t_touch},
          {"theta_touch_deg", to_deg(wrap_angle(b.touch.theta))},
          {"vx_in", b.touch.vx},
          {"vy_in", b.touch.vy},
          {"omega_in", b.touch.omega},
          {"collision_angle_deg", b.collision_angle_deg},
          {"vx_out", b.contact.out.vx},
          {"vy_out", b.contact.out.vy},
          {"omega_out", b.contact.out.omega},
          {"e", json_number(b.contact.restitution)},
          {"contact_duration", b.contact.contact_duration},
          {"peak_force", b.contact.peak_force},
          {"t_apex", b.t_apex},
          {"apex_height", b.apex_height},
          {"above_release", b.above_release},
          {"t_cross_release", b.t_cross_release >= 0 ? json(b.t_cross_release) : json(nullptr)}};
}

}  // namespace

json bounce_impact_json(const Ball& ball, const ImpactResult& r, NormalModel model) {
  json j = contact_json(ball, r.whole, model);
  j["impact_status"] = std::string(to_string(r.status));
  j["contacts"] = r.contacts;
  const ContactResult& f = r.first;
  j["first_phase"] = {{"vx", f.out.vx},
                      {"vy", f.out.vy},
                      {"omega", f.out.omega},
                      {"e", json_number(f.restitution)},
                      {"contact_duration", f.contact_duration},
                      {"peak_force", f.peak_force},
                      {"energy_out", f.energy_out.total()}};
  json list = json::array();
  for (std::size_t i = 0; i < std::min(r.contacts, kMaxStoredContacts); ++i) {
    const ImpactContact& c = r.contact[i];
    list.push_back({{"t_touch", c.t_touch}, {"t_separation", c.t_separation}, {"vy_in", c.vy_in},
                    {"vy_out", c.vy_out}, {"peak_force", c.peak_force}});
  }
  j["contact_list"] = list;
  return j;
}

BounceContactTimeResult bounce_contact_time(const BounceContactTimeOptions& o) {
  check_output_paths({}, {{"report", o.report}});  // before any work (app/common/output_paths.hpp)
  const Ball ball = o.ball.get();
  check_ranges(o, bounce_contact_time_fields());  // docs/cli.md#physical-ranges
  if (o.direction != 1 && o.direction != -1) throw InputError(field("direction"), "must be 1 or -1");
  FlightOptions fo;
  fo.g = checked_g(o.g);
  BounceContactTimeResult res;
  const FlightResult& r = res.flight = first_contact_from_apex(ball, o.height, o.omega, to_rad(o.theta_deg), fo);
  if (r.status == FlightStatus::touching_start) throw InputError(field("height"), r.message);
  if (r.status != FlightStatus::contact) throw InputError(r.message);
  // The flight from the apex to the contact, closed form (docs/theory.md#bounce-flight): the
  // report's gap and orientation curves.
  const BodyState apex{0, o.height, to_rad(o.theta_deg), 0, 0, o.omega};
  constexpr int n = 800;
  res.samples.reserve(n + 1);
  for (int i = 0; i <= n; ++i) {
    const double t = r.t_contact * i / n;
    const BodyState st = free_flight(apex, fo.g, t);
    res.samples.push_back({t, st, st.y - support_depth(ball, st.theta)});
  }
  if (!o.report.empty()) report::write_html(with_study_source(bounce_contact_time_report(ball, apex, o.direction, r, res.samples), Study::rugby_ball), o.report, o.plotly);
  res.json = {{"t_contact", r.t_contact},
              {"theta_contact_deg", to_deg(wrap_angle(r.state.theta))},
              {"contact_point", {r.contact_x, r.contact_y}},
              {"vx", r.state.vx},
              {"vy", r.state.vy},
              {"omega", r.state.omega},
              {"contact_point_velocity", {r.contact_velocity.vx, r.contact_velocity.vy}},
              {"collision_angle_deg", collision_angle_deg(ball, r.state.theta, o.direction)},
              {"t_min", r.t_min},
              {"t_max", r.t_max},
              {"grazing", r.grazing}};
  return res;
}

BounceSimulateResult bounce_simulate(const BounceSimulateOptions& o) {
  check_output_paths({}, {{"history", o.history}, {"report", o.report}});  // before any work (app/common/output_paths.hpp)
  const Ball ball = o.ball.get();
  check_ranges(o, bounce_simulate_fields());  // docs/cli.md#physical-ranges
  const NormalLawSpec spec = o.law.law();
  const FrictionModel fr = o.law.friction_model();
  const ContactOptions copt = o.law.contact(checked_g(o.g, /*zero_allowed=*/true));  // starts at touch
  if (!(o.vy < 0)) throw InputError(field("vy"), "the ball must be falling at first touch (vy < 0)");
  BodyState s;
  s.theta = to_rad(o.theta_deg);
  s.vx = o.vx;
  s.vy = o.vy;
  s.omega = o.omega;
  const PointVelocity pv = contact_point_velocity(ball, s.theta, s.vx, s.vy, s.omega);
  if (!(pv.vy < 0)) {
    throw InputError(field("omega"), "the contact point moves away from the floor at first touch (its vertical velocity "
                                "vy + omega X = " + io::format_number(pv.vy) + " m/s): no contact");
  }
  BounceSimulateResult res;
  ImpactOptions io;
  io.contact = copt;
  // The history is always kept: a notebook wants it, and recording it does not change the
  // integration (the samples are the accepted steps).
  const ImpactResult& r = res.impact = simulate_impact(ball, spec, fr, s, io, &res.history);
  if (r.status == ImpactStatus::failed || r.status == ImpactStatus::max_contacts)
    throw SolverError(std::string("contact simulation failed: ") + std::string(r.message));
  if (!o.report.empty())
    report::write_html(with_study_source(bounce_simulate_report(ball, fr, copt.g, r.whole, res.history, r.contacts), Study::rugby_ball), o.report, o.plotly);
  if (!o.history.empty()) write_history(o.history, res.history);
  res.json = bounce_impact_json(ball, r, spec.model);
  return res;
}

BounceDropResult bounce_drop(const BounceDropOptions& o) {
  check_output_paths({}, {{"trajectory", o.trajectory}, {"report", o.report}});  // before any work (app/common/output_paths.hpp)
  const Ball ball = o.ball.get();
  check_ranges(o, bounce_drop_fields());  // docs/cli.md#physical-ranges
  const bool sampled = !(o.trajectory.empty() && o.report.empty()) || o.keep_trajectory;
  if (sampled && !(o.sample_dt > 0)) throw InputError(field("sample_dt"), "must be positive");
  const NormalLawSpec spec = o.law.law();
  const FrictionModel fr = o.law.friction_model();
  DropOptions d;
  d.flight.g = checked_g(o.g);
  d.contact = o.law.contact(d.flight.g);
  d.max_bounces = static_cast<std::size_t>(o.bounces);
  d.rest_height = o.rest_height;
  d.sample_dt = sampled ? o.sample_dt : 0.0;
  DropRelease rel;
  rel.height = o.height;
  rel.theta = to_rad(o.theta_deg);
  rel.omega = o.omega;
  rel.vx = o.vx;
  rel.vy = o.vy;
  BounceDropResult res;
  res.drop = simulate_drop(ball, spec, fr, rel, d);
  const DropResult& r = res.drop;
  if (r.status == DropStatus::failed) throw SolverError("drop simulation failed: " + r.message);
  json bounces = json::array();
  json apexes = json::array();
  for (const Bounce& b : r.bounces) {
    bounces.push_back(drop_bounce_json(b));
    apexes.push_back(b.apex_height);
  }
  if (!o.report.empty()) report::write_html(with_study_source(bounce_drop_report(ball, fr, rel, r), Study::rugby_ball), o.report, o.plotly);
  if (!o.trajectory.empty()) write_trajectory(o.trajectory, r.trajectory);
  res.trajectory = r.trajectory;
  res.json = {{"status", std::string(to_string(r.status))},
              {"release_apex", r.release_apex},
              {"n_bounces", r.bounces.size()},
              {"apex_heights", apexes},
              {"rebounds_above_release", r.first_above_release >= 0},
              {"first_above_release", r.first_above_release >= 0 ? json(r.first_above_release + 1) : json(nullptr)},
              {"t_above_release", r.first_above_release >= 0 ? json(r.bounces[r.first_above_release].t_cross_release)
                                                               : json(nullptr)},
              {"bounces", bounces}};
  return res;
}

namespace {

/// The keys of one contact or impact object (contact_json, bounce_impact_json), under `p`.
ResultKeys impact_keys() {
  ResultKeys k = {
      {"status", "", "separated or max_duration, of the last contact"},
      {"impact_status", "", "free_flight or rest"},
      {"contacts", "", "number of contacts of the impact"},
      {"vx", "m/s", "centre velocity after the last separation"},
      {"vy", "m/s", "centre velocity after the last separation"},
      {"omega", "rad/s", "spin after the last separation"},
      {"theta_out_deg", "deg", "orientation at the last separation"},
      {"e", "", "restitution -vy_out/vy_in"},
      {"contact_duration", "s", "first touch to the last separation"},
      {"peak_force", "N", "largest normal force"},
      {"t_peak", "s", "time of the peak force from the first touch"},
      {"max_penetration", "m", "largest penetration"},
      {"impulse_normal", "N s", "integral of N over all contacts"},
      {"impulse_tangential", "N s", "integral of f over all contacts"},
      {"v_in_normal", "m/s", "approach speed of the contact point at touch"},
      {"slip_velocity_in", "m/s", "v_t at the first touch"},
      {"slip_velocity_out", "m/s", "v_t at the last separation"},
      {"collision_angle_deg", "deg", "the study's collision angle at touch"},
      {"energy_in", "J", "kinetic energy at the first touch"},
      {"energy_out", "J", "kinetic energy at the last separation"},
      {"energy_in_parts.*", "J", "translational_x, translational_y, rotational, total"},
      {"energy_out_parts.*", "J", "translational_x, translational_y, rotational, total"},
      {"work_gravity", "J", "work of gravity over the impact"},
      {"dissipated_normal", "J", "energy taken by normal damping"},
      {"dissipated_friction", "J", "energy taken by friction"},
      {"energy_residual", "J", "numerical residual of the energy balance"},
      {"n_phases", "", "number of friction phases"},
      {"phases.kind", "", "slip+, slip-, stick or smooth"},
      {"phases.t_start", "s", "from the first touch"},
      {"phases.t_end", "s", "from the first touch"},
      {"steps", "", "accepted integrator steps"},
      {"first_phase.vx", "m/s", ""},
      {"first_phase.vy", "m/s", ""},
      {"first_phase.omega", "rad/s", ""},
      {"first_phase.e", "", ""},
      {"first_phase.contact_duration", "s", ""},
      {"first_phase.peak_force", "N", ""},
      {"first_phase.energy_out", "J", ""},
      {"contact_list.t_touch", "s", "from the first touch"},
      {"contact_list.t_separation", "s", "from the first touch"},
      {"contact_list.vy_in", "m/s", ""},
      {"contact_list.vy_out", "m/s", ""},
      {"contact_list.peak_force", "N", ""},
  };
  for (ResultKey& l : law_result_keys("law.")) k.push_back(std::move(l));
  return k;
}

}  // namespace

const ResultKeys& bounce_contact_time_result_keys() {
  static const ResultKeys k = {
      {"t_contact", "s", "time from the apex to first contact"},
      {"theta_contact_deg", "deg", "orientation at contact"},
      {"contact_point", "m", "[x, y] of the contact point relative to the centre"},
      {"vx", "m/s", "centre velocity at contact"},
      {"vy", "m/s", "centre velocity at contact"},
      {"omega", "rad/s", "spin at contact"},
      {"contact_point_velocity", "m/s", "[vx, vy] of the material contact point"},
      {"collision_angle_deg", "deg", "the study's collision angle"},
      {"t_min", "s", "earliest possible contact"},
      {"t_max", "s", "latest possible contact"},
      {"grazing", "", "true when the gap only touched zero"},
  };
  return k;
}

const ResultKeys& bounce_simulate_result_keys() {
  static const ResultKeys k = impact_keys();
  return k;
}

const ResultKeys& bounce_drop_result_keys() {
  static const ResultKeys k = {
      {"status", "", "max_bounces or rest"},
      {"release_apex", "m", "highest centre height before the first touch"},
      {"n_bounces", "", "contacts simulated"},
      {"apex_heights", "m", "centre apex after each contact"},
      {"rebounds_above_release", "", "true when some apex exceeds release_apex"},
      {"first_above_release", "", "1-based index of the first such bounce"},
      {"t_above_release", "s", "time the centre first rises through release_apex"},
      {"bounces.t_touch", "s", ""},
      {"bounces.theta_touch_deg", "deg", ""},
      {"bounces.vx_in", "m/s", ""},
      {"bounces.vy_in", "m/s", ""},
      {"bounces.omega_in", "rad/s", ""},
      {"bounces.collision_angle_deg", "deg", ""},
      {"bounces.vx_out", "m/s", ""},
      {"bounces.vy_out", "m/s", ""},
      {"bounces.omega_out", "rad/s", ""},
      {"bounces.e", "", "restitution"},
      {"bounces.contact_duration", "s", ""},
      {"bounces.peak_force", "N", ""},
      {"bounces.t_apex", "s", ""},
      {"bounces.apex_height", "m", ""},
      {"bounces.above_release", "", ""},
      {"bounces.t_cross_release", "s", "or null"},
  };
  return k;
}

}  // namespace tribolab::app
