// Seed 001 experiment 1, automated. docs/theory.md#bounce-analysis.
#include "analysis/bounce_analyze.hpp"

#include "analysis/bounce_glitch.hpp"
#include "analysis/bounce_impact.hpp"
#include "analysis/bounce_plausibility.hpp"
#include "analysis/bounce_touch.hpp"
#include "track/outliers.hpp"
#include "track/rigid_body.hpp"

#include "numerics/error.hpp"
#include "numerics/least_squares.hpp"
#include "numerics/roots.hpp"
#include "numerics/units.hpp"
#include "numerics/statistics.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

namespace tribolab::analysis {

using numerics::PolyFit;

std::string BounceAnalyzeOptions::validate() const {
  if (auto e = ball.validate(); !e.empty()) return e;
  if (exclude < 0 || exclude > 50) return "exclude: must lie in 0..50 points";
  if (floor_y && !std::isfinite(*floor_y)) return "floor-y: must be finite";
  if (!(std::isfinite(sigma_floor_y) && sigma_floor_y >= 0 && sigma_floor_y < 1))
    return "sigma-floor-y: must lie in [0, 1) m";
  if (contact_duration && !(std::isfinite(*contact_duration) && *contact_duration > 0))
    return "contact-duration: must be a positive number of seconds";
  if (impact < 1) return "impact: must be 1 or more";
  if (grid_points < 2 || grid_points > 100000) return "grid-points: must lie in 2..100000";
  if (auto e = impacts.validate(); !e.empty()) return e;
  return {};
}

namespace {


/// y = c0 + c1 s + c2 s^2 with c2 given (value c2, variance var_c2: another flight's fit):
/// the line through y - c2 s^2, whose coefficients move with c2 by a = -(X^T X)^-1 X^T s^2, so
/// cov(c0, c1, c2) = [[C_line + var_c2 a a^T, var_c2 a], [var_c2 a^T, var_c2]]. C_line is
/// scaled by the track's noise_y, not the residuals' of a few points (6 degrees of freedom
/// put sigma 2x too low in 1 run of 60) (docs/theory.md#bounce-analysis, "short post-impact flight").
numerics::PolyFit fit_parabola_with_curvature(const std::vector<double>& s, const std::vector<double>& y,
                                              const SegmentFit::GivenCurvature& given, const std::string& what) {
  const double c2 = given.c2, var_c2 = given.var_c2;
  std::vector<double> rest(y.size());
  for (std::size_t i = 0; i < y.size(); ++i) rest[i] = y[i] - c2 * s[i] * s[i];
  auto line = numerics::fit_polynomial(s, rest, 1, what);
  if (line.noise > 0 && given.noise_y > 0) line.covariance *= (given.noise_y / line.noise) * (given.noise_y / line.noise);
  const auto n = static_cast<Eigen::Index>(s.size());
  Eigen::MatrixXd X(n, 2);
  Eigen::VectorXd s2(n);
  for (Eigen::Index i = 0; i < n; ++i) X(i, 0) = 1, X(i, 1) = s[static_cast<std::size_t>(i)], s2(i) = X(i, 1) * X(i, 1);
  const Eigen::Vector2d a = -(X.transpose() * X).ldlt().solve(X.transpose() * s2);
  numerics::PolyFit f = line;
  f.coef.push_back(c2);
  f.covariance = Eigen::MatrixXd::Zero(3, 3);
  f.covariance.topLeftCorner(2, 2) = line.covariance + var_c2 * a * a.transpose();
  f.covariance.block(0, 2, 2, 1) = var_c2 * a;
  f.covariance.block(2, 0, 1, 2) = var_c2 * a.transpose();
  f.covariance(2, 2) = var_c2;
  f.sigma = {std::sqrt(f.covariance(0, 0)), std::sqrt(f.covariance(1, 1)), std::sqrt(var_c2)};
  double mean = 0, tot = 0, res = 0;
  for (double v : y) mean += v / static_cast<double>(y.size());
  for (std::size_t i = 0; i < y.size(); ++i) tot += (y[i] - mean) * (y[i] - mean), res += (y[i] - f(s[i])) * (y[i] - f(s[i]));
  f.r_squared = tot > 0 ? 1 - res / tot : 1.0;
  return f;
}

/// Fits the line and parabola of rows [begin, end) with s = t - t0; the parabola's curvature
/// is seg.given_c2 when that is set (a flight too short to measure gravity).
void fit_segment(const std::vector<track::RigidBodyRow>& rows, SegmentFit& seg, double t0,
                 const char* what) {
  std::vector<double> s, x, y;
  for (std::size_t i = seg.begin; i < seg.end; ++i) {
    s.push_back(rows[i].t - t0);
    x.push_back(rows[i].xc);
    y.push_back(rows[i].yc);
  }
  seg.x_line = numerics::fit_polynomial(s, x, 1, std::string(what) + " x(t)");
  seg.y_parabola = seg.given_c2 ? fit_parabola_with_curvature(s, y, *seg.given_c2, std::string(what) + " y(t)")
                                : numerics::fit_polynomial(s, y, 2, std::string(what) + " y(t)");
  // Residuals correlated in time (a tracker's smooth error) widen both fits' covariances
  // (docs/theory.md#fitting, "Serially correlated residuals").
  std::vector<std::vector<double>> residuals(2);
  for (std::size_t i = 0; i < s.size(); ++i) {
    residuals[0].push_back(x[i] - seg.x_line(s[i]));
    residuals[1].push_back(y[i] - seg.y_parabola(s[i]));
  }
  const double f = numerics::serial_correlation_factor(residuals);
  numerics::widen_for_serial_correlation(seg.x_line, f);
  numerics::widen_for_serial_correlation(seg.y_parabola, f);
}

/// Apex of y = c0 + c1 s + c2 s^2 (c2 < 0): s* = -c1 / (2 c2), y* = c0 - c1^2 / (4 c2).
std::array<double, 2> vertex(const std::vector<double>& c) {
  return {-c[1] / (2 * c[2]), c[0] - c[1] * c[1] / (4 * c[2])};
}

/// Drops points at the impact end of a segment while they disagree with the free flight of
/// the rest: the frames during the contact (a rugby ball stays on the floor 10-20 ms, several
/// frames at 240 fps). A point is in contact when its x, y or theta misses the prediction of
/// the line / parabola / spin line fitted to the others by more than kTrimSd noise sds. A low
/// threshold is cheap (a good flight point dropped by mistake costs one point of many) and
/// catches the late contact frames whose deviation is small but systematic.
/// docs/theory.md#bounce-analysis.
void trim_contact_frames(const std::vector<track::RigidBodyRow>& rows, SegmentFit& seg, bool at_end,
                         double noise_x, double noise_y, int min_points) {
  while (static_cast<int>(seg.end - seg.begin) > min_points) {
    const std::size_t k = at_end ? seg.end - 1 : seg.begin;
    SegmentFit rest = seg;
    if (at_end) {
      --rest.end;
    } else {
      ++rest.begin;
    }
    fit_segment(rows, rest, rows[k].t, "segment");
    const auto spin = track::fit_spin(rows, rest.begin, rest.end);
    const double rx = rows[k].xc - rest.x_line.coef[0];
    const double ry = rows[k].yc - rest.y_parabola.coef[0];
    const double rt = rows[k].theta - (spin.theta_ref + spin.omega * (rows[k].t - spin.t_ref));
    const double theta_noise = std::max(spin.rms_residual, 1e-6);
    constexpr double kTrimSd = 3;
    if (std::abs(rx) > kTrimSd * noise_x || std::abs(ry) > kTrimSd * noise_y || std::abs(rt) > kTrimSd * theta_noise) {
      seg = rest;
    } else {
      break;
    }
  }
}

/// Gravity seen by the two flights: ay from the y parabolas, ax from x parabolas (a free
/// flight has none), inverse-variance means over the flights. A frame-rate error of k %
/// changes |g| by about 2k %; a camera turned by alpha tilts g by alpha. Warns when either is
/// significant (3 sd; |g| also beyond the 9.78-9.83 m/s^2 of the Earth's surface).
void check_gravity(const std::vector<track::RigidBodyRow>& rows, BounceAnalysis& r) {
  double wx = 0, sx = 0, wy = 0, sy = 0;
  for (const SegmentFit* seg : {&r.pre, &r.post}) {
    if (seg->given_c2) continue;  // its curvature is the other flight's: no measurement of g
    std::vector<double> s, x;
    for (std::size_t i = seg->begin; i < seg->end; ++i) {
      s.push_back(rows[i].t - r.impact_time);
      x.push_back(rows[i].xc);
    }
    const auto q = numerics::fit_polynomial(s, x, 2, "x(t)");
    const double vax = std::max(4 * q.covariance(2, 2), 1e-30), vay = std::max(4 * seg->y_parabola.covariance(2, 2), 1e-30);
    wx += 1 / vax, sx += 2 * q.coef[2] / vax;
    wy += 1 / vay, sy += 2 * seg->y_parabola.coef[2] / vay;
  }
  const double ax = sx / wx, ay = sy / wy, vax = 1 / wx, vay = 1 / wy;
  const double g = std::hypot(ax, ay);
  r.gravity = g;
  r.sigma_gravity = std::sqrt(ax * ax * vax + ay * ay * vay) / g;
  r.gravity_tilt_deg = to_deg(std::atan2(ax, -ay));
  r.sigma_gravity_tilt_deg = to_deg(std::sqrt(ay * ay * vax + ax * ax * vay) / (g * g));
  auto fmt = [](double v, int digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return std::string(buf);
  };
  if (std::string w = gravity_warning(g, r.sigma_gravity); !w.empty()) r.warnings.push_back(std::move(w));
  if (std::abs(r.gravity_tilt_deg) > 3 * r.sigma_gravity_tilt_deg)
    r.warnings.push_back("gravity is tilted by " + fmt(r.gravity_tilt_deg, 2) + " +- " + fmt(r.sigma_gravity_tilt_deg, 2) +
                         " deg from the file's -y axis: the camera or the axes are turned; orientations and the "
                         "collision angle carry this tilt (level the axes and analyse again)");
}

}  // namespace

const char* to_string(FloorMethod m) {
  switch (m) {
    case FloorMethod::contact_duration: return "contact_duration";
    case FloorMethod::bracket: return "bracket";
    case FloorMethod::given: break;
  }
  return "given";
}

const char* to_string(ForceDurationMethod m) { return m == ForceDurationMethod::given ? "given" : "located"; }

namespace {

// A parabola with a noise estimate needs 4 points; the spin fit's sigma 3. Ask for 5.
constexpr int kMinPoints = 5;

/// Throws InputError unless tracks `a` and `b` are marked in at least two common frames
/// (docs/theory.md#bounce-analysis: the body needs both tips in one frame).
void require_common_frames(const track::Track& a, const track::Track& b) {
  std::size_t common = 0;
  std::size_t j = 0;
  for (const auto& p : a.points) {
    while (j < b.points.size() && b.points[j].frame < p.frame) ++j;
    if (j < b.points.size() && b.points[j].frame == p.frame) ++common;
  }
  if (common < 2) {
    throw InputError("tracks '" + a.name + "' and '" + b.name + "' share " + std::to_string(common) +
                     " frame(s); the tips must be marked in the same frames");
  }
}

/// True when points [seg.begin, seg.end) of `centre`, between two detected impacts, are no
/// rebound: too few for a parabola, or a y parabola with no apex inside them (falling all
/// along, or still rising at the next touch). bounce::simulate_impact's whole impact goes on
/// through such a flight (docs/theory.md#bounce-analysis, repeated contacts).
bool is_hop(const track::Track& centre, const track::Segment& seg) {
  if (seg.size() < static_cast<std::size_t>(kMinPoints)) return true;
  std::vector<double> t, y;
  for (std::size_t i = seg.begin; i < seg.end; ++i) t.push_back(centre.points[i].t), y.push_back(centre.points[i].y);
  const auto p = numerics::fit_polynomial(t, y, 2, "flight between impacts y(t)");
  if (!(p.coef[2] < 0)) return true;
  const double apex = -p.coef[1] / (2 * p.coef[2]);
  return !(apex > t.front() && apex < t.back());
}

/// Why no impact was found, for the message: when the centre falls to its lowest point and then
/// never rises above it by more than 3 times the position noise, the ball landed without a
/// rebound the track can show (a low, short hop under noise); "" otherwise (no velocity jump).
std::string no_rebound_reason(const track::Track& centre, double noise) {
  // On y averaged over 5 points (noise / sqrt 5), so that the extremes of the noise alone
  // stay well inside 3 sds of a single point.
  const auto& p = centre.points;
  constexpr std::size_t w = 5;
  if (p.size() < 4 * w || !(noise > 0)) return {};
  std::vector<double> y(p.size() - w + 1);
  for (std::size_t i = 0; i < y.size(); ++i) {
    for (std::size_t k = 0; k < w; ++k) y[i] += p[i + k].y;
    y[i] /= w;
  }
  const auto low = static_cast<std::size_t>(std::min_element(y.begin(), y.end()) - y.begin());
  if (low < w || low + w > y.size()) return {};  // still falling at the end (no landing), or no fall
  const double fall = *std::max_element(y.begin(), y.begin() + static_cast<std::ptrdiff_t>(low)) - y[low];
  const double rise = *std::max_element(y.begin() + static_cast<std::ptrdiff_t>(low), y.end()) - y[low];
  if (!(fall > 10 * noise) || !(rise < 3 * noise)) return {};
  auto mm = [](double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.1f mm", v * 1000);
    return std::string(b);
  };
  char t[32];
  std::snprintf(t, sizeof t, "%.3f s", p[low + w / 2].t);
  return "the ball falls " + mm(fall) + " to its lowest point near t = " + t + " and then rises at most " + mm(rise) +
         " above it (5-point means), within 3 times the position noise (~" + mm(noise) +
         "): no rebound flight the track can show, so e cannot be measured; a larger image of the ball (less noise) "
         "or a higher frame rate is needed";
}

/// When the track's lowest point lies within its last kMinPoints - 1 points (the ball left
/// the view, or the film ended, just after the bounce), why no rebound can be measured; ""
/// otherwise (the impact detector's windows need points on both sides of a jump, so such a
/// bounce shows none).
std::string ends_after_lowest(const track::Track& centre) {
  const auto& p = centre.points;
  if (p.size() < static_cast<std::size_t>(2 * kMinPoints)) return {};
  const auto low = static_cast<std::size_t>(
      std::min_element(p.begin(), p.end(), [](const auto& u, const auto& v) { return u.y < v.y; }) - p.begin());
  const std::size_t after = p.size() - 1 - low;
  if (after >= static_cast<std::size_t>(kMinPoints) || low < static_cast<std::size_t>(kMinPoints)) return {};
  char t[32];
  std::snprintf(t, sizeof t, "%.3f s", p[low].t);
  return "the track ends " + std::to_string(after) + " point(s) after its lowest one (t = " + t +
         "): a post-impact flight needs at least " + std::to_string(kMinPoints) +
         "; keep the ball in view (and filming) longer after it bounces";
}

/// The impact options.impact of the centre track and the flights on either side of it, less
/// options.exclude points next to it (docs/theory.md#bounce-analysis). Fills r.impacts,
/// r.impact_used, r.pre and r.post's ranges; throws InputError when there is no such impact
/// or a flight keeps fewer than kMinPoints points.
track::Impact choose_impact(const track::Track& a, const track::Track& b, const BounceAnalyzeOptions& options,
                            BounceAnalysis& r) {
  r.impacts = track::detect_impacts(r.centre, options.impacts);
  // The floor can only push the ball up: a "jump" that makes it fall faster (dvy < 0) is the
  // detector's windows reaching across a bounce at the track's end, not an impact with the floor.
  std::erase_if(r.impacts.impacts, [](const track::Impact& i) { return !(i.dvy > 0); });
  // A contact of many frames or a noisy track shows no jump between adjacent windows: look
  // across a gap of contact frames with wider windows (detail::find_impact_across_gap).
  std::size_t first_post = 0;
  if (r.impacts.impacts.empty()) {
    if (const auto g = detail::find_impact_across_gap(r.centre, r.impacts, options.impacts)) {
      r.impacts.impacts.push_back(g->impact);
      first_post = g->first_post;
    }
  }
  if (r.impacts.impacts.empty()) {
    std::string why = ends_after_lowest(r.centre);
    if (why.empty()) why = no_rebound_reason(r.centre, r.impacts.noise_y);
    throw InputError("no impact found in the centre track of '" + a.name + "' and '" + b.name + "' (" +
                     (why.empty() ? "no significant velocity jump; position noise ~" +
                                        std::to_string(r.impacts.noise_y * 1000).substr(0, 5) + " mm"
                                  : why) +
                     ")");
  }
  // The whole impacts: a detected impact followed by a flight that never reaches its apex
  // before the next one (the ball leaves still moving down, or touches again while rising)
  // is one impact with it, as bounce::simulate_impact follows it.
  const auto& found = r.impacts.impacts;
  const auto segs = track::flight_segments(r.centre.points.size(), found);
  std::vector<std::pair<std::size_t, std::size_t>> whole;  // first and last detected impact
  for (std::size_t k = 0; k < found.size(); ++k) {
    if (!whole.empty() && whole.back().second + 1 == k && is_hop(r.centre, segs[k])) {
      whole.back().second = k;
    } else {
      whole.emplace_back(k, k);
    }
  }
  if (static_cast<std::size_t>(options.impact) > whole.size()) {
    throw InputError(field("impact"), "asked for impact " + std::to_string(options.impact) + " but only " +
                                     std::to_string(whole.size()) + " found");
  }
  const auto [first, last] = whole[static_cast<std::size_t>(options.impact - 1)];
  r.impact_used = first;
  // centre_track has one point per body row, so track indices are row indices.
  const track::Segment in = segs[first], out = segs[last + 1];
  const auto ex = static_cast<std::size_t>(options.exclude);
  r.pre.begin = in.begin;
  r.pre.end = in.end > in.begin + ex ? in.end - ex : in.begin;
  r.post.begin = std::min(std::max(out.begin, first_post) + ex, out.end);
  r.post.end = out.end;
  r.pre.n_points = static_cast<int>(r.pre.end - r.pre.begin);
  r.post.n_points = static_cast<int>(r.post.end - r.post.begin);
  for (const auto* seg : {&r.pre, &r.post}) {
    if (seg->n_points < kMinPoints) {
      const bool track_ends = seg == &r.post && seg->end == r.centre.points.size();
      throw InputError(std::string(seg == &r.pre ? "pre" : "post") + "-impact segment has " +
                       std::to_string(seg->n_points) + " usable point(s) (after excluding " +
                       std::to_string(options.exclude) + " next to the impact); at least " +
                       std::to_string(kMinPoints) + " are needed for a y-t parabola" +
                       (track_ends ? std::string("; the track ends there: keep the ball in view (and filming) longer "
                                                 "after it bounces")
                                   : std::string()));
    }
  }
  if (first == last) return found[first];
  // Several contacts: the detector's time of the first stands for the whole (the fits then
  // find where the flights' parabolas meet, within the gap between them).
  track::Impact imp = found[first];
  for (std::size_t k = first + 1; k <= last; ++k) imp.dvx += found[k].dvx, imp.dvy += found[k].dvy;
  imp.t = 0.5 * (r.centre.points[in.end - 1].t + r.centre.points[out.begin].t);
  return imp;
}

/// The median time between consecutive rows, s: the frame period (it sets the uncertainty of a
/// contact duration counted in frames, docs/theory.md#bounce-analysis).
double median_frame_period(const std::vector<track::RigidBodyRow>& rows) {
  std::vector<double> dts;
  for (std::size_t i = 1; i < rows.size(); ++i) dts.push_back(rows[i].t - rows[i - 1].t);
  return upper_median(std::move(dts));
}

/// Where the two fitted y parabolas (in s = t - t_detect) meet: the root nearest the
/// detector's time t_detect within the gap widened by its length on both sides, else
/// t_detect itself (docs/theory.md#bounce-analysis, the impact time).
double parabolas_meeting_time(const std::vector<track::RigidBodyRow>& rows, const BounceAnalysis& r,
                              double t_detect) {
  const auto& p = r.pre.y_parabola.coef;
  const auto& q = r.post.y_parabola.coef;
  const double A = p[2] - q[2], B = p[1] - q[1], C = p[0] - q[0];
  const double lo = rows[r.pre.end - 1].t - t_detect, hi = rows[r.post.begin].t - t_detect;
  double best = NAN;
  auto consider = [&](double s) {
    if (std::isfinite(s) && s >= lo - (hi - lo) && s <= hi + (hi - lo) &&
        (!std::isfinite(best) || std::abs(s) < std::abs(best)))
      best = s;
  };
  if (std::abs(A) > 1e-12 * (std::abs(B) + 1)) {
    const double disc = B * B - 4 * A * C;
    if (disc >= 0) {
      const double sq = std::sqrt(disc);
      consider((-B + sq) / (2 * A));
      consider((-B - sq) / (2 * A));
    }
  } else if (B != 0) {
    consider(-C / B);
  }
  return std::isfinite(best) ? t_detect + best : t_detect;
}

/// A flight's quantities at the impact time from its fits (fitted about t_imp): velocities,
/// vertical acceleration, spin, apex, kinetic energy, and the fitted curves on a grid of
/// options.grid_points times over the flight for figures (docs/theory.md#bounce-analysis).
void describe_flight(const std::vector<track::RigidBodyRow>& rows, double t_imp, const bounce::Ball& ball,
                     int grid_points, SegmentFit& seg) {
  seg.grid_t.clear(), seg.grid_x.clear(), seg.grid_y.clear(), seg.grid_theta.clear();
  seg.vx = seg.x_line.coef[1];
  seg.sigma_vx = seg.x_line.sigma[1];
  seg.vy = seg.y_parabola.coef[1];
  seg.sigma_vy = seg.y_parabola.sigma[1];
  seg.acceleration_y = 2 * seg.y_parabola.coef[2];
  seg.sigma_acceleration_y = 2 * seg.y_parabola.sigma[2];
  seg.spin = track::fit_spin(rows, seg.begin, seg.end);
  seg.omega = seg.spin.omega;
  seg.sigma_omega = seg.spin.sigma_omega;
  const auto v = vertex(seg.y_parabola.coef);
  seg.apex_time = t_imp + v[0];
  seg.apex_y = v[1];
  seg.energy.translational_x = 0.5 * ball.mass * seg.vx * seg.vx;
  seg.energy.translational_y = 0.5 * ball.mass * seg.vy * seg.vy;
  seg.energy.rotational = 0.5 * ball.inertia * seg.omega * seg.omega;
  const double t_lo = rows[seg.begin].t, t_hi = rows[seg.end - 1].t;
  const int n = grid_points;
  for (int k = 0; k < n; ++k) {
    const double t = t_lo + (t_hi - t_lo) * k / (n - 1);
    seg.grid_t.push_back(t);
    seg.grid_x.push_back(seg.x_line(t - t_imp));
    seg.grid_y.push_back(seg.y_parabola(t - t_imp));
    seg.grid_theta.push_back(seg.spin.theta_ref + seg.omega * (t - seg.spin.t_ref));
  }
}

/// The floor's height from the two flights (docs/theory.md#bounce-analysis, "floor").
///
/// Restitution from apex heights over the floor. The floor, unless given (recommended: the
/// seed sets y = 0 on the floor in Tracker), is bracketed by the fitted flights: with
/// h(t) = y(t) - Y(theta(t)) the height of the lowest point, the ball touches between the
/// last sure pre-impact flight frame t1 and impact_time (the centroid of the normal impulse,
/// after the touch) and separates between impact_time and the first post-impact flight
/// frame t4 (sure flight). h_pre falls through the floor at the touch and h_post rises through it at the
/// separation, so  max(h_pre(t_imp), h_post(t_imp)) <= floor <= min(h_pre(t1), h_post(t4)).
/// The bracket is wide (its lower end is the extrapolated flights' depth at the impulse
/// centroid, ~1-2 cm for a rugby ball) but never wrong; give floor_y for a sharp e_height.
/// The estimate is the bracket's middle, its half-width w entering the uncertainty as a
/// uniform error (sd w / sqrt 3).
///
/// With a contact duration T (and no floor), the floor follows from the flights alone: the
/// touch t_c and the separation t_c + T both lie on the floor, h_pre(t_c) = floor =
/// h_post(t_c + T), and t_c lies in [t_imp - T, t_imp] because the impulse centroid t_imp lies
/// inside the contact. g(t) = h_pre(t) - h_post(t + T) decreases (h_pre falls, h_post rises)
/// from g(t_imp - T) > 0 to g(t_imp) < 0, so its root is unique. T counted from frames is
/// uncertain by a uniform frame period: sd dt / sqrt 12, propagated by dfloor/dT.
struct FloorFromFlights {
  const BounceAnalyzeOptions& options;
  const BounceAnalysis& r;
  double t_imp, theta_imp, theta_post0;
  double t1, t4;  ///< the last sure pre-impact and first sure post-impact flight frames, s
  double frame_dt;

