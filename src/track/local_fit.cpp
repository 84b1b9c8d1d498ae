#include "track/local_fit.hpp"

#include "track/check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace tribolab::track {

double PolyFit::value(std::size_t j, double t, double t0) const {
  double v = 0;
  const double u = t - t0;
  for (int k = order; k >= 0; --k) v = v * u + c[j][static_cast<std::size_t>(k)];
  return v;
}

PolyFit fit_polynomial(const double* t, const double* y0, const double* y1, int n, double t0,
                       int order) {
  TRACK_CHECK(order >= 0 && order <= kMaxFitOrder && n >= order + 1,
              "n = " + std::to_string(n) + ", order = " + std::to_string(order));
  const int m = order + 1;
  constexpr int M = kMaxFitTerms;
  double h = 0;
  for (int i = 0; i < n; ++i) h = std::max(h, std::abs(t[i] - t0));
  if (!(h > 0) || !std::isfinite(h)) h = 1;
  // normal equations in u = (t - t0)/h: N = A^T A (moments of u), b_j = A^T y_j
  std::array<double, 2 * M> mom{};
  std::array<std::array<double, M>, 2> b{};
  const int ny = y1 != nullptr ? 2 : 1;
  for (int i = 0; i < n; ++i) {
    const double u = (t[i] - t0) / h;
    double p = 1;
    for (int k = 0; k < 2 * m - 1; ++k) {
      mom[static_cast<std::size_t>(k)] += p;
      if (k < m) {
        b[0][static_cast<std::size_t>(k)] += p * y0[i];
        if (ny == 2) b[1][static_cast<std::size_t>(k)] += p * y1[i];
      }
      p *= u;
    }
  }
  PolyFit fit;
  fit.order = order;
  fit.points = n;
  // Cholesky N = L L^T
  std::array<double, M * M> L{};
  for (int r = 0; r < m; ++r) {
    for (int col = 0; col <= r; ++col) {
      double s = mom[static_cast<std::size_t>(r + col)];
      for (int k = 0; k < col; ++k) s -= L[static_cast<std::size_t>(r * M + k)] * L[static_cast<std::size_t>(col * M + k)];
      if (r == col) {
        if (!(s > 1e-13 * mom[0]) || !std::isfinite(s)) {  // numerically singular
          const double nan = std::numeric_limits<double>::quiet_NaN();
          for (auto& row : fit.c) row.fill(nan);
          fit.rss.fill(nan);
          fit.cov_unit.fill(nan);
          return fit;
        }
        L[static_cast<std::size_t>(r * M + r)] = std::sqrt(s);
      } else {
        L[static_cast<std::size_t>(r * M + col)] = s / L[static_cast<std::size_t>(col * M + col)];
      }
    }
  }
  auto solve = [&](const std::array<double, M>& rhs) {  // N x = rhs
    std::array<double, M> z{}, x{};
    for (int r = 0; r < m; ++r) {
      double s = rhs[static_cast<std::size_t>(r)];
      for (int k = 0; k < r; ++k) s -= L[static_cast<std::size_t>(r * M + k)] * z[static_cast<std::size_t>(k)];
      z[static_cast<std::size_t>(r)] = s / L[static_cast<std::size_t>(r * M + r)];
    }
    for (int r = m - 1; r >= 0; --r) {
      double s = z[static_cast<std::size_t>(r)];
      for (int k = r + 1; k < m; ++k) s -= L[static_cast<std::size_t>(k * M + r)] * x[static_cast<std::size_t>(k)];
      x[static_cast<std::size_t>(r)] = s / L[static_cast<std::size_t>(r * M + r)];
    }
    return x;
  };
  fit.ok = true;
  std::array<double, 2 * M> hp{};  // h^k
  hp[0] = 1;
  for (std::size_t k = 1; k < hp.size(); ++k) hp[k] = hp[k - 1] * h;
  for (int col = 0; col < m; ++col) {
    std::array<double, M> e{};
    e[static_cast<std::size_t>(col)] = 1;
    const auto x = solve(e);
    for (int r = 0; r < m; ++r) {
      fit.cov_unit[static_cast<std::size_t>(r * M + col)] =
          x[static_cast<std::size_t>(r)] / hp[static_cast<std::size_t>(r + col)];
    }
  }
  const double* ys[2] = {y0, y1};
  for (int j = 0; j < ny; ++j) {
    const auto a = solve(b[static_cast<std::size_t>(j)]);
    double rss = 0;
    for (int i = 0; i < n; ++i) {
      const double u = (t[i] - t0) / h;
      double v = 0;
      for (int k = m - 1; k >= 0; --k) v = v * u + a[static_cast<std::size_t>(k)];
      rss += (ys[j][i] - v) * (ys[j][i] - v);
    }
    fit.rss[static_cast<std::size_t>(j)] = rss;
    for (int k = 0; k < m; ++k) {
      fit.c[static_cast<std::size_t>(j)][static_cast<std::size_t>(k)] =
          a[static_cast<std::size_t>(k)] / hp[static_cast<std::size_t>(k)];
    }
  }
  return fit;
}

}  // namespace tribolab::track
