// `tribolab incline predict | simulate | families` as functions (docs/design.md
// "Application layer: incline", docs/cli.md#incline): plain option structs whose member
// initializers are the command line's defaults, results holding the command's JSON and the
// arrays a notebook wants. No printing; files only where a path is given.
#pragma once

#include "app/incline/incline_launch.hpp"
#include "incline/closed_form.hpp"
#include "incline/families.hpp"
#include "report/plotly_script.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace tribolab::app {

// ---- predict --------------------------------------------------------------------------

struct InclinePredictOptions {
  InclineLaunchOptions launch;  ///< --mu, --phi-deg, --v0 (required), --g, --mu-static
  std::string report;           ///< HTML report to write; empty = none
  report::PlotlyMode plotly = report::PlotlyMode::embed;  ///< --plotly: how the report gets Plotly.js (embed, cdn, file)
};

struct InclinePredictResult {
  nlohmann::json json;            ///< exactly what `incline predict --json` prints
  incline::Parameters parameters; ///< the checked launch (SI, phi in rad)
  incline::Prediction prediction; ///< closed form of model B (seed 000, eqs 七-九)
  /// Closed form at 401 times evenly over [0, default duration] (1.25 t_stop, or 2 v0/alpha);
  /// empty when that duration is not finite. The report draws these.
  std::vector<incline::State> trajectory;
};

InclinePredictResult incline_predict(const InclinePredictOptions& o);

/// The declaration of every option of `incline predict` (app/common/option_fields.hpp).
inline const Fields<InclinePredictOptions>& incline_predict_fields() {
  using O = InclinePredictOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.group(&O::launch, incline_launch_fields(true));
    d.add_report(&O::report, &O::plotly);
    return d;
  }();
  return f;
}
/// The keys of `incline predict --json` (docs/cli.md#incline-predict). In incline_forward.cpp.
const ResultKeys& incline_predict_result_keys();

// ---- simulate -------------------------------------------------------------------------

struct InclineSimulateOptions {
  InclineLaunchOptions launch;       ///< --mu, --phi-deg, --v0 (required), --g, --mu-static
  std::string model = "B";           ///< A (a friction component normal to the path) or B
  /// Model A: normal friction / mass, m/s^2, positive left of the velocity; unset = 0.
  std::optional<double> normal_accel;
  /// analytic (closed form, model B only) or numeric; unset: analytic for B, numeric for A.
  std::optional<std::string> method;
  /// Sample interval, s; unset = t_end / 500.
  std::optional<double> dt;
  /// Duration, s; unset = 1.25 t_stop if it stops, else 2 v0/(g mu cos phi), else 1.
  std::optional<double> t_end;
  std::string out;                   ///< CSV t,x,y,vx,vy,ax,ay to write; empty = none
  std::string report;                ///< HTML report to write; empty = none
  report::PlotlyMode plotly = report::PlotlyMode::embed;  ///< --plotly: how the report gets Plotly.js (embed, cdn, file)
};

/// The declaration of every option of `incline simulate` (app/common/option_fields.hpp).
inline const Fields<InclineSimulateOptions>& incline_simulate_fields() {
  using O = InclineSimulateOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.group(&O::launch, incline_launch_fields(true));
    d.add("model", &O::model, "", "A (normal friction component) or B").one_of({"A", "B"});
    d.add("normal_accel", &O::normal_accel, "m/s^2", "model A: normal friction / mass, positive left of the velocity (unset: 0)")
        .in(ranges::accel);
    d.add("method", &O::method, "", "analytic (closed form, model B only) or numeric; unset: analytic for B, numeric for A")
        .one_of({"analytic", "numeric"});
    d.add("dt", &O::dt, "s", "sample interval (unset: t-end/500)").in(ranges::step);
    d.add("t_end", &O::t_end, "s", "duration (unset: 1.25 t_stop if it stops, else 2 v0/(g mu cos phi), else 1)").in(ranges::step);
    d.add("out", &O::out, "", "output CSV file").as(FieldRole::output_path).needed();
    d.add_report(&O::report, &O::plotly);
    return d;
  }();
  return f;
}
/// The keys of `incline simulate --json` (docs/cli.md#incline-simulate). In incline_forward.cpp.
const ResultKeys& incline_simulate_result_keys();

struct InclineSimulateResult {
  nlohmann::json json;                     ///< exactly what `incline simulate --json` prints
  incline::Parameters parameters;          ///< the checked launch
  std::vector<incline::State> trajectory;  ///< samples t, x, y, vx, vy, ax, ay (SI), as the CSV
  /// With a report, model B only: the other method (numeric for analytic and back) on the
  /// report's sample times (incline_report_times), and its legend name; else empty.
  std::vector<incline::State> comparison;
  std::string comparison_name;
};

InclineSimulateResult incline_simulate(const InclineSimulateOptions& o);

// ---- families -------------------------------------------------------------------------

struct InclineFamiliesOptions {
  InclineLaunchOptions launch;  ///< the fixed launch; the varied one may be unset
  std::string vary;             ///< v0, phi or mu (required)
  /// Values of the varied parameter: m/s for v0, degrees for phi, 1 for mu (required).
  std::vector<double> values;
  int samples = 500;            ///< samples per curve, in [2, 10^6]
  /// Duration of every curve, s; unset = each member its own, 1.25 t_stop or 2 v0/alpha.
  std::optional<double> t_end;
  std::string out;              ///< CSV <vary>,t,x,y,vx,vy,ax,ay to write; empty = none
  std::string report;           ///< HTML report to write; empty = none
  report::PlotlyMode plotly = report::PlotlyMode::embed;  ///< --plotly: how the report gets Plotly.js (embed, cdn, file)
};

struct InclineFamiliesResult {
  nlohmann::json json;             ///< exactly what `incline families --json` prints
  incline::FamilyOptions options;  ///< the checked family (SI, phi in rad)
  /// The members: each one's value, parameters, prediction and curve (`trajectory`).
  incline::Family family;
};

/// The declaration of every option of `incline families` (app/common/option_fields.hpp): the
/// launch without required fields (the varied one may be unset), the family's own fields.
inline const Fields<InclineFamiliesOptions>& incline_families_fields() {
  using O = InclineFamiliesOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.group(&O::launch, incline_launch_fields(false));
    d.add("vary", &O::vary, "", "parameter to vary").one_of({"v0", "phi", "mu"}).needed();
    d.add("values", &O::values, "", "comma-separated values of the varied parameter (m/s for v0, degrees for phi)")
        .needed();
    d.add("samples", &O::samples, "", "samples per curve, in [2, 1000000]");
    d.add("t_end", &O::t_end, "s", "duration of every curve (unset: each member its own, 1.25 t_stop or 2 v0/alpha)")
        .in(ranges::step);
    d.add("out", &O::out, "", "output CSV file").as(FieldRole::output_path).needed();
    d.add_report(&O::report, &O::plotly);
    return d;
  }();
  return f;
}

InclineFamiliesResult incline_families(const InclineFamiliesOptions& o);

}  // namespace tribolab::app
