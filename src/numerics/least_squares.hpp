// Nonlinear least squares with parameter uncertainties, on top of Ceres Solver.
//
// One parameter block of P unknowns, N residuals r_i(p). The solver minimises
// (1/2) sum rho(r_i^2) (rho = identity or a robust loss), then estimates the covariance of p
// from the Jacobian at the optimum: C = s^2 (J^T J)^-1, where s^2 = sum r_i^2 / (N - P_free)
// when the residuals are unscaled (measurement noise unknown, estimated from the fit), or 1
// when the caller has already divided each residual by its standard deviation; or, with
// FitOptions::covariance = sandwich, Huber's sandwich estimator for robust losses.
// Confidence intervals use Student's t with N - P_free degrees of freedom.
// See docs/theory.md#fitting.
#pragma once

#include <ceres/dynamic_autodiff_cost_function.h>
#include <ceres/dynamic_numeric_diff_cost_function.h>

#include <Eigen/Dense>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tribolab::numerics {

enum class RobustLoss { none, huber, cauchy, soft_l1 };

/// How the covariance of the parameters is estimated at the optimum (docs/theory.md#fitting).
enum class Covariance {
  /// s^2 (J~^T J~)^-1 with Ceres' robustified Jacobian J~ (rows scaled by sqrt(rho')) and
  /// s^2 = sum r^2 / (N - P_free) from the raw residuals; exact for least squares (no loss)
  /// with equal, independent noise.
  gauss_newton,
  /// Huber's sandwich H^-1 B H^-1 N/(N - P_free) for an M-estimator:
  /// H = sum (rho' + 2 rho'' r^2) J_i^T J_i, B = sum (rho' r)^2 J_i^T J_i, with rho', rho''
  /// the loss's derivatives at s = r^2 (Ceres convention). Needs no noise level, allows
  /// unequal noise across residuals and down-weights outliers as the fit does.
  sandwich,
  /// Huber's scalar correction for an M-estimator (Huber 1981, Robust Statistics, eq. 7.6.x;
  /// as R's MASS::rlm): K^2 [sum psi^2 / (N - F)] / m^2 (J^T J)^-1 with psi = rho' r,
  /// m = mean(rho' + 2 rho'' r^2), K = 1 + (F/N) var(rho' + 2 rho'' r^2) / m^2. Equals
  /// s^2 (J^T J)^-1 without a loss; assumes one noise level, but counts outliers only at
  /// their clipped size and is far steadier than the sandwich in small samples.
  huber,
};

struct FitOptions {
  int max_iterations = 200;
  double function_tolerance = 1e-14;
  double parameter_tolerance = 1e-12;
  double gradient_tolerance = 1e-14;
  RobustLoss loss = RobustLoss::none;
  double loss_scale = 1.0;  ///< residual size at which the robust loss bends, residual units
  /// true: residuals are already divided by their standard deviations (covariance not
  /// rescaled); false: the noise level is estimated from the residuals.
  bool residuals_are_normalized = false;
  Covariance covariance = Covariance::gauss_newton;  ///< see Covariance

  std::string validate() const;
};

/// One unknown: name, starting value, optional bounds, and whether it is held fixed.
struct FitParameter {
  std::string name;
  double initial = 0.0;
  std::optional<double> lower, upper;
  bool fixed = false;
};

enum class FitStatus {
  converged,          ///< a minimum was found and its covariance computed
  no_convergence,     ///< the solver stopped without meeting the tolerances
  not_identifiable,   ///< the data cannot determine all free parameters (singular J^T J)
  too_few_points,     ///< fewer residuals than free parameters
  failed,             ///< the model could not be evaluated at the starting point
};

struct FitResult {
  FitStatus status = FitStatus::failed;
  std::string message;                ///< one line, for people
  int iterations = 0;
  std::vector<std::string> names;
  std::vector<double> values;         ///< best-fit parameters
  std::vector<double> sigma;          ///< standard errors (0 for fixed parameters)
  Eigen::MatrixXd covariance;         ///< P x P, zero rows/cols for fixed parameters
  std::vector<double> residuals;      ///< r_i at the optimum
  double cost = 0.0;                  ///< (1/2) sum r_i^2 at the optimum (no robust loss)
  double rms = 0.0;                   ///< sqrt(sum r_i^2 / N)
  int dof = 0;                        ///< N - number of free parameters
  double noise_scale = 1.0;           ///< s used to scale the covariance (gauss_newton; informative with sandwich)
  /// The factor the covariance was widened by for serially correlated residuals (1: not
  /// widened; see widen_for_serial_correlation).
  double serial_factor = 1.0;

