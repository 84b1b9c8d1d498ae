// `tribolab incline mu-from-stop` as a function (seed 000, eq 十A; docs/cli.md#incline):
// the friction coefficient from the stopping point alone, with the best-angle advice.
#pragma once

#include "app/common/option_fields.hpp"
#include "incline/inverse.hpp"
#include "numerics/units.hpp"
#include "report/plotly_script.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace tribolab::app {

struct InclineMuFromStopOptions {
  std::optional<double> phi_deg;  ///< incline angle, degrees, in (0, 90) (required)
  std::optional<double> x_stop;   ///< stop position across the slope, m, > 0 (required)
  std::optional<double> y_stop;   ///< stop position up the slope, m, < 0 (required)
  /// Uncertainty of the angle, degrees; unset = exact (sigma_mu is then null unless --sigma-pos).
  std::optional<double> sigma_phi_deg;
  /// Uncertainty of x-stop and of y-stop, m; unset = exact.
  std::optional<double> sigma_pos;
  double g = kDefaultG;             ///< gravitational acceleration, m/s^2 (for the launch speed)
  /// Largest usable stop distance, m: enables the best-angle advice; unset = no advice.
  std::optional<double> plate_size;
  std::string report;               ///< HTML report to write; empty = none
  report::PlotlyMode plotly = report::PlotlyMode::embed;  ///< --plotly: how the report gets Plotly.js (embed, cdn, file)
};

/// The declaration of every option of `incline mu-from-stop` (app/common/option_fields.hpp).
inline const Fields<InclineMuFromStopOptions>& incline_mu_from_stop_fields() {
  using O = InclineMuFromStopOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.add("phi_deg", &O::phi_deg, "deg", "incline angle, in (0, 90)").needed();
    d.add("x_stop", &O::x_stop, "m", "stop position across the slope (> 0)").needed();
    d.add("y_stop", &O::y_stop, "m", "stop position up the slope (< 0)").needed();
    d.add("sigma_phi_deg", &O::sigma_phi_deg, "deg", "uncertainty of the angle").in(ranges::angle_sigma_deg);
    d.add("sigma_pos", &O::sigma_pos, "m", "uncertainty of x-stop and of y-stop").in(ranges::noise);
    d.add("g", &O::g, "m/s^2", "gravitational acceleration").in(ranges::gravity);
    d.add("plate_size", &O::plate_size, "m", "largest usable stop distance: enables the best-angle advice").in(ranges::distance);
    d.add_report(&O::report, &O::plotly);
    return d;
  }();
  return f;
}
/// The keys of `incline mu-from-stop --json` (docs/cli.md#incline-mu-from-stop). In incline_stop.cpp.
const ResultKeys& incline_mu_from_stop_result_keys();

struct InclineMuFromStopResult {
  nlohmann::json json;                         ///< exactly what `incline mu-from-stop --json` prints
  incline::StopMeasurement measurement;        ///< the checked measurement (SI, phi in rad)
  incline::MuFromStopResult fit;               ///< mu, k, r, sigma_mu, v0
  std::optional<incline::AngleAdvice> advice;  ///< with plate_size: the best angle
};

InclineMuFromStopResult incline_mu_from_stop(const InclineMuFromStopOptions& o);

}  // namespace tribolab::app
