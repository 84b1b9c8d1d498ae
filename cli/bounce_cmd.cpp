// `tribolab bounce`: the spinning-ellipse bounce of seed 001 (docs/cli.md#bounce).
//   contact-time  first contact after release from an apex (seed's experiment 3, table 4)
//   simulate      the impact from first touch to free flight (seed's experiment 4), every
//                 contact of it (docs/theory.md#bounce-contact, "whole impact")
//   drop          release -> flight -> contact -> ... several bounces
#include "app.hpp"
#include "bounce_analysis_cmd.hpp"
#include "bounce_options.hpp"
#include "bounce_render_cmd.hpp"
#include "app/report_bounce.hpp"
#include "report_option.hpp"
#include "bounce_sweep_cmd.hpp"

#include "bounce/contact.hpp"
#include "bounce/drop.hpp"
#include "bounce/flight.hpp"
#include "bounce/impact.hpp"
#include "io/atomic_file.hpp"
#include "io/text.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace tribolab::cli {
namespace {

using namespace tribolab::bounce;
using nlohmann::json;

constexpr double kDeg = 180.0 / std::numbers::pi;

/// NaN/inf become JSON null (e.g. e when vy_in = 0).
json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }


json energy_json(const KineticEnergy& e) {
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
      {"theta_out_deg", wrap_angle(r.out.theta) * kDeg},
      {"e", num(r.restitution)},
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
      {"energy_in_parts", energy_json(r.energy_in)},
      {"energy_out_parts", energy_json(r.energy_out)},
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

/// The whole impact: contact_json of the summed result, the number of contacts, the first
/// contact phase alone and each contact's times (docs/cli.md#bounce-simulate).
json impact_json(const Ball& ball, const ImpactResult& r, NormalModel model) {
  json j = contact_json(ball, r.whole, model);
  j["impact_status"] = std::string(to_string(r.status));
  j["contacts"] = r.contacts;
  const ContactResult& f = r.first;
  j["first_phase"] = {{"vx", f.out.vx},
                      {"vy", f.out.vy},
                      {"omega", f.out.omega},
                      {"e", num(f.restitution)},
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

void add_contact_time(CLI::App* area) {
  struct Opts {
    BallOptions ball;
    double height = 0, omega = 0, theta_deg = 0, g = 9.8;
    int direction = 1;
    bool json = false;
    std::string report;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = area->add_subcommand("contact-time", "First contact of a ball released at an apex (seed 001, table 4)");
  cmd->add_option("--height", o->height, "centre height at the apex, m")->required();
  cmd->add_option("--omega", o->omega, "spin, rad/s, counter-clockwise positive (default 0)");
  cmd->add_option("--theta-deg", o->theta_deg, "major axis from the horizontal at the apex, deg (default 0)");
  cmd->add_option("--direction", o->direction, "direction of motion for the collision angle: 1 (+x) or -1 (default 1)");
  cmd->add_option("--g", o->g, "gravitational acceleration, m/s^2 (default 9.8)");
  add_ball_options(cmd, o->ball);
  add_json_flag(*cmd, o->json);
  add_report_option(*cmd, o->report);
  cmd->callback([o] {
    const Ball ball = o->ball.get();
    check_range(o->height, ranges::height, "--height");  // docs/cli.md#physical-ranges
    check_range(o->omega, ranges::spin, "--omega");
    check_range(o->theta_deg, ranges::angle_deg, "--theta-deg");
    if (o->direction != 1 && o->direction != -1) throw InputError("--direction", "must be 1 or -1");
    FlightOptions fo;
    fo.g = checked_g(o->g);
    const FlightResult r = first_contact_from_apex(ball, o->height, o->omega, o->theta_deg / kDeg, fo);
    if (r.status == FlightStatus::touching_start) throw InputError("--height", r.message);
    if (r.status != FlightStatus::contact) throw InputError(r.message);
    write_report_if_requested(o->report, [&] {
      return bounce_contact_time_report(ball, {0, o->height, o->theta_deg / kDeg, 0, 0, o->omega}, fo.g, o->direction, r);
    });
    print_result({{"t_contact", r.t_contact},
                  {"theta_contact_deg", wrap_angle(r.state.theta) * kDeg},
                  {"contact_point", {r.contact_x, r.contact_y}},
                  {"vx", r.state.vx},
                  {"vy", r.state.vy},
                  {"omega", r.state.omega},
                  {"contact_point_velocity", {r.contact_velocity.vx, r.contact_velocity.vy}},
                  {"collision_angle_deg", collision_angle_deg(ball, r.state.theta, o->direction)},
                  {"t_min", r.t_min},
                  {"t_max", r.t_max},
                  {"grazing", r.grazing}},
                 o->json);
  });
}

void add_simulate(CLI::App* area) {
  struct Opts {
    BallOptions ball;
    LawOptions law;
    double vx = 0, vy = 0, omega = 0, theta_deg = 0, g = 9.8;
    std::string history, report;
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = area->add_subcommand("simulate", "The impact from first touch (gap 0) until the ball flies free to its apex: "
                                               "every contact of it (seed 001, experiment 4)");
  cmd->add_option("--vx", o->vx, "centre velocity at first touch, m/s (default 0)");
  cmd->add_option("--vy", o->vy, "centre velocity at first touch, m/s (< 0)")->required();
  cmd->add_option("--omega", o->omega, "spin at first touch, rad/s, CCW positive (default 0)");
  cmd->add_option("--theta-deg", o->theta_deg, "major axis from the horizontal at first touch, deg (default 0)");
  cmd->add_option("--g", o->g, "gravitational acceleration, m/s^2 (default 9.8)");
  cmd->add_option("--history", o->history, "write the time history to this CSV file");
  add_ball_options(cmd, o->ball);
  add_law_options(cmd, o->law);
  add_json_flag(*cmd, o->json);
  add_report_option(*cmd, o->report);
  cmd->callback([o] {
    const Ball ball = o->ball.get();
    for (auto [v, r, name] : {std::tuple{o->vx, ranges::velocity, "--vx"}, {o->vy, ranges::velocity, "--vy"},
                              {o->omega, ranges::spin, "--omega"}, {o->theta_deg, ranges::angle_deg, "--theta-deg"}})
      check_range(v, r, name);  // docs/cli.md#physical-ranges
    const NormalLawSpec spec = o->law.law();
    const FrictionModel fr = o->law.friction_model();
    const ContactOptions copt = o->law.contact(checked_g(o->g, /*zero_allowed=*/true));  // starts at touch
    if (!(o->vy < 0)) throw InputError("--vy", "the ball must be falling at first touch (vy < 0)");
    BodyState s;
    s.theta = o->theta_deg / kDeg;
    s.vx = o->vx;
    s.vy = o->vy;
    s.omega = o->omega;
    const PointVelocity pv = contact_point_velocity(ball, s.theta, s.vx, s.vy, s.omega);
    if (!(pv.vy < 0)) {
      throw InputError("--omega", "the contact point moves away from the floor at first touch (its vertical velocity "
                                  "vy + omega X = " + io::format_number(pv.vy) + " m/s): no contact");
    }
    std::vector<ContactSample> hist;
    ImpactOptions io;
    io.contact = copt;
    const ImpactResult r = simulate_impact(ball, spec, fr, s, io, o->history.empty() && o->report.empty() ? nullptr : &hist);
    if (r.status == ImpactStatus::failed || r.status == ImpactStatus::max_contacts)
      throw SolverError(std::string("contact simulation failed: ") + std::string(r.message));
    write_report_if_requested(o->report, [&] { return bounce_simulate_report(ball, fr, copt.g, r.whole, hist, r.contacts); });
    if (!o->history.empty()) write_history(o->history, hist);
    print_result(impact_json(ball, r, spec.model), o->json);
  });
}

void add_drop(CLI::App* area) {
  struct Opts {
    BallOptions ball;
    LawOptions law;
    double height = 0, omega = 0, theta_deg = 0, vx = 0, vy = 0, g = 9.8, rest_height = 1e-4, sample_dt = 1e-3;
    int bounces = 5;
    std::string trajectory, report;
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = area->add_subcommand("drop", "Release, flight and several bounces until rest or --bounces");
  cmd->add_option("--height", o->height, "centre height at release, m")->required();
  cmd->add_option("--theta-deg", o->theta_deg, "major axis from the horizontal at release, deg (default 0)");
  cmd->add_option("--omega", o->omega, "spin at release, rad/s, CCW positive (default 0)");
  cmd->add_option("--vx", o->vx, "horizontal speed at release, m/s (default 0)");
  cmd->add_option("--vy", o->vy, "vertical speed at release, m/s (default 0: released at the apex)");
  cmd->add_option("--bounces", o->bounces, "number of contacts to simulate (default 5)");
  cmd->add_option("--rest-height", o->rest_height, "energy (as a height, m) below which the ball is at rest (default 1e-4)");
  cmd->add_option("--g", o->g, "gravitational acceleration, m/s^2 (default 9.8)");
  cmd->add_option("--trajectory", o->trajectory, "write the sampled trajectory to this CSV file");
  cmd->add_option("--sample-dt", o->sample_dt, "flight sampling step of --trajectory, s (default 1e-3)");
  add_ball_options(cmd, o->ball);
  add_law_options(cmd, o->law);
  add_json_flag(*cmd, o->json);
  add_report_option(*cmd, o->report);
  cmd->callback([o] {
    const Ball ball = o->ball.get();
    for (auto [v, r, name] :
         {std::tuple{o->height, ranges::height, "--height"}, {o->omega, ranges::spin, "--omega"},
          {o->theta_deg, ranges::angle_deg, "--theta-deg"}, {o->vx, ranges::velocity, "--vx"},
          {o->vy, ranges::velocity, "--vy"}, {o->rest_height, PhysicalRange{0, 1e3, "m"}, "--rest-height"},
          {o->sample_dt, PhysicalRange{0, 10, "s"}, "--sample-dt"}})
      check_range(v, r, name);  // docs/cli.md#physical-ranges
    if (o->bounces < 1 || o->bounces > 10000) throw InputError("--bounces", "must lie in 1..10000");
    if (!(o->rest_height >= 0)) throw InputError("--rest-height", "must be >= 0");
    if (!(o->trajectory.empty() && o->report.empty()) && !(o->sample_dt > 0)) throw InputError("--sample-dt", "must be positive");
    const NormalLawSpec spec = o->law.law();
    const FrictionModel fr = o->law.friction_model();
    DropOptions d;
    d.flight.g = checked_g(o->g);
    d.contact = o->law.contact(d.flight.g);
    d.max_bounces = static_cast<std::size_t>(o->bounces);
    d.rest_height = o->rest_height;
    d.sample_dt = o->trajectory.empty() && o->report.empty() ? 0.0 : o->sample_dt;
    DropRelease rel;
    rel.height = o->height;
    rel.theta = o->theta_deg / kDeg;
    rel.omega = o->omega;
    rel.vx = o->vx;
    rel.vy = o->vy;
    const DropResult r = simulate_drop(ball, spec, fr, rel, d);
    if (r.status == DropStatus::failed) throw SolverError("drop simulation failed: " + r.message);
    json bounces = json::array();
    for (const Bounce& b : r.bounces) {
      bounces.push_back({{"t_touch", b.t_touch},
                         {"theta_touch_deg", wrap_angle(b.touch.theta) * kDeg},
                         {"vx_in", b.touch.vx},
                         {"vy_in", b.touch.vy},
                         {"omega_in", b.touch.omega},
                         {"collision_angle_deg", b.collision_angle_deg},
                         {"vx_out", b.contact.out.vx},
                         {"vy_out", b.contact.out.vy},
                         {"omega_out", b.contact.out.omega},
                         {"e", num(b.contact.restitution)},
                         {"contact_duration", b.contact.contact_duration},
                         {"peak_force", b.contact.peak_force},
                         {"t_apex", b.t_apex},
                         {"apex_height", b.apex_height},
                         {"above_release", b.above_release},
                         {"t_cross_release", b.t_cross_release >= 0 ? json(b.t_cross_release) : json(nullptr)}});
    }
    write_report_if_requested(o->report, [&] { return bounce_drop_report(ball, fr, rel, r); });
    if (!o->trajectory.empty()) write_trajectory(o->trajectory, r.trajectory);
    json apexes = json::array();
    for (const Bounce& b : r.bounces) apexes.push_back(b.apex_height);
    print_result({{"status", std::string(to_string(r.status))},
                  {"release_apex", r.release_apex},
                  {"n_bounces", r.bounces.size()},
                  {"apex_heights", apexes},
                  {"rebounds_above_release", r.first_above_release >= 0},
                  {"first_above_release", r.first_above_release >= 0 ? json(r.first_above_release + 1) : json(nullptr)},
                  {"t_above_release", r.first_above_release >= 0 ? json(r.bounces[r.first_above_release].t_cross_release)
                                                                   : json(nullptr)},
                  {"bounces", bounces}},
                 o->json);
  });
}

}  // namespace

void register_bounce(CLI::App& root) {
  auto* area = root.add_subcommand("bounce", "spinning rugby ball (ellipse) bouncing on a floor (seed 001)");
  area->require_subcommand(1);
  add_contact_time(area);
  add_simulate(area);
  add_drop(area);
  register_bounce_analysis(area);
  register_bounce_sweep(*area);
  register_bounce_render(area);
}

}  // namespace tribolab::cli