  static double poly(const std::vector<double>& c, double s) { return c[0] + s * (c[1] + s * c[2]); }

  /// {floor, half-width of a bracket (0 otherwise), sd of the floor from what is not in the
  /// fit covariances (bracket or T)} for the y parabolas p (pre) and q (post).
  std::array<double, 3> floor_of(const std::vector<double>& p, const std::vector<double>& q) const {
    if (options.floor_y.has_value()) return {*options.floor_y, 0.0, 0.0};
    const bounce::Ball& ball = options.ball;
    auto h_pre = [&](double t) { return poly(p, t - t_imp) - bounce::support_depth(ball, theta_imp + r.pre.omega * (t - t_imp)); };
    auto h_post = [&](double t) { return poly(q, t - t_imp) - bounce::support_depth(ball, theta_post0 + r.post.omega * (t - t_imp)); };
    if (options.contact_duration) {
      auto floor_for = [&](double T) {
        const auto root = numerics::find_root([&](double t) { return h_pre(t) - h_post(t + T); }, t_imp - T, t_imp);
        return root.converged ? h_pre(root.x) : NAN;
      };
      const double T = *options.contact_duration;
      const double f = floor_for(T);
      const double dT = 1e-3 * T;
      const double slope = (floor_for(T + dT) - floor_for(T - dT)) / (2 * dT);
      if (std::isfinite(f) && std::isfinite(slope)) return {f, 0.0, std::abs(slope) * frame_dt / std::sqrt(12.0)};
    }
    const double lo = std::max(h_pre(t_imp), h_post(t_imp));
    const double hi = std::min(h_pre(t1), h_post(t4));
    return {0.5 * (lo + hi), 0.5 * std::abs(hi - lo), 0.5 * std::abs(hi - lo) / std::sqrt(3.0)};
  }

