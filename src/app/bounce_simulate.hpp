// `tribolab bounce contact-time|simulate|drop` as workflows of the application layer
// (docs/design.md, "Application layer: bounce"; docs/cli.md#bounce): one options struct per
// command whose member initializers are the command's defaults, one function that checks,
// computes, writes the requested files and returns the JSON the command prints together with
// the arrays a notebook wants. Errors are InputError naming the field (field("vy"):
// "--vy: ..." on the command line, "vy: ..." in Python). Nothing is printed.
#pragma once

#include "app/bounce_options.hpp"

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

struct BounceDropResult {
  nlohmann::json json;                                ///< exactly what `--json` prints
  bounce::DropResult drop;                            ///< the core's result, with its bounces
  std::vector<bounce::TrajectorySample> trajectory;   ///< sampled when a file, report or keep_trajectory asks
};

BounceDropResult bounce_drop(const BounceDropOptions& o);

/// The `bounce simulate` object of an impact (docs/cli.md#bounce-simulate).
nlohmann::json bounce_impact_json(const bounce::Ball& ball, const bounce::ImpactResult& r, bounce::NormalModel model);

}  // namespace tribolab::app
