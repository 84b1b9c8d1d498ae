// docs/theory.md#bounce-analysis (touch, separation, e, collision angle, uncertainty model).
#include "analysis/bounce_touch.hpp"

#include "numerics/error.hpp"
#include "numerics/roots.hpp"
#include "numerics/units.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

namespace tribolab::analysis::detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Parameters of the propagation: the flights' fits and the floor's (or T's) own error.
enum Param : int {
  kPreY = 0,    // 3: pre-impact y parabola in s = t - impact_time
  kPreX = 3,    // 2: pre-impact x line
  kPreSpin = 5, // 2: theta_ref, omega of the pre-impact spin line
  kPostY = 7, kPostX = 10, kPostSpin = 12,
  kFloor = 14,  // shift of the floor (given or bracket) or of T (floor from the duration)
  kForceT = 15, // shift of the given contact duration dividing the impulse
  kParams = 16
};
enum Out : int {
  oFloor, oTouch, oSep, oTheta, oAngle, oVyIn, oVyOut, oE, oT, oCpx, oCpy, oCps, oForce, oECommon, kOuts
};
using Vec = Eigen::Matrix<double, kParams, 1>;
using OutVec = Eigen::Matrix<double, kOuts, 1>;

/// Spin-line covariance: theta_ref (at the mean time) and omega are uncorrelated;
/// var(theta_ref) = s^2 / n with s^2 = rss / (n - 2) = rms^2 n / (n - 2).
void spin_block(const track::SpinFit& f, Eigen::Matrix<double, kParams, kParams>& C, int at) {
  const int n = f.points;
  C(at, at) = n > 2 ? f.rms_residual * f.rms_residual / (n - 2) : kNaN;
  C(at + 1, at + 1) = f.sigma_omega * f.sigma_omega;
}

}  // namespace

