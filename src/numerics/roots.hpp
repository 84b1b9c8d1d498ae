// Robust scalar root finding: bracketing (TOMS 748, Alefeld, Potra & Shi 1995, via
// Boost.Math) with a result struct, plus bracket search by scanning. See docs/theory.md#numerics.
#pragma once

#include <boost/math/tools/roots.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>

namespace tribolab::numerics {

struct RootOptions {
  /// Absolute tolerance on x; the bracket is shrunk until narrower than this. Default:
  /// machine precision relative to the bracket (converges to the last bit).
  double x_tol = 0.0;
  std::uintmax_t max_iterations = 200;
};

struct RootResult {
  double x = std::numeric_limits<double>::quiet_NaN();  ///< best estimate of the root
  double lo = 0, hi = 0;                                ///< final bracket, lo <= x <= hi
  std::uintmax_t iterations = 0;
  bool converged = false;
};

/// Root of f in [a, b] where f(a) and f(b) have opposite signs (or one is zero).
/// Returns converged = false (x = NaN) when [a, b] does not bracket a sign change.
template <class F>
RootResult find_root(F&& f, double a, double b, const RootOptions& options = {}) {
  RootResult r;
  if (a > b) std::swap(a, b);
  const double fa = f(a), fb = f(b);
  r.lo = a;
  r.hi = b;
  if (!std::isfinite(fa) || !std::isfinite(fb)) return r;
  if (fa == 0) return RootResult{a, a, a, 0, true};
  if (fb == 0) return RootResult{b, b, b, 0, true};
  if ((fa < 0) == (fb < 0)) return r;
  const double x_tol = options.x_tol;
  auto tol = [x_tol](double lo, double hi) {
    const double eps = 4 * std::numeric_limits<double>::epsilon() *
                       std::max(std::abs(lo), std::abs(hi));
    return hi - lo <= std::max(x_tol, eps);
  };
  std::uintmax_t iters = options.max_iterations;
  auto [lo, hi] = boost::math::tools::toms748_solve(f, a, b, fa, fb, tol, iters);
  r.lo = lo;
  r.hi = hi;
  r.iterations = iters;
  r.x = 0.5 * (lo + hi);
  r.converged = iters < options.max_iterations || tol(lo, hi);
  return r;
}

/// Scans [a, b] in `n` equal cells and returns the first cell [x_i, x_{i+1}] over which
/// f changes sign, or nullopt. Finds every root separated by more than (b - a) / n.
template <class F>
std::optional<std::pair<double, double>> first_sign_change(F&& f, double a, double b, int n) {
  double x0 = a, f0 = f(a);
  if (f0 == 0) return std::pair{a, a};
  for (int i = 1; i <= n; ++i) {
    const double x1 = a + (b - a) * i / n;
    const double f1 = f(x1);
    if (f1 == 0 || (f0 < 0) != (f1 < 0)) return std::pair{x0, x1};
    x0 = x1;
    f0 = f1;
  }
  return std::nullopt;
}

}  // namespace tribolab::numerics
