#include "numerics/least_squares.hpp"

#include "numerics/error.hpp"

#include <ceres/ceres.h>
#include <ceres/covariance.h>
#include <ceres/manifold.h>

#include <boost/math/distributions/students_t.hpp>

#include <cmath>
#include <limits>

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

std::size_t FitResult::index(const std::string& name) const {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return i;
  }
  throw InputError("fit has no parameter named '" + name + "'");
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

bool evaluate(const ceres::CostFunction& cost, const std::vector<double>& p,
              std::vector<double>& r) {
  const double* blocks[] = {p.data()};
  if (!cost.Evaluate(blocks, r.data(), nullptr)) return false;
  for (double v : r) {
    if (!std::isfinite(v)) return false;
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

  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  problem.AddResidualBlock(cost.get(), make_loss(options), p.data());
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
  for (int i = 0; i < P; ++i) {
    r.sigma[i] = parameters[i].fixed ? 0.0 : std::sqrt(std::max(0.0, r.covariance(i, i)));
  }
  r.status = FitStatus::converged;
  r.message = "converged in " + std::to_string(r.iterations) + " iterations";
  return r;
}

}  // namespace detail
}  // namespace tribolab::numerics
