#include "track/local_fit.hpp"

#include "numerics/error.hpp"
#include "track/check.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <string>

namespace tribolab::track {

double PolyFit::value(std::size_t j, double t, double t0) const {
  double v = 0;
  const double u = t - t0;
  for (int k = order; k >= 0; --k) v = v * u + c[j][static_cast<std::size_t>(k)];
  return v;
}

double PolyFit::slope(std::size_t j, double t, double t0) const {
  double v = 0;
  const double u = t - t0;
  for (int k = order; k >= 1; --k) v = v * u + k * c[j][static_cast<std::size_t>(k)];
  return v;
}

PolyFit fit_polynomial(const double* t, const std::vector<const double*>& ys, int n, double t0,
                       int order) {
  TRACK_CHECK(order >= 0 && n >= order + 1,
                  "n = " + std::to_string(n) + ", order = " + std::to_string(order));
  const int m = order + 1;
  double h = 0;
  for (int i = 0; i < n; ++i) h = std::max(h, std::abs(t[i] - t0));
  if (!(h > 0)) h = 1;
  Eigen::MatrixXd a(n, m);
  for (int i = 0; i < n; ++i) {
    const double u = (t[i] - t0) / h;
    double p = 1;
    for (int k = 0; k < m; ++k) {
      a(i, k) = p;
      p *= u;
    }
  }
  const Eigen::MatrixXd ata = a.transpose() * a;
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(ata);
  TRACK_CHECK(ldlt.info() == Eigen::Success, "singular normal matrix in fit_polynomial");
  const Eigen::MatrixXd inv = ldlt.solve(Eigen::MatrixXd::Identity(m, m));

  PolyFit fit;
  fit.order = order;
  fit.points = n;
  fit.cov_unit.resize(static_cast<std::size_t>(m));
  fit.cov_unit_full.resize(static_cast<std::size_t>(m * m));
  // scale back: c_k = a_k / h^k, cov(c_k, c_l) = cov(a_k, a_l) / h^(k+l)
  std::vector<double> hp(static_cast<std::size_t>(2 * m), 1.0);
  for (std::size_t k = 1; k < hp.size(); ++k) hp[k] = hp[k - 1] * h;
  for (int k = 0; k < m; ++k) {
    for (int l = 0; l < m; ++l) {
      fit.cov_unit_full[static_cast<std::size_t>(k * m + l)] =
          inv(k, l) / hp[static_cast<std::size_t>(k + l)];
    }
    fit.cov_unit[static_cast<std::size_t>(k)] = inv(k, k) / hp[static_cast<std::size_t>(2 * k)];
  }
  for (const double* y : ys) {
    Eigen::VectorXd b(n);
    for (int i = 0; i < n; ++i) b(i) = y[i];
    const Eigen::VectorXd coef = ldlt.solve(a.transpose() * b);
    const double rss = (a * coef - b).squaredNorm();
    std::vector<double> c(static_cast<std::size_t>(m));
    for (int k = 0; k < m; ++k) c[static_cast<std::size_t>(k)] = coef(k) / hp[static_cast<std::size_t>(k)];
    fit.c.push_back(std::move(c));
    fit.rss.push_back(rss);
  }
  return fit;
}

double variance_factor(const PolyFit& fit, const std::vector<double>& g) {
  const std::size_t m = static_cast<std::size_t>(fit.order + 1);
  TRACK_CHECK(g.size() == m, "gradient size mismatch");
  double v = 0;
  for (std::size_t k = 0; k < m; ++k) {
    for (std::size_t l = 0; l < m; ++l) v += g[k] * fit.cov_unit_full[k * m + l] * g[l];
  }
  return v;
}

}  // namespace tribolab::track
