// `tribolab incline mu-from-stop` as a function (seed 000, eq 十A; docs/cli.md#incline):
// the friction coefficient from the stopping point alone, with the best-angle advice.
#pragma once

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

struct InclineMuFromStopResult {
  nlohmann::json json;                         ///< exactly what `incline mu-from-stop --json` prints
  incline::StopMeasurement measurement;        ///< the checked measurement (SI, phi in rad)
  incline::MuFromStopResult fit;               ///< mu, k, r, sigma_mu, v0
  std::optional<incline::AngleAdvice> advice;  ///< with plate_size: the best angle
};

InclineMuFromStopResult incline_mu_from_stop(const InclineMuFromStopOptions& o);

}  // namespace tribolab::app
