#include "numerics/least_squares.hpp"

#include "numerics/error.hpp"

#include <ceres/ceres.h>
#include <ceres/covariance.h>
#include <ceres/manifold.h>

#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace tribolab::numerics {

std::string FitOptions::validate() const {
  if (max_iterations <= 0) return "fit: max_iterations must be positive";
  if (!(function_tolerance > 0) || !(parameter_tolerance > 0) || !(gradient_tolerance > 0)) {
    return "fit: tolerances must be positive";
  }
  if (!(loss_scale > 0) || !std::isfinite(loss_scale)) return "fit: loss scale must be positive";
  return {};
}

double FitResult::ci_half_width(std::size_t i, double level) const {
  if (dof <= 0 || i >= sigma.size()) return std::numeric_limits<double>::quiet_NaN();
  const boost::math::students_t t(dof);
  return boost::math::quantile(boost::math::complement(t, (1.0 - level) / 2.0)) * sigma[i];
}

double serial_correlation_factor(const std::vector<std::vector<double>>& series) {
  // Autocovariances pooled over the series, each about its own mean.
  std::vector<std::vector<double>> centred;
  std::size_t n = 0, longest = 0;
  for (const auto& s : series) {
    if (s.size() < 3) continue;
    double mean = 0;
    for (double v : s) mean += v;
    mean /= static_cast<double>(s.size());
    std::vector<double> c(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) c[i] = s[i] - mean;
    n += s.size();
    longest = std::max(longest, s.size());
    centred.push_back(std::move(c));
  }
  const auto autocovariance = [&](std::size_t lag) {
    double sum = 0;
    for (const auto& c : centred) {
      for (std::size_t i = lag; i < c.size(); ++i) sum += c[i] * c[i - lag];
    }
    return sum / static_cast<double>(n);
  };
  const double c0 = n > 0 ? autocovariance(0) : 0;
  if (!(c0 > 0)) return 1.0;
  const double rho1 = std::clamp(autocovariance(1) / c0, -0.97, 0.97);
  const double alpha = 4 * rho1 * rho1 / ((1 - rho1) * (1 - rho1) * (1 + rho1) * (1 + rho1));
  const std::size_t bandwidth = std::min<std::size_t>(
      longest / 2, static_cast<std::size_t>(std::floor(1.1447 * std::cbrt(alpha * static_cast<double>(n)))));
  double factor = 1;
  for (std::size_t lag = 1; lag <= bandwidth; ++lag) {
    factor += 2 * (1 - static_cast<double>(lag) / static_cast<double>(bandwidth + 1)) * autocovariance(lag) / c0;
  }
  return std::max(1.0, factor);
}

void widen_for_serial_correlation(FitResult& f, double factor) {
  if (!(factor > 1)) return;
  f.covariance *= factor;
  for (double& s : f.sigma) s *= std::sqrt(factor);
  f.serial_factor = factor;
}

std::size_t FitResult::index(const std::string& name) const {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return i;
  }
  throw InputError("fit has no parameter named '" + name + "'");
}

void throw_fit_failure(const FitResult& fit, const std::string& where, const std::string& message) {
  switch (fit.status) {
    case FitStatus::too_few_points:
    case FitStatus::not_identifiable:
      throw InputError(where, message);
    case FitStatus::converged:
    case FitStatus::no_convergence:
    case FitStatus::failed:
      break;
  }
  throw SolverError(where, message);
}

FitResult fit_least_squares(const ResidualFunction& residuals, int num_residuals,
                            const std::vector<FitParameter>& parameters,
                            const FitOptions& options) {
  struct Functor {
    const ResidualFunction* f;
    bool operator()(double const* const* p, double* r) const { return (*f)(p[0], r); }
  };
  auto cost = std::make_unique<ceres::DynamicNumericDiffCostFunction<Functor, ceres::CENTRAL>>(
      new Functor{&residuals});
  cost->AddParameterBlock(static_cast<int>(parameters.size()));
  cost->SetNumResiduals(num_residuals);
  return detail::solve_with_cost(std::move(cost), num_residuals, parameters, options);
}