void locate_touch(const BounceAnalyzeOptions& options, double frame_dt, double t1, double t4,
                  BounceAnalysis& r) {
  const bounce::Ball& ball = options.ball;
  const auto& rows = r.body.rows;
  const double t_imp = r.impact_time;
  // Time of the segment's frame where h is largest.
  auto highest = [&](const auto& h, const SegmentFit& seg) {
    double best = rows[seg.begin].t;
    for (std::size_t i = seg.begin; i < seg.end; ++i)
      if (h(rows[i].t) > h(best)) best = rows[i].t;
    return best;
  };
  const double gap = rows[r.post.begin].t - rows[r.pre.end - 1].t;  // frames spanning the contact
  const int direction = r.pre.vx >= 0 ? 1 : -1;
  const FloorMethod method = r.floor_method;
  const double T_given = options.contact_duration.value_or(kNaN);
  const double step = frame_dt / 4;

  Vec P0;
  P0.segment<3>(kPreY) = Eigen::Map<const Eigen::Vector3d>(r.pre.y_parabola.coef.data());
  P0.segment<2>(kPreX) = Eigen::Map<const Eigen::Vector2d>(r.pre.x_line.coef.data());
  P0.segment<2>(kPreSpin) << r.pre.spin.theta_ref, r.pre.spin.omega;
  P0.segment<3>(kPostY) = Eigen::Map<const Eigen::Vector3d>(r.post.y_parabola.coef.data());
  P0.segment<2>(kPostX) = Eigen::Map<const Eigen::Vector2d>(r.post.x_line.coef.data());
  P0.segment<2>(kPostSpin) << r.post.spin.theta_ref, r.post.spin.omega;
  P0(kFloor) = P0(kForceT) = 0;

  // All outputs as functions of the parameters; NaN where a root is not found.
  auto evaluate = [&](const Vec& P) {
    OutVec o = OutVec::Constant(kNaN);
    auto y = [&](int at, double t) { const double s = t - t_imp; return P(at) + s * (P(at + 1) + s * P(at + 2)); };
    auto vy = [&](int at, double t) { return P(at + 1) + 2 * (t - t_imp) * P(at + 2); };
    auto theta_pre = [&](double t) { return P(kPreSpin) + P(kPreSpin + 1) * (t - r.pre.spin.t_ref); };
    auto theta_post = [&](double t) { return P(kPostSpin) + P(kPostSpin + 1) * (t - r.post.spin.t_ref); };
    // Height of the lowest point of the ball on each flight (docs/theory.md#bounce-geometry).
    auto h_pre = [&](double t) { return y(kPreY, t) - bounce::support_depth(ball, theta_pre(t)); };
    auto h_post = [&](double t) { return y(kPostY, t) - bounce::support_depth(ball, theta_post(t)); };
    double floor = kNaN, t_touch = kNaN, t_sep = kNaN;
    if (method == FloorMethod::contact_duration) {
      // Touch t_c and separation t_c + T both on the floor (see analyze_bounce).
      const double T = T_given + P(kFloor);
      const auto root = numerics::find_root([&](double t) { return h_pre(t) - h_post(t + T); }, t_imp - T, t_imp);
      if (root.converged) {
        t_touch = root.x;
        t_sep = root.x + T;
        floor = h_pre(root.x);
      }
    } else {
      if (method == FloorMethod::given) {
        floor = *options.floor_y + P(kFloor);
      } else {  // bracket: its middle (analyze_bounce), moving with the fits
        const double lo = std::max(h_pre(t_imp), h_post(t_imp)), hi = std::min(h_pre(t1), h_post(t4));
        floor = 0.5 * (lo + hi) + P(kFloor);
      }
      // First touch: the first t, scanning forward from the pre-impact frame where the lowest
      // point is highest (surely in flight; the video may start or end near another contact),
      // where the lowest point reaches the floor.
      auto f_pre = [&](double t) { return h_pre(t) - floor; };
      const double t_pre_high = highest(h_pre, r.pre);
      if (f_pre(t_pre_high) > 0) {
        const double t_stop = t_imp + gap + 0.05;
        for (double a = t_pre_high; a < t_stop; a += step) {
          if (f_pre(a + step) <= 0) {
            t_touch = numerics::find_root(f_pre, a, a + step).x;
            break;
          }
        }
      }
      // Separation: the last t where the gap is 0, scanning back from the post-impact frame
      // where the lowest point is highest.
      auto f_post = [&](double t) { return h_post(t) - floor; };
      const double t_post_high = highest(h_post, r.post);
      if (f_post(t_post_high) > 0) {
        const double t_stop = t_imp - gap - 0.05;
        for (double b = t_post_high; b > t_stop; b -= step) {
          if (f_post(b - step) <= 0) {
            t_sep = numerics::find_root(f_post, b - step, b).x;
            break;
          }
        }
      }
    }
    o(oFloor) = floor;
    o(oTouch) = t_touch;
    o(oSep) = t_sep;
    o(oT) = t_sep - t_touch;
    const double th = theta_pre(t_touch);
    o(oTheta) = th;
    o(oAngle) = std::isfinite(th) ? bounce::collision_angle_deg(ball, th, direction) : kNaN;
    o(oVyIn) = vy(kPreY, t_touch);
    o(oVyOut) = vy(kPostY, t_sep);
    // e as bounce simulate defines it: -vy at separation / vy at first touch.
    o(oE) = -o(oVyOut) / o(oVyIn);
    o(oECommon) = -P(kPostY + 1) / P(kPreY + 1);
    if (std::isfinite(th)) {
      const auto cp = bounce::contact_point_velocity(ball, th, P(kPreX + 1), o(oVyIn), P(kPreSpin + 1));
      o(oCpx) = cp.vx;
      o(oCpy) = cp.vy;
      o(oCps) = std::hypot(cp.vx, cp.vy);
    }
    // Mean normal force: the impulse m (vy_post - vy_pre) at one instant (gravity cancels, so
    // it equals m (vy_out - vy_in) + m g T) over the contact duration.
    const double T_force = method != FloorMethod::contact_duration && std::isfinite(T_given) ? T_given + P(kForceT) : o(oT);
    o(oForce) = ball.mass * (P(kPostY + 1) - P(kPreY + 1)) / T_force;
    return o;
  };

  // Covariance of the parameters: independent blocks (tip noise makes the centre and the
  // orientation, sum and difference of the tips, uncorrelated).
  Eigen::Matrix<double, kParams, kParams> C = Eigen::Matrix<double, kParams, kParams>::Zero();
  C.block<3, 3>(kPreY, kPreY) = r.pre.y_parabola.covariance;
  C.block<2, 2>(kPreX, kPreX) = r.pre.x_line.covariance;
  spin_block(r.pre.spin, C, kPreSpin);
  C.block<3, 3>(kPostY, kPostY) = r.post.y_parabola.covariance;
  C.block<2, 2>(kPostX, kPostX) = r.post.x_line.covariance;
  spin_block(r.post.spin, C, kPostSpin);
  // A contact duration counted in frames: uniform error of half a frame, sd dt / sqrt 12.
  const double sd_T = frame_dt / std::sqrt(12.0);
  if (method == FloorMethod::given) C(kFloor, kFloor) = options.sigma_floor_y * options.sigma_floor_y;
  else if (method == FloorMethod::contact_duration) C(kFloor, kFloor) = sd_T * sd_T;
  else C(kFloor, kFloor) = r.floor_half_width * r.floor_half_width / 3;  // uniform on the bracket
  if (std::isfinite(T_given) && method != FloorMethod::contact_duration) C(kForceT, kForceT) = sd_T * sd_T;

  const OutVec o0 = evaluate(P0);
  if (!std::isfinite(o0(oTouch)) || !std::isfinite(o0(oSep))) {
    const bool pre = !std::isfinite(o0(oTouch));
    const SegmentFit& seg = pre ? r.pre : r.post;
    // Height of the flight's lowest point at the impact time, to say where the floor should be.
    const double h_imp = seg.y_parabola.coef[0] -
                         bounce::support_depth(ball, seg.spin.theta_ref + seg.spin.omega * (t_imp - seg.spin.t_ref));
    const std::string where = std::string(pre ? "pre" : "post") + "-impact flight (its lowest point is at y = " +
                              std::to_string(h_imp).substr(0, 7) + " m at the impact time)";
    if (method == FloorMethod::given)
      throw InputError(field("floor_y"), "the floor at y = " + std::to_string(*options.floor_y).substr(0, 7) +
                                        " m does not meet the fitted " + where + "; check the floor's height and the track's origin");
    throw InputError("the first touch and separation could not be located on the fitted " + where + "; give " + field("floor_y"));
  }
  // Linear propagation, central differences with steps of 1e-3 standard deviations.
  Eigen::Matrix<double, kOuts, kParams> J = Eigen::Matrix<double, kOuts, kParams>::Zero();
  for (int k = 0; k < kParams; ++k) {
    const double sd = std::sqrt(C(k, k));
    if (!(sd > 0)) continue;
    const double h = 1e-3 * sd;
    Vec up = P0, dn = P0;
    up(k) += h;
    dn(k) -= h;
    J.col(k) = (evaluate(up) - evaluate(dn)) / (2 * h);
  }
  const Eigen::Matrix<double, kOuts, kOuts> V = J * C * J.transpose();
  auto sd = [&](int i) { return std::sqrt(V(i, i)); };

  r.t_touch = o0(oTouch);
  r.sigma_t_touch = sd(oTouch);
  r.t_separation = o0(oSep);
  r.sigma_t_separation = sd(oSep);
  r.contact_duration = o0(oT);
  r.sigma_contact_duration = sd(oT);
  r.theta_touch_deg = to_deg(bounce::wrap_angle(o0(oTheta)));
  r.sigma_theta_touch_deg = to_deg(sd(oTheta));
  r.collision_angle_impact_deg = r.collision_angle_deg;  // analyze_bounce set it at impact_time
  r.collision_angle_deg = o0(oAngle);
  r.sigma_collision_angle_deg = sd(oAngle);
  r.vy_touch = o0(oVyIn);
  r.sigma_vy_touch = sd(oVyIn);
  r.vy_separation = o0(oVyOut);
  r.sigma_vy_separation = sd(oVyOut);
  r.e_velocity = o0(oE);
  r.sigma_e_velocity = sd(oE);
  r.e_velocity_common = o0(oECommon);
  r.sigma_e_velocity_common = sd(oECommon);
  r.contact_point_vx = o0(oCpx);
  r.contact_point_vy = o0(oCpy);
  r.contact_point_speed = o0(oCps);
  r.sigma_contact_point_vx = sd(oCpx);
  r.sigma_contact_point_vy = sd(oCpy);
  r.sigma_contact_point_speed = sd(oCps);
  // Energies at the instants simulate uses: first touch and separation.
  r.pre.energy.translational_y = 0.5 * ball.mass * r.vy_touch * r.vy_touch;
  r.post.energy.translational_y = 0.5 * ball.mass * r.vy_separation * r.vy_separation;
  if (method == FloorMethod::bracket) {
    // Without floor_y or contact_duration the floor is only bracketed, and at high frame
    // rates the bracket is wrong (late contact frames pass as flight): over 200 synthetic
    // runs at 240 fps the intervals from it held simulate's angle in 68 and e in 89 (e biased
    // +0.012). No honest uncertainty can be stated: the sigmas are null and no mean force.
    for (double* v : {&r.sigma_t_touch, &r.sigma_t_separation, &r.sigma_contact_duration, &r.sigma_theta_touch_deg,
                      &r.sigma_collision_angle_deg, &r.sigma_vy_touch, &r.sigma_vy_separation, &r.sigma_e_velocity,
                      &r.sigma_contact_point_vx, &r.sigma_contact_point_vy, &r.sigma_contact_point_speed})
      *v = kNaN;
    // How much e rests on the floor assumed: e at the bracket's two ends (the floor's middle
    // +- its half-width), said in the warning (a user without floor_y otherwise trusts e).
    Vec low = P0, high = P0;
    low(kFloor) = -r.floor_half_width;
    high(kFloor) = r.floor_half_width;
    const double e_low = evaluate(low)(oE), e_high = evaluate(high)(oE);
    char range[160] = "";
    if (std::isfinite(e_low) && std::isfinite(e_high))
      std::snprintf(range, sizeof range, "; over that bracket e_velocity = %.4f runs from %.4f to %.4f", r.e_velocity,
                    std::min(e_low, e_high), std::max(e_low, e_high));
    // The study's convention, y = 0 on the floor, when it lies near the flights (10 cm): e there.
    char at_zero[200] = "";
    if (std::abs(r.floor_y) < 0.1) {
      Vec zero = P0;
      zero(kFloor) = -r.floor_y;
      const double e_zero = evaluate(zero)(oE);
      if (std::isfinite(e_zero))
        std::snprintf(at_zero, sizeof at_zero, " (with the floor at y = 0, as the study sets it, e_velocity = %.4f)", e_zero);
    }
    char bracket[160];
    std::snprintf(bracket, sizeof bracket, "between y = %.4f and %.4f m", r.floor_y - r.floor_half_width,
                  r.floor_y + r.floor_half_width);
    r.warnings.push_back("floor not known (neither " + field("floor_y") + " nor " + field("contact_duration") + " given): touch and separation "
                                     "located on a floor only bracketed " + bracket + " by the fitted flights" + range +
                         at_zero +
                         "; the bracket itself can miss the floor at high frame rates (contact frames that pass as "
                         "flight), so e may lie outside that range, and the uncertainties of the touch quantities "
                         "(collision angle, e_velocity) are not stated. Give " + field("floor_y") + " (the floor's height in the file's "
                         "frame, m; 0 when y = 0 was set on the floor) for e with its uncertainty");
    return;
  }
  r.force_duration_method = std::isfinite(T_given) ? ForceDurationMethod::given : ForceDurationMethod::located;
  r.mean_normal_force = o0(oForce);
  r.sigma_mean_normal_force = sd(oForce);
}

}  // namespace tribolab::analysis::detail
