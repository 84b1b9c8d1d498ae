// `tribolab bounce contact-time|simulate|drop` as workflows of the application layer
// (docs/design.md, "Application layer: bounce"; docs/cli.md#bounce): one options struct per
// command whose member initializers are the command's defaults, one function that checks,
// computes, writes the requested files and returns the JSON the command prints together with
// the arrays a notebook wants. Errors are InputError naming the field (field("vy"):
// "--vy: ..." on the command line, "vy: ..." in Python). Nothing is printed.
#pragma once

#include "app/bounce/bounce_options.hpp"
#include "app/common/option_fields.hpp"

#include "bounce/contact.hpp"
#include "bounce/drop.hpp"
#include "bounce/flight.hpp"
#include "bounce/impact.hpp"
#include "numerics/units.hpp"
#include "report/plotly_script.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace tribolab::app {

/// `bounce contact-time`: first contact of a ball released at an apex (seed 001, table 4).
struct BounceContactTimeOptions {
  BallOptions ball;
  double height = 0;         ///< centre height at the apex, m (required)
  double omega = 0;          ///< spin, rad/s, counter-clockwise positive
  double theta_deg = 0;      ///< major axis from the horizontal at the apex, deg
  int direction = 1;         ///< direction of motion for the collision angle: 1 (+x) or -1
  double g = kDefaultG;      ///< gravitational acceleration, m/s^2
  std::string report;        ///< HTML report path; empty = none
  report::PlotlyMode plotly = report::PlotlyMode::embed;  ///< --plotly: how the report gets Plotly.js (embed, cdn, file)
};

/// The declaration of every option of `bounce contact-time` (app/common/option_fields.hpp).
inline const Fields<BounceContactTimeOptions>& bounce_contact_time_fields() {
  using O = BounceContactTimeOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.add("height", &O::height, "m", "centre height at the apex").in(ranges::height).needed();
    d.add("omega", &O::omega, "rad/s", "spin, counter-clockwise positive").in(ranges::spin);
    d.add("theta_deg", &O::theta_deg, "deg", "major axis from the horizontal at the apex").in(ranges::angle_deg);
    d.add("direction", &O::direction, "", "direction of motion for the collision angle: 1 (+x) or -1");
    d.add("g", &O::g, "m/s^2", "gravitational acceleration").in(ranges::gravity);
    d.group(&O::ball, ball_fields());
    d.add_report(&O::report, &O::plotly);
    return d;
  }();
  return f;
}

/// The keys of `bounce contact-time --json` (docs/cli.md#bounce-contact-time).
const ResultKeys& bounce_contact_time_result_keys();

/// One sample of the free flight from the apex to the first contact.
struct FlightSample {
  double t = 0;              ///< s from release
  bounce::BodyState state;   ///< centre and orientation (free flight, docs/theory.md#bounce-flight)
  double gap = 0;            ///< y - Y(theta): height of the lowest point above the floor, m
};

struct BounceContactTimeResult {
  nlohmann::json json;                 ///< exactly what `--json` prints
  bounce::FlightResult flight;         ///< the core's result
  std::vector<FlightSample> samples;   ///< 801 samples from release to the first contact
};

BounceContactTimeResult bounce_contact_time(const BounceContactTimeOptions& o);

/// `bounce simulate`: the impact from first touch until the ball flies free (seed 001, exp. 4).
struct BounceSimulateOptions {
  BallOptions ball;
  LawOptions law;
  double vx = 0;             ///< centre velocity at first touch, m/s
  double vy = 0;             ///< centre velocity at first touch, m/s (< 0; required)
  double omega = 0;          ///< spin at first touch, rad/s, CCW positive
  double theta_deg = 0;      ///< major axis from the horizontal at first touch, deg
  double g = kDefaultG;      ///< gravitational acceleration, m/s^2
  std::string history;       ///< CSV path of the time history; empty = none
  std::string report;        ///< HTML report path; empty = none
  report::PlotlyMode plotly = report::PlotlyMode::embed;  ///< --plotly: how the report gets Plotly.js (embed, cdn, file)
};

/// The declaration of every option of `bounce simulate` (app/common/option_fields.hpp).
inline const Fields<BounceSimulateOptions>& bounce_simulate_fields() {
  using O = BounceSimulateOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.add("vx", &O::vx, "m/s", "centre velocity at first touch").in(ranges::velocity);
    d.add("vy", &O::vy, "m/s", "centre velocity at first touch (< 0)").in(ranges::velocity).needed();
    d.add("omega", &O::omega, "rad/s", "spin at first touch, CCW positive").in(ranges::spin);
    d.add("theta_deg", &O::theta_deg, "deg", "major axis from the horizontal at first touch").in(ranges::angle_deg);
    d.add("g", &O::g, "m/s^2", "gravitational acceleration").in(ranges::gravity_or_zero);
    d.add("history", &O::history, "", "write the time history to this CSV file").as(FieldRole::output_path);
    d.group(&O::ball, ball_fields());
    d.group(&O::law, law_fields());
    d.add_report(&O::report, &O::plotly);
    return d;
  }();
  return f;
}