namespace detail {
namespace {

ceres::LossFunction* make_loss(const FitOptions& o) {
  switch (o.loss) {
    case RobustLoss::none: return nullptr;
    case RobustLoss::huber: return new ceres::HuberLoss(o.loss_scale);
    case RobustLoss::cauchy: return new ceres::CauchyLoss(o.loss_scale);
    case RobustLoss::soft_l1: return new ceres::SoftLOneLoss(o.loss_scale);
  }
  return nullptr;
}

// The robust loss must act on every residual: Ceres applies a LossFunction to the squared
// norm of a whole residual block, and the model's N residuals form one block here, so
// rho(sum r_i^2) would be a monotone transform of least squares (same minimiser: no
// robustness at all, and a covariance scaled by 1/rho'(sum r^2)). Instead each residual is
// mapped to r~ = sign(r) sqrt(rho(r^2)), so that sum r~^2 = sum rho(r_i^2) is the robust
// cost exactly, with d r~/d r = rho'(r^2) |r| / sqrt(rho(r^2)) (1 at r = 0).
// docs/theory.md#fitting.
class PerResidualLoss final : public ceres::CostFunction {
 public:
  PerResidualLoss(const ceres::CostFunction* inner, std::unique_ptr<ceres::LossFunction> loss)
      : inner_(inner), loss_(std::move(loss)) {
    set_num_residuals(inner->num_residuals());
    *mutable_parameter_block_sizes() = inner->parameter_block_sizes();
  }
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    if (!inner_->Evaluate(parameters, residuals, jacobians)) return false;
    const std::vector<int32_t>& sizes = parameter_block_sizes();
    for (int i = 0; i < num_residuals(); ++i) {
      const double r = residuals[i];
      double rho[3];
      loss_->Evaluate(r * r, rho);
      const double root = std::sqrt(std::max(rho[0], 0.0));
      const double factor = root > 0 ? rho[1] * std::abs(r) / root : 1.0;
      residuals[i] = r < 0 ? -root : root;
      if (jacobians == nullptr) continue;
      for (std::size_t b = 0; b < sizes.size(); ++b) {
        if (jacobians[b] == nullptr) continue;
        for (int k = 0; k < sizes[b]; ++k) jacobians[b][i * sizes[b] + k] *= factor;
      }
    }
    return true;
  }

