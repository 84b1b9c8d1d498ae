#include "numerics/polyfit.hpp"

#include "numerics/error.hpp"

#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tribolab::numerics {

double PolyFit::operator()(double x) const {
  double y = 0;
  for (std::size_t k = coef.size(); k-- > 0;) y = y * x + coef[k];
  return y;
}

double PolyFit::ci_half_width(int k, double level) const {
  if (dof <= 0) return std::numeric_limits<double>::quiet_NaN();
  const boost::math::students_t t(dof);
  return boost::math::quantile(boost::math::complement(t, (1.0 - level) / 2.0)) * sigma.at(k);
}

void widen_for_serial_correlation(PolyFit& f, double factor) {
  if (!(factor > 1)) return;
  f.covariance *= factor;
  for (double& sd : f.sigma) sd *= std::sqrt(factor);
}

PolyFit fit_polynomial(std::span<const double> x, std::span<const double> y, int degree,
                       const std::string& what) {
  TRIBOLAB_ASSERT(x.size() == y.size(), "x and y sizes differ");
  TRIBOLAB_ASSERT(degree >= 0, "negative degree");
  const int n = static_cast<int>(x.size());
  const int p = degree + 1;
  if (n < p + 1) {
    throw InputError(what + ": a degree-" + std::to_string(degree) + " fit needs at least " +
                     std::to_string(p + 1) + " points, got " + std::to_string(n));
  }
  // The columns are powers of x / scale (|x / scale| <= 1), the coefficients scaled back
  // below: in raw units the columns of a local fit over 25 frames at 50 kHz (|x| <= 2.5e-4 s)
  // span 1 to 4e-15 for degree 4, and QR's rank test took them for dependent (docs/theory.md#fitting).
  double scale = 0;
  for (int i = 0; i < n; ++i) {
    require_finite(x[i], what + " x value");
    require_finite(y[i], what + " y value");
    scale = std::max(scale, std::abs(x[i]));
  }
  if (!(scale > 1e-60 && scale < 1e60)) scale = 1;  // scale^degree stays finite
  Eigen::MatrixXd A(n, p);
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) {
    double xk = 1.0;
    for (int k = 0; k < p; ++k) {
      A(i, k) = xk;
      xk *= x[i] / scale;
    }
    b(i) = y[i];
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  if (qr.rank() < p) {
    throw InputError(what + ": the x values cannot determine a degree-" + std::to_string(degree) +
                     " fit (too few distinct values)");
  }
  const Eigen::VectorXd c = qr.solve(b);
  const Eigen::VectorXd r = b - A * c;
  PolyFit f;
  f.n = n;
  f.dof = n - p;
  std::vector<double> unscale(p, 1.0);  // 1 / scale^k
  for (int k = 1; k < p; ++k) unscale[k] = unscale[k - 1] / scale;
  for (int k = 0; k < p; ++k) f.coef.push_back(c(k) * unscale[k]);
  const double ss_res = r.squaredNorm();
  const double mean = b.mean();
  const double ss_tot = (b.array() - mean).square().sum();
  f.r_squared = ss_tot > 0 ? 1.0 - ss_res / ss_tot : 1.0;
  f.rms = std::sqrt(ss_res / n);
  f.noise = std::sqrt(ss_res / f.dof);
  // Cov(c) = s^2 (A^T A)^-1, computed from R of the QR: (A^T A)^-1 = P R^-1 R^-T P^T.
  const Eigen::MatrixXd R =
      qr.matrixR().topLeftCorner(p, p).template triangularView<Eigen::Upper>();
  const Eigen::MatrixXd Rinv = R.inverse();
  const Eigen::MatrixXd cov_perm = Rinv * Rinv.transpose();
  const auto& perm = qr.colsPermutation();
  f.covariance = perm * cov_perm * perm.transpose() * (f.noise * f.noise);
  for (int j = 0; j < p; ++j)
    for (int k = 0; k < p; ++k) f.covariance(j, k) *= unscale[j] * unscale[k];
  for (int k = 0; k < p; ++k) f.sigma.push_back(std::sqrt(std::max(0.0, f.covariance(k, k))));
  return f;
}

std::vector<double> least_squares_polynomial(std::span<const double> x, std::span<const double> y, int degree) {
  TRIBOLAB_ASSERT(x.size() == y.size(), "x and y sizes differ");
  TRIBOLAB_ASSERT(degree >= 0 && x.size() >= static_cast<std::size_t>(degree) + 1, "too few points for the degree");
  const auto n = static_cast<Eigen::Index>(x.size());
  Eigen::MatrixXd A(n, degree + 1);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    double xk = 1.0;
    for (int k = 0; k <= degree; ++k, xk *= x[static_cast<std::size_t>(i)]) A(i, k) = xk;
    b(i) = y[static_cast<std::size_t>(i)];
  }
  const Eigen::VectorXd c = A.colPivHouseholderQr().solve(b);
  return {c.data(), c.data() + c.size()};
}

}  // namespace tribolab::numerics