  /// {floor + shift, apex height over it before, after}.
  std::array<double, 3> apex_heights(const std::vector<double>& p, const std::vector<double>& q, double shift) const {
    const double floor = floor_of(p, q)[0] + shift;
    const double H = vertex(p)[1] - floor, H2 = vertex(q)[1] - floor;
    return std::array<double, 3>{floor, H, H2};
  }
};

/// The floor, the apex heights over it and e_height = sqrt(H'/H) with their uncertainties,
/// propagated linearly through the 6 parabola coefficients (two independent blocks) and the
/// floor's own error, with central differences of the closed forms
/// (docs/theory.md#bounce-analysis, "e from apex heights").
void estimate_floor_and_e_height(const FloorFromFlights& ff, BounceAnalysis& r) {
  const bool floor_given = ff.options.floor_y.has_value();
  const auto floor0 = ff.floor_of(r.pre.y_parabola.coef, r.post.y_parabola.coef);
  r.floor_half_width = floor0[1];
  r.floor_method = floor_given ? FloorMethod::given
                   : (floor0[1] == 0 ? FloorMethod::contact_duration : FloorMethod::bracket);
  const auto& pc = r.pre.y_parabola.coef;
  const auto& qc = r.post.y_parabola.coef;
  const auto base = ff.apex_heights(pc, qc, 0.0);
  r.floor_y = base[0];
  r.pre.apex_height = base[1];
  r.post.apex_height = base[2];
  // A parabola opening upwards (noise on a short segment) has no apex: no e_height.
  const bool apexes = pc[2] < 0 && qc[2] < 0;
  if (!apexes) r.pre.apex_height = r.post.apex_height = NAN;
  r.e_height = (apexes && base[1] > 0 && base[2] >= 0) ? std::sqrt(base[2] / base[1]) : NAN;
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(7, 7);
  cov.topLeftCorner(3, 3) = r.pre.y_parabola.covariance;
  cov.block(3, 3, 3, 3) = r.post.y_parabola.covariance;
  cov(6, 6) = floor0[2] * floor0[2];  // the floor's own error: bracket (uniform) or T
  Eigen::MatrixXd J(3, 7);  // rows: H, H', e_height; columns: 6 coefficients, floor shift
  for (int k = 0; k < 7; ++k) {
    auto p = pc, q = qc;
    double shift = 0;
    double& c = k < 3 ? p[k] : (k < 6 ? q[k - 3] : shift);
    const double h = k < 6 ? 1e-6 * (std::abs(c) + 1e-3) : 1e-7;
    c += h;
    const auto up = ff.apex_heights(p, q, shift);
    c -= 2 * h;
    const auto dn = ff.apex_heights(p, q, shift);
    J(0, k) = (up[1] - dn[1]) / (2 * h);
    J(1, k) = (up[2] - dn[2]) / (2 * h);
    J(2, k) = (std::sqrt(up[2] / up[1]) - std::sqrt(dn[2] / dn[1])) / (2 * h);
  }
  const Eigen::MatrixXd C = J * cov * J.transpose();
  r.pre.sigma_apex_height = apexes ? std::sqrt(C(0, 0)) : NAN;
  r.post.sigma_apex_height = apexes ? std::sqrt(C(1, 1)) : NAN;
  r.sigma_e_height = std::isfinite(r.e_height) ? std::sqrt(C(2, 2)) : NAN;
  // A bracketed floor is not trusted for e_height: at 240 fps the bracket missed the truth in
  // 200 of 200 synthetic runs (late contact frames pass the trim test and t4 falls inside the
  // contact), so e_height is reported only with floor_y or contact_duration.
  if (r.floor_method == FloorMethod::bracket) r.e_height = r.sigma_e_height = NAN;
}

/// The pre-impact flight's fitted curvature for the post-impact flight, with the track's noise.
SegmentFit::GivenCurvature pre_curvature(const SegmentFit& pre, double noise_y) {
  return {pre.y_parabola.coef[2], pre.y_parabola.covariance(2, 2), noise_y};
}

/// A post-impact flight too short to measure gravity (a low hop ended by the next touch: the
/// issue-27 throw at 60 deg, -10 rad/s, 0.7 m leaves at 0.23 m/s and lands again 8 frames
/// later) leaves its free parabola's curvature, and with it the velocity at the separation,
/// undetermined. The ball flies freely in both flights under the same gravity, seen by the same
/// camera: when the free fit's acceleration is uncertain by more than a quarter of the
/// pre-impact flight's, the post-impact parabola takes the pre-impact curvature (with its
/// variance) and fits only its position and velocity. The free fit's sigma of 2 c2 grows as
/// n^-1/2 T^-2: a post flight of 0.1 s or more at 5 mm of noise stays far below the limit.
/// docs/theory.md#bounce-analysis ("short post-impact flight").
void use_pre_gravity_if_post_too_short(const std::vector<track::RigidBodyRow>& rows, double t0, BounceAnalysis& r) {
  fit_segment(rows, r.pre, t0, "pre-impact");
  fit_segment(rows, r.post, t0, "post-impact");
  const double a_pre = 2 * r.pre.y_parabola.coef[2], sigma_a_post = 2 * r.post.y_parabola.sigma[2];
  constexpr double kMaxRelativeSigma = 0.25;
  if (!(sigma_a_post <= kMaxRelativeSigma * std::abs(a_pre))) r.post.given_c2 = pre_curvature(r.pre, r.impacts.noise_y);
}

/// One pass of the flight fits (docs/theory.md#bounce-analysis): both flights fitted about
/// the detector's time, then about the time their parabolas meet; the flights described
/// there; the orientation and collision angle at that time; the floor and e_height; the
/// first touch and the separation (detail::locate_touch).
void fit_flights_once(const std::vector<track::RigidBodyRow>& rows, const track::Impact& imp,
                      const BounceAnalyzeOptions& options, double frame_dt, BounceAnalysis& r) {
  r.warnings.clear();
  fit_segment(rows, r.pre, imp.t, "pre-impact");
  if (r.post.given_c2) r.post.given_c2 = pre_curvature(r.pre, r.post.given_c2->noise_y);
  fit_segment(rows, r.post, imp.t, "post-impact");
  const double t_imp = parabolas_meeting_time(rows, r, imp.t);
  r.impact_time = t_imp;
  fit_segment(rows, r.pre, t_imp, "pre-impact");
  fit_segment(rows, r.post, t_imp, "post-impact");

  const bounce::Ball& ball = options.ball;
  for (SegmentFit* seg : {&r.pre, &r.post}) describe_flight(rows, t_imp, ball, options.grid_points, *seg);

  // Orientation at the impulse centroid (kept as theta_impact_deg; the collision angle is
  // moved to the first touch by locate_touch below).
  const double theta_imp = r.pre.spin.theta_ref + r.pre.omega * (t_imp - r.pre.spin.t_ref);
  r.theta_impact_deg = to_deg(bounce::wrap_angle(theta_imp));
  r.collision_angle_deg = bounce::collision_angle_deg(ball, theta_imp, r.pre.vx >= 0 ? 1 : -1);

  r.floor_given = options.floor_y.has_value();
  const double theta_post0 = r.post.spin.theta_ref + r.post.omega * (t_imp - r.post.spin.t_ref);
  // The frame next to the contact may itself be early (or late) in the contact: its motion
  // hardly differs from flight while the force is small. So t1 and t4 are taken one frame
  // further out, where the ball is surely in flight.
  const double t1 = rows[r.pre.end - 2].t, t4 = rows[r.post.begin + 1].t;
  const FloorFromFlights ff{options, r, t_imp, theta_imp, theta_post0, t1, t4, frame_dt};
  estimate_floor_and_e_height(ff, r);

  // First touch and separation on the fitted flights; the collision angle, e (as bounce
  // simulate defines it), the contact point's velocity and the mean normal force there.
  detail::locate_touch(options, frame_dt, t1, t4, r);
}

/// Drops the frames of each flight that lie inside the located contact (after the touch,
/// before the separation), keeping kMinPoints; true when any was dropped: the flights are
/// then fitted again (docs/theory.md#bounce-analysis, contact frames).
bool drop_frames_inside_contact(const std::vector<track::RigidBodyRow>& rows, BounceAnalysis& r) {
  bool dropped = false;
  while (static_cast<int>(r.pre.end - r.pre.begin) > kMinPoints && rows[r.pre.end - 1].t > r.t_touch) {
    --r.pre.end;
    dropped = true;
  }
  while (static_cast<int>(r.post.end - r.post.begin) > kMinPoints && rows[r.post.begin].t < r.t_separation) {
    ++r.post.begin;
    dropped = true;
  }
  r.pre.n_points = static_cast<int>(r.pre.end - r.pre.begin);
  r.post.n_points = static_cast<int>(r.post.end - r.post.begin);
  return dropped;
}

/// The frames each flight lost to the located contact (drop_frames_inside_contact) were in
/// contact only if the ball's lowest point there, as measured (centre and orientation of the
/// frame itself), is not far below the floor: a real contact compresses the ball by less than
/// kMaxDeformation, while a floor (or T) too high by 10 cm or more (another origin, other
/// units) puts flight frames that far "under" it. Throws InputError naming the option when two or
/// more lost frames lie below the floor by more than kMaxDeformation plus 4 sds of the
/// measured lowest point (docs/theory.md#bounce-analysis). A low rebound or a repeated
/// contact loses many frames to a correct floor: their count alone says nothing.
void require_plausible_floor(const std::vector<track::RigidBodyRow>& rows, const bounce::Ball& ball,
                             std::size_t pre_trimmed_end, std::size_t post_trimmed_begin, const BounceAnalysis& r) {
  // 3 cm: above the largest compression of the synthetic contacts (the seed's law: up to
  // 1.8 cm at 3.4 m/s over bounce_grid_test's grid, checked there, bounce::simulate_contact's
  // max_penetration) and below the 10 cm or more a wrong origin or unit puts between the
  // floor and the flights.
  constexpr double kMaxDeformation = 0.03;
  const double theta_noise = std::max({r.pre.spin.rms_residual, r.post.spin.rms_residual, 0.0});
  const double sd_h = std::hypot(std::max(r.impacts.noise_y, 1e-6), ball.a * theta_noise);
  const double limit = r.floor_y - kMaxDeformation - 4 * sd_h;
  int below = 0;
  auto count = [&](std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i) below += rows[i].yc - bounce::support_depth(ball, rows[i].theta) < limit;
  };
  count(r.pre.end, pre_trimmed_end);
  count(post_trimmed_begin, r.post.begin);
  if (below >= 2) {
    const std::string what = r.floor_method == FloorMethod::given              ? field("floor_y")
                             : r.floor_method == FloorMethod::contact_duration ? field("contact_duration")
                                                                               : std::string("floor");
    throw InputError(what, "puts the ball on the floor during " + std::to_string(below) +
                               " frames where its lowest point is more than 3 cm below it (the ball would be pressed "
                               "into the floor); check the floor's height (file frame, m) and the contact duration");
  }
}

/// A spin near half a turn per frame is ambiguous. A ball seen as an ellipse looks the same
/// after half a turn, so its ends' tracks, with A and B exchanged in every other frame, fit a
/// spin of omega - sign(omega) pi / dt as well: a tracker (or a person clicking the tips) takes
/// the smaller turn, and across the bounce the turn nearest the one before. Warns when a flight
/// turns more than track::kAmbiguousTurnDeg per frame, or the spin changes by more than that
/// across the impact (docs/theory.md#plausibility-checks, "Spin near half a turn per frame").
void check_spin_aliasing(double frame_dt, BounceAnalysis& r) {
  using track::kAmbiguousTurnDeg;
  if (!(frame_dt > 0)) return;
  const double fps = 1 / frame_dt, half_turn = kPi / frame_dt;  // rad/s
  const auto deg_per_frame = [&](double omega) { return std::abs(omega) * frame_dt * 180 / kPi; };
  const auto other = [&](double omega) { return omega - std::copysign(half_turn, omega); };
  // The frame rate that keeps either reading under 60 degrees per frame.
  const auto remedy = [&](double one, double another) {
    const double fps_needed = std::max(std::abs(one), std::abs(another)) * 180 / kPi / 60;
    return "if the ball may spin that fast, film at " + std::to_string(static_cast<int>(std::ceil(fps_needed))) +
           " frames per second or more (under 60 degrees per frame), or put a mark on the ball";
  };
  char buf[600];
  for (const auto& [flight, name] : {std::pair{&r.pre, "before"}, std::pair{&r.post, "after"}}) {
    if (deg_per_frame(flight->omega) <= kAmbiguousTurnDeg) continue;
    std::snprintf(buf, sizeof buf,
                  "the ball turns %.0f degrees per frame %s the impact (omega %.1f rad/s at %.0f frames per second): a "
                  "ball seen as an ellipse looks the same after half a turn, so its tips' tracks fit a spin of %.1f rad/s "
                  "(%.0f degrees per frame the other way) as well, and the smaller turn was taken; ",
                  deg_per_frame(flight->omega), name, flight->omega, fps, other(flight->omega),
                  deg_per_frame(other(flight->omega)));
    r.warnings.push_back(buf + remedy(flight->omega, other(flight->omega)));
  }
  const double change = r.post.omega - r.pre.omega;
  if (deg_per_frame(change) > kAmbiguousTurnDeg) {
    std::snprintf(buf, sizeof buf,
                  "the spin changes at the impact by %.0f degrees per frame (from %.1f to %.1f rad/s at %.0f frames per "
                  "second): a ball seen as an ellipse looks the same after half a turn, and across the bounce each "
                  "frame's turn is taken nearest the one before, so a spin after the impact of %.1f rad/s fits its "
                  "tips' tracks as well; ",
                  deg_per_frame(change), r.pre.omega, r.post.omega, fps, r.pre.omega + other(change));
    r.warnings.push_back(buf + remedy(r.post.omega, r.pre.omega + other(change)));
  }
}

}  // namespace