 private:
  const ceres::CostFunction* inner_;
  std::unique_ptr<ceres::LossFunction> loss_;
};

bool evaluate(const ceres::CostFunction& cost, const std::vector<double>& p,
              std::vector<double>& r) {
  const double* blocks[] = {p.data()};
  if (!cost.Evaluate(blocks, r.data(), nullptr)) return false;
  for (double v : r) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

// Huber's sandwich (Huber 1967, Proc. 5th Berkeley Symp. 1; Huber & Ronchetti, Robust
// Statistics, 2009, section 7.6) for the M-estimator minimising (1/2) sum rho(r_i^2):
// the estimating equation is sum psi_i = 0 with psi_i = rho'(r_i^2) r_i J_i^T, its derivative
// (Gauss-Newton, r'' dropped) H = sum (rho' + 2 rho'' r_i^2) J_i^T J_i, and
// Cov = N/(N - F) H^-1 (sum psi_i psi_i^T) H^-1 (F free parameters; the factor is the HC1
// small-sample correction). For Huber's loss H counts the inliers only and psi is the
// residual clipped at the loss scale. When H is not positive definite (a redescending loss
// such as Cauchy with many large residuals), the IRLS weights rho' alone make the bread,
// H = sum rho' J_i^T J_i. J is the raw residuals' Jacobian (central differences or autodiff).
bool sandwich_covariance(const ceres::CostFunction& cost, const std::vector<double>& p,
                         const std::vector<FitParameter>& parameters, const FitOptions& options,
                         FitResult& r) {
  const int P = static_cast<int>(p.size());
  const int N = static_cast<int>(r.residuals.size());
  std::vector<int> free;
  for (int i = 0; i < P; ++i) {
    if (!parameters[i].fixed) free.push_back(i);
  }
  const int F = static_cast<int>(free.size());
  if (N <= F) return false;
  std::vector<double> res(N);
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> J(N, P);
  const double* blocks[] = {p.data()};
  double* jacobians[] = {J.data()};
  if (!cost.Evaluate(blocks, res.data(), jacobians) || !J.allFinite()) return false;
  std::unique_ptr<ceres::LossFunction> loss(make_loss(options));
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(F, F), Hw = H, B = H, JtJ = H;
  Eigen::VectorXd j(F);
  double sum_w = 0, sum_w2 = 0, sum_psi2 = 0;
  for (int i = 0; i < N; ++i) {
    for (int k = 0; k < F; ++k) j[k] = J(i, free[k]);
    const double sq = res[i] * res[i];
    double rho[3] = {sq, 1.0, 0.0};
    if (loss) loss->Evaluate(sq, rho);
    const double psi = rho[1] * res[i];
    const double w = rho[1] + 2 * rho[2] * sq;  // d psi / d r
    H += w * j * j.transpose();
    Hw += rho[1] * j * j.transpose();
    B += psi * psi * j * j.transpose();
    JtJ += j * j.transpose();
    sum_w += w;
    sum_w2 += w * w;
    sum_psi2 += psi * psi;
  }
  if (options.covariance == Covariance::huber) {
    const double m = sum_w / N;
    const double var_w = std::max(0.0, sum_w2 / N - m * m);
    if (!(m > 0)) return false;
    const double K = 1 + (static_cast<double>(F) / N) * var_w / (m * m);
    Eigen::LDLT<Eigen::MatrixXd> ldlt(JtJ);
    if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 0)) return false;
    const Eigen::MatrixXd C = (K * K * sum_psi2 / (N - F) / (m * m)) * ldlt.solve(Eigen::MatrixXd::Identity(F, F));
    if (!C.allFinite()) return false;
    r.covariance = Eigen::MatrixXd::Zero(P, P);
    for (int a = 0; a < F; ++a) {
      for (int b = 0; b < F; ++b) r.covariance(free[a], free[b]) = C(a, b);
    }
    return true;
  }
  Eigen::LLT<Eigen::MatrixXd> llt(H);
  if (llt.info() != Eigen::Success) {
    llt.compute(Hw);
    if (llt.info() != Eigen::Success) return false;
  }
  const Eigen::MatrixXd Hinv = llt.solve(Eigen::MatrixXd::Identity(F, F));
  const Eigen::MatrixXd C = (static_cast<double>(N) / (N - F)) * Hinv * B * Hinv;
  if (!C.allFinite()) return false;
  r.covariance = Eigen::MatrixXd::Zero(P, P);
  for (int a = 0; a < F; ++a) {
    for (int b = 0; b < F; ++b) r.covariance(free[a], free[b]) = C(a, b);
  }
  return true;
}

}  // namespace

