// docs/theory.md#plausibility-checks.
#include "analysis/bounce_plausibility.hpp"
#include "numerics/error.hpp"

#include "numerics/polyfit.hpp"
#include "numerics/units.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <utility>

namespace tribolab::analysis {
namespace {

/// printf into a string (the core does not link fmt).
std::string format(const char* f, ...) {
  char buf[1024];
  va_list args;
  va_start(args, f);
  std::vsnprintf(buf, sizeof buf, f, args);
  va_end(args);
  return buf;
}

}  // namespace

EnergyGain energy_gain(const bounce::Ball& ball, const BounceAnalysis& r) {
  const double m = ball.mass, I = ball.inertia;
  // sd of m v^2/2 is m |v| sd(v); the touch quantities' sds are null with a bracketed floor:
  // the flight fits' own sds at the impact time stand in for them then.
  auto sd = [](double s, double fallback) { return std::isfinite(s) ? s : fallback; };
  auto var = [&](const SegmentFit& f, double vy, double s_vy) {
    const double a = m * f.vx * f.sigma_vx, b = m * vy * sd(s_vy, f.sigma_vy), c = I * f.omega * f.sigma_omega;
    return a * a + b * b + c * c;
  };
  EnergyGain g;
  g.gain = r.post.energy.total() - r.pre.energy.total();
  g.sigma = std::sqrt(var(r.pre, r.vy_touch, r.sigma_vy_touch) + var(r.post, r.vy_separation, r.sigma_vy_separation));
  // Rebound speed the energy allows once the outgoing vx and spin are paid for (seed 001's
  // energy bookkeeping: translation + rotation with the ball's inertia).
  const double left = r.pre.energy.total() - r.post.energy.translational_x - r.post.energy.rotational;
  g.e_allowed = std::sqrt(std::max(left, 0.0) / std::max(r.pre.energy.translational_y, 1e-300));
  return g;
}

namespace {

/// Frames of a flight whose centre lies far from the flight's fitted x line and y parabola.
void wild_frames(const SegmentFit& f, const BounceAnalysis& r, double limit, std::vector<double>& times, double& worst) {
  for (std::size_t i = f.begin; i < f.end; ++i) {
    const auto& row = r.body.rows[i];
    const double s = row.t - r.impact_time;
    const double d = std::hypot(row.xc - f.x_line(s), row.yc - f.y_parabola(s));
    if (d > limit) {
      times.push_back(row.t);
      worst = std::max(worst, d);
    }
  }
}

}  // namespace

void check_bounce_plausibility(const bounce::Ball& ball, BounceAnalysis& r) {
  const double E_pre = r.pre.energy.total(), E_post = r.post.energy.total();
  if (!std::isfinite(E_pre) || !std::isfinite(E_post) || E_pre < 0 || E_post < 0) {
    r.warnings.push_back(format(("the kinetic energies are not finite positive numbers (before %.4g J, after "
                                 "%.4g J): check " + field("mass") + " and " + field("inertia") +
                                 " and that both flights were fitted").c_str(),
                                E_pre, E_post));
  } else {
    const EnergyGain g = energy_gain(ball, r);
    // 3 sd of the gain, and at least 0.1 % of the arrival's energy (exact data: sd ~ 0).
    if (g.gain > 3 * g.sigma + 1e-3 * E_pre) {
      r.warnings.push_back(format(
          ("the ball leaves with more kinetic energy than it arrives with (%.4g J after, %.4g J before, "
           "translation + rotation with mass %.4g kg and inertia %.4g kg m^2; gain %.2g +- %.2g J): no passive "
           "bounce does that, and e_velocity = %.3f is above the %.3f the energy allows. Check that both tips are "
           "the ball's (not swapped or another object between flights), the length calibration, and " +
           field("inertia")).c_str(),
          E_post, E_pre, ball.mass, ball.inertia, g.gain, g.sigma, r.e_velocity, g.e_allowed));
    }
  }
  if (!std::isfinite(r.collision_angle_deg))
    r.warnings.push_back("the collision angle could not be computed at the first touch: check the tips' tracks and " +
                         field("a") + "/" + field("b"));
  if (std::isfinite(r.contact_duration) && r.contact_duration < 0)
    r.warnings.push_back(format(("the ball separates %.2f ms before it first touches the floor: the flights do not "
                                 "meet the floor in order; check " + field("floor_y") + " (file frame, m) and " +
                                 field("contact_duration")).c_str(),
                                -1e3 * r.contact_duration));
  // Wild frames: a hand, a shadow or the tracker jumping puts a point centimetres off the
  // flight. 8 robust noise sds (a Gaussian never reaches that in a few hundred frames) plus
  // 2 mm for the air drag a free-flight fit leaves (docs/theory.md#plausibility-checks).
  const double noise = std::max(r.impacts.noise_x, r.impacts.noise_y);
  const double limit = 8 * noise + 2e-3;
  std::vector<double> times;
  double worst = 0;
  wild_frames(r.pre, r, limit, times, worst);
  wild_frames(r.post, r, limit, times, worst);
  if (!times.empty()) {
    std::string list;
    for (std::size_t k = 0; k < std::min<std::size_t>(times.size(), 5); ++k)
      list += (k ? ", " : "") + format("%.4g", times[k]);
    if (times.size() > 5) list += ", ...";
    r.warnings.push_back(format(
        "%zu frame(s) of the flights lie far from the fitted flight (up to %.1f mm; the noise is %.1f mm) at t = %s "
        "s: something else was tracked there (a hand, a shadow) or the tracker jumped; the fits are pulled by them. "
        "Correct or delete those points and analyse again",
        times.size(), 1e3 * worst, 1e3 * noise, list.c_str()));
  }
}

std::string gravity_warning(double g, double sigma_g) {
  if (!(std::abs(g - kDefaultG) > 3 * sigma_g + 0.03)) return {};
  // Two decimals near 9.8; significant digits for a g far below 1 (0.0024 +- 1e-05).
  std::string w = g < 1 ? format("the flights fall at g = %.3g +- %.2g m/s^2, not 9.8: ", g, sigma_g)
                        : format("the flights fall at g = %.2f +- %.2f m/s^2, not 9.8: ", g, sigma_g);
  // Times wrong by a factor c scale g by 1/c^2: name the factor that restores 9.8.
  if (std::abs(g / kDefaultG - 1) > 0.25)
    return w + format(("the times or the lengths are wrong. If the lengths are right, the file's times must be multiplied "
                       "by %.3g (e.g. " + field("time_scale") + " %.3g times the one used; 240 fps slow motion played at 30 fps needs 0.125)").c_str(),
                      std::sqrt(g / kDefaultG), std::sqrt(g / kDefaultG));
  return w + "check the frame rate (" + field("time_scale") + "; an error of k % in it changes g by 2k %) and the length calibration";
}

std::array<double, 2> rough_gravity(const track::Track& centre) {
  const auto& p = centre.points;
  if (p.empty()) return {NAN, NAN};
  std::size_t low = 0;
  for (std::size_t i = 1; i < p.size(); ++i)
    if (p[i].y < p[low].y) low = i;
  double w = 0, sum = 0;
  // Two frames either side of the lowest are likely in contact.
  for (auto [b, e] : {std::pair<std::size_t, std::size_t>{0, low >= 2 ? low - 2 : 0}, {low + 3, p.size()}}) {
    if (e < b + 5) continue;
    std::vector<double> t, y;
    for (std::size_t i = b; i < e; ++i) t.push_back(p[i].t - p[low].t), y.push_back(p[i].y);
    try {
      const auto f = numerics::fit_polynomial(t, y, 2, "y(t)");
      const double v = std::max(4 * f.covariance(2, 2), 1e-30);
      w += 1 / v, sum += -2 * f.coef[2] / v;
    } catch (const std::exception&) {  // degenerate times: this side says nothing
    }
  }
  if (!(w > 0)) return {NAN, NAN};
  return {sum / w, std::sqrt(1 / w)};
}

std::vector<std::string> bound_warnings(const std::vector<std::string>& names, const std::vector<double>& values,
                                        const std::vector<double>& lower, const std::vector<double>& upper,
                                        const std::vector<bool>& free) {
  std::vector<std::string> out;
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (!free[k]) continue;
    // Within 1e-6 of the search range of a bound: the solver stopped on it.
    const double tol = std::isfinite(upper[k] - lower[k]) ? 1e-6 * (upper[k] - lower[k]) : 0.0;
    const bool at_low = values[k] - lower[k] <= tol, at_high = upper[k] - values[k] <= tol;
    if (!at_low && !at_high) continue;
    std::string why;
    const std::string& n = names[k];
    if (n == "e" && at_high)
      why = "the rebounds want more than a lossless normal contact returns: check the table's signs (vy_in < 0 < "
            "vy_out), the spin's sign (counter-clockwise positive), and " + field("inertia");
    else if (n == "mu" && at_high)
      why = "no friction coefficient up to 3 explains the change of vx and spin: check the spin's sign and units "
            "(rad/s) and the orientation theta_deg";
    else
      why = "the data want a value outside the law's range: the law does not describe them, or a column is in other "
            "units; fix the parameter with " + field("fix") + " or try another " + field("model");
    out.push_back("the fitted " + n + " sits at its " + (at_high ? "upper" : "lower") + " bound: " + why +
                  "; its uncertainty is not meaningful");
  }
  return out;
}

}  // namespace tribolab::analysis