  bool ok() const { return status == FitStatus::converged; }
  /// Half-width of the two-sided confidence interval at `level` (e.g. 0.95) for parameter i.
  double ci_half_width(std::size_t i, double level = 0.95) const;
  /// Index of a parameter by name; throws InputError if absent.
  std::size_t index(const std::string& name) const;
  double value(const std::string& name) const { return values[index(name)]; }
  double sigma_of(const std::string& name) const { return sigma[index(name)]; }
};

/// How much residuals that are correlated in time widen the parameters' variance
/// (docs/theory.md#fitting, "Serially correlated residuals"): the long-run variance of the
/// residuals over their variance, 1 + 2 sum_{l=1..L} (1 - l/(L+1)) rho_l (Newey & West 1987,
/// Bartlett weights), rho_l the lag-l autocorrelation pooled over `series` (each one residual
/// series in time order, its mean taken away), the bandwidth L from Andrews' (1991) AR(1)
/// plug-in 1.1447 (alpha n)^(1/3), alpha = 4 rho_1^2 / ((1 - rho_1)^2 (1 + rho_1)^2), rho_1
/// at most 0.97. At least 1: independent noise leaves a covariance as it is.
double serial_correlation_factor(const std::vector<std::vector<double>>& series);

/// Widens `f`'s covariance by `factor` (its sigmas by the square root) and records it in
/// f.serial_factor; a factor of at most 1 leaves `f` as it is.
void widen_for_serial_correlation(FitResult& f, double factor);

/// Throws for a fit that is not ok() (the convention of numerics/error.hpp): InputError when
/// the data cannot support the fit (too_few_points, not_identifiable), SolverError when the
/// solver failed on it (no_convergence, failed). what() is "<where>: <message>".
[[noreturn]] void throw_fit_failure(const FitResult& fit, const std::string& where, const std::string& message);

/// Residual function for numeric differentiation: fills r[0..N) from p[0..P); returns false
/// when the model cannot be evaluated at p (the solver then backs off).
using ResidualFunction = std::function<bool(const double* p, double* r)>;

/// Solves with central-difference Jacobians (for models that cannot be templated).
FitResult fit_least_squares(const ResidualFunction& residuals, int num_residuals,
                            const std::vector<FitParameter>& parameters,
                            const FitOptions& options = {});

/// Solves with automatic differentiation: `functor` has
///   template <class T> bool operator()(const T* p, T* r) const;
template <class Functor>
FitResult fit_least_squares_autodiff(const Functor& functor, int num_residuals,
                                     const std::vector<FitParameter>& parameters,
                                     const FitOptions& options = {});

namespace detail {
FitResult solve_with_cost(std::unique_ptr<ceres::CostFunction> cost, int num_residuals,
                          const std::vector<FitParameter>& parameters, const FitOptions& options);

template <class Functor>
struct AutoDiffAdapter {
  const Functor* f;
  template <class T>
  bool operator()(T const* const* params, T* residuals) const {
    return (*f)(params[0], residuals);
  }
};
}  // namespace detail

template <class Functor>
FitResult fit_least_squares_autodiff(const Functor& functor, int num_residuals,
                                     const std::vector<FitParameter>& parameters,
                                     const FitOptions& options) {
  using Adapter = detail::AutoDiffAdapter<Functor>;
  auto cost = std::make_unique<ceres::DynamicAutoDiffCostFunction<Adapter, 8>>(
      new Adapter{&functor});
  cost->AddParameterBlock(static_cast<int>(parameters.size()));
  cost->SetNumResiduals(num_residuals);
  return detail::solve_with_cost(std::move(cost), num_residuals, parameters, options);
}

}  // namespace tribolab::numerics