FitResult solve_with_cost(std::unique_ptr<ceres::CostFunction> cost, int num_residuals,
                          const std::vector<FitParameter>& parameters,
                          const FitOptions& options) {
  if (const std::string e = options.validate(); !e.empty()) throw InputError(e);
  const int P = static_cast<int>(parameters.size());
  TRIBOLAB_ASSERT(P > 0, "a fit needs at least one parameter");
  FitResult r;
  std::vector<double> p(P);
  std::vector<int> fixed_indices;
  for (int i = 0; i < P; ++i) {
    r.names.push_back(parameters[i].name);
    p[i] = parameters[i].initial;
    if (parameters[i].fixed) fixed_indices.push_back(i);
  }
  const int free_count = P - static_cast<int>(fixed_indices.size());
  r.values = p;
  r.sigma.assign(P, 0.0);
  r.covariance = Eigen::MatrixXd::Zero(P, P);
  r.dof = num_residuals - free_count;
  if (r.dof < 0 || (free_count > 0 && num_residuals < free_count)) {
    r.status = FitStatus::too_few_points;
    r.message = "fit needs at least " + std::to_string(free_count) + " data values for " +
                std::to_string(free_count) + " free parameters, got " +
                std::to_string(num_residuals);
    return r;
  }
  std::vector<double> res(num_residuals);
  if (!evaluate(*cost, p, res)) {
    r.status = FitStatus::failed;
    r.message = "the model cannot be evaluated at the starting values";
    return r;
  }

  std::unique_ptr<ceres::LossFunction> loss(make_loss(options));
  std::unique_ptr<ceres::CostFunction> robust;  // outlives the problem that points to it
  if (loss) robust = std::make_unique<PerResidualLoss>(cost.get(), std::move(loss));
  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  problem.AddResidualBlock(robust ? robust.get() : cost.get(), nullptr, p.data());
  if (free_count == 0) {
    problem.SetParameterBlockConstant(p.data());
  } else if (!fixed_indices.empty()) {
    problem.SetManifold(p.data(), new ceres::SubsetManifold(P, fixed_indices));
  }
  for (int i = 0; i < P; ++i) {
    if (parameters[i].fixed) continue;
    if (parameters[i].lower) problem.SetParameterLowerBound(p.data(), i, *parameters[i].lower);
    if (parameters[i].upper) problem.SetParameterUpperBound(p.data(), i, *parameters[i].upper);
  }

  ceres::Solver::Summary summary;
  if (free_count > 0) {
    ceres::Solver::Options so;
    so.linear_solver_type = ceres::DENSE_QR;
    so.max_num_iterations = options.max_iterations;
    so.function_tolerance = options.function_tolerance;
    so.parameter_tolerance = options.parameter_tolerance;
    so.gradient_tolerance = options.gradient_tolerance;
    so.logging_type = ceres::SILENT;
    so.num_threads = 1;
    ceres::Solve(so, &problem, &summary);
    r.iterations = static_cast<int>(summary.iterations.size());
  }
  r.values = p;
  evaluate(*cost, p, res);
  r.residuals = res;
  double ss = 0;
  for (double v : res) ss += v * v;
  r.cost = 0.5 * ss;
  r.rms = std::sqrt(ss / std::max(1, num_residuals));

  if (free_count > 0 && summary.termination_type != ceres::CONVERGENCE) {
    r.status = summary.termination_type == ceres::NO_CONVERGENCE ? FitStatus::no_convergence
                                                                 : FitStatus::failed;
    r.message = "least squares did not converge: " + summary.message;
    return r;
  }
  if (free_count == 0) {
    r.status = FitStatus::converged;
    r.message = "all parameters fixed";
    return r;
  }

  ceres::Covariance::Options co;
  co.algorithm_type = ceres::DENSE_SVD;
  co.null_space_rank = 0;  // rank deficiency is an error: the data do not fix every parameter
  co.min_reciprocal_condition_number = 1e-14;
  ceres::Covariance covariance(co);
  std::vector<std::pair<const double*, const double*>> blocks{{p.data(), p.data()}};
  if (!covariance.Compute(blocks, &problem)) {
    r.status = FitStatus::not_identifiable;
    r.message = "the data cannot determine every free parameter (singular Jacobian); fix one "
                "or add data";
    return r;
  }
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> c(P, P);
  covariance.GetCovarianceBlock(p.data(), p.data(), c.data());
  r.noise_scale = 1.0;
  if (!options.residuals_are_normalized) {
    r.noise_scale = r.dof > 0 ? std::sqrt(ss / r.dof) : std::numeric_limits<double>::quiet_NaN();
  }
  r.covariance = c * (r.noise_scale * r.noise_scale);
  if (options.covariance != Covariance::gauss_newton) {
    if (!sandwich_covariance(*cost, p, parameters, options, r)) {
      r.status = FitStatus::not_identifiable;
      r.message = "the data cannot determine every free parameter (singular sandwich bread); fix one "
                  "or add data";
      return r;
    }
  }
  for (int i = 0; i < P; ++i) {
    r.sigma[i] = parameters[i].fixed ? 0.0 : std::sqrt(std::max(0.0, r.covariance(i, i)));
  }
  r.status = FitStatus::converged;
  r.message = "converged in " + std::to_string(r.iterations) + " iterations";
  return r;
}

}  // namespace detail
}  // namespace tribolab::numerics
