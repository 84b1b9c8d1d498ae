// Fitting the contact law of bounce::simulate_contact to measured bounces (one row per
// bounce: orientation and velocities before, velocities after). Unknowns K, n, D (or the
// target restitution e of a restitution-based law) and mu; residuals are predicted minus
// measured outgoing vx, vy and b omega (omega scaled by the semi-minor axis so all residuals
// are speeds, m/s). K and D are fitted as logarithms (they span decades; positivity for
// free). Robust loss (Huber by default). docs/theory.md#bounce-fit.
#pragma once

#include "bounce/contact.hpp"
#include "numerics/least_squares.hpp"

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace tribolab::analysis {

/// One measured bounce (a row of the `bounce fit` table).
struct BounceRow {
  double theta_deg = 0;                         ///< orientation at first touch, deg
  double vx_in = 0, vy_in = 0, omega_in = 0;    ///< m/s, m/s (< 0), rad/s
  double vx_out = 0, vy_out = 0, omega_out = 0; ///< m/s, m/s, rad/s
  /// Standard uncertainties of the values above (deg, m/s, rad/s); NaN when not known (a
  /// table without the sigma columns). With them fit_bounces weighs each row by its own.
  double sigma_theta_deg = NAN, sigma_vx_in = NAN, sigma_vy_in = NAN, sigma_omega_in = NAN;
  double sigma_vx_out = NAN, sigma_vy_out = NAN, sigma_omega_out = NAN;
  bool has_sigmas() const;  ///< all seven sigmas finite and >= 0, the outgoing ones > 0
};

struct BounceFitOptions {
  bounce::Ball ball;
  bounce::NormalModel model = bounce::NormalModel::hunt_crossley;
  bool restitution_model = false;    ///< unknown e (target restitution) instead of D
  bounce::FrictionModel friction;    ///< kind, slip_scale, k_t, c_t used; mu is fitted
  /// Starting values (also the values of fixed parameters): K N/m^n, n, D, e, mu.
  double K0 = 1e5, n0 = 1.5, D0 = 5e4, e0 = 0.8, mu0 = 0.5;
  std::map<std::string, double> fixed;  ///< parameters held at the given value ("K", "n", "D", "e", "mu")
  numerics::RobustLoss loss = numerics::RobustLoss::huber;
  double loss_scale = 0.05;          ///< m/s: residual size where the robust loss bends
  double tolerance = 1e-9;           ///< simulate_contact integrator tolerance
  /// Covariance estimator (docs/theory.md#bounce-fit): Huber's scalar-corrected form
  /// (default: covers on small tables with outliers, measured), the sandwich (unequal noise;
  /// under-covers on ~10-bounce tables) or Gauss-Newton (too wide with outliers).
  numerics::Covariance covariance = numerics::Covariance::huber;
  std::string validate() const;
};

/// Per-row prediction and residuals (predicted - measured).
struct BounceFitRow {
  double vx_pred = 0, vy_pred = 0, omega_pred = 0;  ///< m/s, m/s, rad/s
  double r_vx = 0, r_vy = 0, r_b_omega = 0;         ///< m/s (omega residual times b)
  std::size_t contacts = 0;                         ///< contacts of the predicted impact (0: none predicted)
};

struct BounceFitResult {
  numerics::FitResult fit;           ///< raw solver result (log K, n, log D or e, mu)
  double K = 0, sigma_K = 0;         ///< N/m^n
  double n = 0, sigma_n = 0;
  double D = 0, sigma_D = 0;         ///< N s/m^(n+1) (Hooke N s/m); NaN with restitution_model
  double e = 0, sigma_e = 0;         ///< target restitution; NaN unless restitution_model
  double mu = 0, sigma_mu = 0;
  double rms = 0;                    ///< m/s over all 3 N residuals
  /// Plain-language warnings: free parameters at a bound of the search (docs/theory.md#plausibility-checks).
  std::vector<std::string> warnings;
  std::vector<BounceFitRow> rows;
  std::vector<std::string> free_parameters;
  /// Rows (1-based) whose impact under the fitted law touches the floor again: their
  /// predictions are whole impacts of several contacts (as every row's is the whole impact).
  std::vector<std::size_t> touching_again;
  /// Rows (1-based) left out of the fit: their predicted outcome jumps at the fitted law (a
  /// touch of the floor that begins or ends at the apex, where the whole impact is cut), so
  /// the fit's linearisation, and its sigmas, would not hold there. Predicted all the same.
  std::vector<std::size_t> left_out;
};

/// Fits. Rows with sigmas (BounceRow::has_sigmas, all or none) are weighted by their own
/// uncertainties: each residual is divided by its sd, the outgoing value's and the incoming
/// ones' carried through the law (sensitivities at the unweighted fit), then multiplied by
/// the median sd so residuals stay in m/s (docs/theory.md#bounce-fit, weights). Throws
/// InputError when the options are invalid, only some rows have sigmas, the data are too few for the free
/// parameters, or the fit cannot determine them (status not_identifiable / failed).
BounceFitResult fit_bounces(const std::vector<BounceRow>& rows, const BounceFitOptions& options);

/// Predicts one row's outgoing state with the given parameters: the whole impact
/// (bounce::simulate_impact, every contact until free flight), NaN when a contact fails or the
/// ball does not leave the floor.
BounceFitRow predict_bounce(const BounceRow& row, const bounce::Ball& ball,
                            const bounce::NormalLawSpec& law, const bounce::FrictionModel& friction,
                            double tolerance);

/// The rows whose whole impact (bounce::simulate_impact: a second touch and more) under `law`
/// differs from its first contact phase: `rows` (1-based) where max(|dvx|, |dvy|, b |domega|)
/// exceeds `threshold` (m/s), `worst` the largest such difference, m/s (issue 27;
/// docs/theory.md#bounce-fit).
struct WholeImpactDifference {
  std::vector<std::size_t> rows;
  double worst = 0;  ///< m/s
};
WholeImpactDifference whole_impact_differences(const std::vector<BounceRow>& rows, const bounce::Ball& ball,
                                               const bounce::NormalLawSpec& law, const bounce::FrictionModel& friction,
                                               double tolerance, double threshold);

/// "K of N rows (i, j, ...)": the rows of `d` among `n_rows`, at most 8 named.
std::string rows_text(const WholeImpactDifference& d, std::size_t n_rows);

}  // namespace tribolab::analysis