BounceAnalysis analyze_bounce(const track::Track& tip_a, const track::Track& tip_b,
                              const BounceAnalyzeOptions& options) {
  if (auto e = options.validate(); !e.empty()) throw input_error_of(e);
  BounceAnalysis r;
  require_common_frames(tip_a, tip_b);
  // Wild frames the impact detector would take for impacts (a hand in the picture) are left
  // out first and named below (docs/theory.md#plausibility-checks).
  // An isolated value far off its neighbours' motion on either tip (a lost decimal point) is
  // left out of both tips first ("isolated outliers").
  std::vector<std::string> outlier_warnings;
  std::vector<int> outlier_frames;
  for (const track::Track* tip : {&tip_a, &tip_b}) {
    for (const track::Outlier& x : track::isolated_outliers(*tip)) {
      outlier_warnings.push_back(track::outlier_warning(*tip, x));
      outlier_frames.push_back(tip->points[x.index].frame);
    }
  }
  auto drop_frames = [&](const track::Track& t) {
    track::Track kept{t.name, {}};
    for (const auto& p : t.points)
      if (std::find(outlier_frames.begin(), outlier_frames.end(), p.frame) == outlier_frames.end()) kept.points.push_back(p);
    return kept;
  };
  track::Track a = drop_frames(tip_a), b = drop_frames(tip_b);
  const Glitches glitches = drop_glitches(a, b, options.impacts);
  r.body = track::rigid_body_from_points(a, b);
  r.centre = track::centre_track(r.body);
  std::optional<track::Impact> found;
  try {
    found = choose_impact(a, b, options, r);
  } catch (const InputError& e) {
    // A wrong time scale hides the impact from the detector: say what the flights show.
    const auto [g, sigma_g] = rough_gravity(r.centre);
    const std::string w = std::isfinite(g) ? gravity_warning(g, sigma_g) : std::string();
    if (w.empty() || std::abs(g / kDefaultG - 1) <= 0.25) throw;
    throw InputError(marked_message(e) + "; " + w);
  }
  const track::Impact& imp = *found;
  const auto& rows = r.body.rows;
  // Noise of the centre: the track's robust estimate, floored (exact synthetic data).
  const double nx = std::max(r.impacts.noise_x, 1e-6), ny = std::max(r.impacts.noise_y, 1e-6);
  trim_contact_frames(rows, r.pre, true, nx, ny, kMinPoints);
  use_pre_gravity_if_post_too_short(rows, imp.t, r);
  trim_contact_frames(rows, r.post, false, nx, ny, kMinPoints);
  r.pre.n_points = static_cast<int>(r.pre.end - r.pre.begin);
  r.post.n_points = static_cast<int>(r.post.end - r.post.begin);
  const double frame_dt = median_frame_period(rows);
  // Contact frames that pass the trim test (small force early and late in the contact) bias
  // the flights just where the touch and the separation are read. Once located, every kept
  // frame after the touch (pre) or before the separation (post) is in contact by definition:
  // drop them and fit again, until none is left (docs/theory.md#bounce-analysis).
  const std::size_t pre_trimmed_end = r.pre.end, post_trimmed_begin = r.post.begin;
  for (int pass = 0;; ++pass) {
    fit_flights_once(rows, imp, options, frame_dt, r);
    if (!drop_frames_inside_contact(rows, r) || pass == 5) break;
  }
  require_plausible_floor(rows, options.ball, pre_trimmed_end, post_trimmed_begin, r);
  if (r.post.given_c2) {
    char buf[300];
    std::snprintf(buf, sizeof buf,
                  "the post-impact flight (%d frames, %.1f ms) is too short to measure gravity: its y parabola takes the "
                  "pre-impact flight's acceleration (%.3f m/s^2), so e_velocity rests on that flight's gravity",
                  r.post.n_points, 1e3 * (rows[r.post.end - 1].t - rows[r.post.begin].t), r.post.acceleration_y);
    r.warnings.push_back(buf);
  }
  check_gravity(rows, r);
  check_spin_aliasing(frame_dt, r);
  check_bounce_plausibility(options.ball, r);  // docs/theory.md#plausibility-checks
  if (!glitches.times.empty()) {
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "%zu frame(s) between t = %.4g and %.4g s lie far from the flight (up to %.1f mm) while the frames on "
                  "both sides follow one flight: something else was tracked there (a hand, a shadow) or the tracker "
                  "jumped; they were left out of the analysis. Check those frames in the video",
                  glitches.times.size(), glitches.times.front(), glitches.times.back(), 1e3 * glitches.worst);
    r.warnings.insert(r.warnings.begin(), buf);
  }
  r.warnings.insert(r.warnings.begin(), outlier_warnings.begin(), outlier_warnings.end());
  return r;
}

}  // namespace tribolab::analysis