/// The keys of `bounce simulate --json`: an impact (docs/cli.md#bounce-simulate).
const ResultKeys& bounce_simulate_result_keys();

struct BounceSimulateResult {
  nlohmann::json json;                          ///< exactly what `--json` prints
  bounce::ImpactResult impact;                  ///< the core's result
  std::vector<bounce::ContactSample> history;   ///< every step of every contact (t, state, d, d_dot, N, f, v_t, phase)
};

BounceSimulateResult bounce_simulate(const BounceSimulateOptions& o);

/// `bounce drop`: release, flight and several bounces until rest or `bounces`.
struct BounceDropOptions {
  BallOptions ball;
  LawOptions law;
  double height = 0;          ///< centre height at release, m (required)
  double theta_deg = 0;       ///< major axis from the horizontal at release, deg
  double omega = 0;           ///< spin at release, rad/s, CCW positive
  double vx = 0;              ///< horizontal speed at release, m/s
  double vy = 0;              ///< vertical speed at release, m/s; 0: released at the apex
  int bounces = 5;            ///< number of contacts to simulate
  double rest_height = 1e-4;  ///< energy (as a height, m) below which the ball is at rest
  double g = kDefaultG;       ///< gravitational acceleration, m/s^2
  std::string trajectory;     ///< CSV path of the sampled trajectory; empty = none
  double sample_dt = 1e-3;    ///< flight sampling step of the trajectory, s
  std::string report;         ///< HTML report path; empty = none
  report::PlotlyMode plotly = report::PlotlyMode::embed;  ///< --plotly: how the report gets Plotly.js (embed, cdn, file)
  /// Sample the trajectory even without a trajectory file or report (for a notebook).
  bool keep_trajectory = false;
};

/// The declaration of every option of `bounce drop` (app/common/option_fields.hpp).
inline const Fields<BounceDropOptions>& bounce_drop_fields() {
  using O = BounceDropOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.add("height", &O::height, "m", "centre height at release").in(ranges::height).needed();
    d.add("theta_deg", &O::theta_deg, "deg", "major axis from the horizontal at release").in(ranges::angle_deg);
    d.add("omega", &O::omega, "rad/s", "spin at release, CCW positive").in(ranges::spin);
    d.add("vx", &O::vx, "m/s", "horizontal speed at release").in(ranges::velocity);
    d.add("vy", &O::vy, "m/s", "vertical speed at release; 0: released at the apex").in(ranges::velocity);
    d.add("bounces", &O::bounces, "", "number of contacts to simulate").in(PhysicalRange{1, 1e4, ""});
    d.add("rest_height", &O::rest_height, "m", "energy (as a height) below which the ball is at rest")
        .in(PhysicalRange{0, 1e3, "m"});
    d.add("g", &O::g, "m/s^2", "gravitational acceleration").in(ranges::gravity);
    d.add("trajectory", &O::trajectory, "", "write the sampled trajectory to this CSV file").as(FieldRole::output_path);
    d.add("sample_dt", &O::sample_dt, "s", "flight sampling step of the trajectory").in(PhysicalRange{0, 10, "s"});
    d.group(&O::ball, ball_fields());
    d.group(&O::law, law_fields());
    d.add_report(&O::report, &O::plotly);
    d.add("keep_trajectory", &O::keep_trajectory, "", "sample the trajectory even without a file or report")
        .as(FieldRole::notebook);
    return d;
  }();
  return f;
}

/// The keys of `bounce drop --json` (docs/cli.md#bounce-drop).
const ResultKeys& bounce_drop_result_keys();

struct BounceDropResult {
  nlohmann::json json;                                ///< exactly what `--json` prints
  bounce::DropResult drop;                            ///< the core's result, with its bounces
  std::vector<bounce::TrajectorySample> trajectory;   ///< sampled when a file, report or keep_trajectory asks
};

BounceDropResult bounce_drop(const BounceDropOptions& o);

/// The `bounce simulate` object of an impact (docs/cli.md#bounce-simulate).
nlohmann::json bounce_impact_json(const bounce::Ball& ball, const bounce::ImpactResult& r, bounce::NormalModel model);

}  // namespace tribolab::app
