// Analysis of one tracked bounce of the rugby ball (seed 001, experiment 1): the two tips
// A and B give the centre (midpoint) and the orientation; the impact is found on the centre
// track; each flight segment gets an x–t line, a y–t parabola (with R^2) and a linear
// theta–t spin fit; velocities are the fits' derivatives at the impact time; first touch and
// separation located where each flight's lowest point meets the floor; restitution from the
// velocities at touch and separation (as bounce simulate) and from apex heights; energies;
// orientation, collision angle and contact-point velocity at the touch; the mean normal
// force over the contact duration, with uncertainties propagated from the fits and the floor.
// See docs/theory.md#bounce-analysis.
#pragma once

#include "bounce/contact.hpp"
#include "bounce/geometry.hpp"
#include "numerics/polyfit.hpp"
#include "track/impacts.hpp"
#include "track/rigid_body.hpp"
#include "track/track.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace tribolab::analysis {

struct BounceAnalyzeOptions {
  bounce::Ball ball;                    ///< for energies, support depth, collision angle
  /// Points always dropped on each side of the impact split, e.g. 0; frames in contact are
  /// also dropped automatically (see trim in docs/theory.md#bounce-analysis).
  int exclude = 0;
  std::optional<double> floor_y;        ///< floor height, m; default: from the flights (see theory)
  double sigma_floor_y = 0;             ///< standard uncertainty of a given floor_y, m (e.g. 0.001)
  /// s, counted in frames (uncertain by half a frame): divides the impulse for the mean
  /// normal force, and locates the floor without floor_y; default: the located contact.
  std::optional<double> contact_duration;
  int impact = 1;                       ///< which detected impact to analyse (1 = first)
  track::ImpactOptions impacts;         ///< impact detection on the centre track
  int grid_points = 101;                ///< samples of each fitted curve for figures (>= 2)
  std::string validate() const;         ///< empty when valid; names the field
};

/// One flight segment (before or after the impact), fitted in the time variable
/// s = t - impact_time, so the fits' linear coefficients are the velocities at the impact.
struct SegmentFit {
  std::size_t begin = 0, end = 0;  ///< fitted rows [begin, end) of BounceAnalysis::body.rows
  int n_points = 0;                ///< end - begin
  numerics::PolyFit x_line;        ///< x = c0 + c1 s (m, m/s)
  numerics::PolyFit y_parabola;    ///< y = c0 + c1 s + c2 s^2 (m, m/s, m/s^2)
  /// The post-impact parabola's curvature taken from the pre-impact flight when the
  /// post-impact flight is too short to measure gravity (docs/theory.md#bounce-analysis,
  /// "short post-impact flight"); empty: c2 fitted.
  struct GivenCurvature {
    double c2 = 0;       ///< m/s^2, about -4.9 (the pre-impact fit's)
    double var_c2 = 0;   ///< its variance, (m/s^2)^2
    double noise_y = 0;  ///< m: the centre track's y noise (robust, every frame), ~1-4 mm
  };
  std::optional<GivenCurvature> given_c2;
  track::SpinFit spin;             ///< theta = theta_ref + omega (t - t_ref)
  double vx = 0, sigma_vx = 0;     ///< at the impact time, m/s
  double vy = 0, sigma_vy = 0;     ///< at the impact time, m/s
  double omega = 0, sigma_omega = 0;  ///< rad/s (constant in flight)
  double acceleration_y = 0, sigma_acceleration_y = 0;  ///< 2 c2, m/s^2 (about -g)
  double apex_time = 0;            ///< time of the parabola's vertex, s
  double apex_y = 0;               ///< centre height there, m (above the file's origin)
  double apex_height = 0;          ///< apex_y - floor_y, m
  double sigma_apex_height = 0;    ///< m (fit covariance, floor included)
  bounce::KineticEnergy energy;    ///< J, from vx, omega and vy at t_touch (pre) / t_separation (post)
  /// Fitted curves sampled on a grid over the segment's time span, for figures.
  std::vector<double> grid_t, grid_x, grid_y, grid_theta;
};

/// How BounceAnalysis found the floor (docs/theory.md#bounce-analysis).
enum class FloorMethod {
  given,             ///< the floor_y option
  contact_duration,  ///< both flights meet the floor contact_duration apart (recommended without floor_y)
  bracket,           ///< neither given: unreliable at high frame rates
};
/// "given", "contact_duration" or "bracket": the value of the JSON key "floor_method".
const char* to_string(FloorMethod m);

/// The contact duration dividing the impulse for BounceAnalysis::mean_normal_force.
enum class ForceDurationMethod {
  located,  ///< t_separation - t_touch
  given,    ///< the contact_duration option, uncertain by a uniform half frame
};
/// "located" or "given": the value of the JSON key "force_duration_method".
const char* to_string(ForceDurationMethod m);

struct BounceAnalysis {
  track::RigidBody body;             ///< tips -> centre, orientation, local spin per frame
  track::Track centre;               ///< the centre track ("A+B")
  track::ImpactResult impacts;       ///< every impact found on the centre track
  std::size_t impact_used = 0;       ///< index into impacts.impacts
  double impact_time = 0;            ///< s: where the two fitted y parabolas meet
  SegmentFit pre, post;
  /// -vy_separation / vy_touch: simulate's e (velocities at first touch and at separation)
  double e_velocity = 0, sigma_e_velocity = 0;
  double e_height = 0, sigma_e_height = 0;      ///< sqrt(H'/H); NaN when floor_method is "bracket"
  double floor_y = 0;                ///< m (given, or y_centre(impact) - Y(theta_impact))
  bool floor_given = false;
  double floor_half_width = 0;       ///< m: half-width of the floor's bracket (0 unless "bracket")
  /// How the floor was found: "given" (floor_y option), "contact_duration" (both flights meet
  /// the floor contact_duration apart; recommended without floor_y) or "bracket" (neither
  /// given: unreliable at high frame rates, see docs/theory.md#bounce-analysis).
  FloorMethod floor_method = FloorMethod::given;
  double theta_impact_deg = 0;       ///< pre-impact spin fit at impact_time, wrapped to (-180, 180]
  double collision_angle_deg = 0;    ///< bounce::collision_angle_deg at first touch (t_touch)
  std::optional<double> mean_normal_force, sigma_mean_normal_force;  ///< N

  // First touch and separation, located on the fitted flights and the ball's geometry: the
  // lowest point h(t) = y(t) - Y(theta(t)) meets the floor (docs/theory.md#bounce-analysis).
  // Sigmas propagate the fit covariances and the floor's (or the contact duration's) error.
  double t_touch = 0, sigma_t_touch = 0;            ///< first touch (pre-impact flight), s
  double t_separation = 0, sigma_t_separation = 0;  ///< separation (post-impact flight), s
  /// t_separation - t_touch, s (with floor_method "contact_duration": the given value)
  double contact_duration = 0, sigma_contact_duration = 0;
  double theta_touch_deg = 0, sigma_theta_touch_deg = 0;  ///< orientation at t_touch, deg
  double sigma_collision_angle_deg = 0;  ///< of collision_angle_deg (now at t_touch), deg
  double collision_angle_impact_deg = 0; ///< collision angle at impact_time (the old instant), deg
  double vy_touch = 0, sigma_vy_touch = 0;            ///< centre vy at t_touch (pre fit), m/s
  double vy_separation = 0, sigma_vy_separation = 0;  ///< centre vy at t_separation (post fit), m/s
  /// -pre.vy / post.vy at impact_time (both flights at one instant: the old e_velocity)
  double e_velocity_common = 0, sigma_e_velocity_common = 0;
  /// Velocity of the material point at the support point at t_touch: centre velocity +
  /// omega x r_contact (bounce::contact_point_velocity), m/s; speed = its magnitude.
  double contact_point_vx = 0, contact_point_vy = 0, contact_point_speed = 0;
  double sigma_contact_point_vx = 0, sigma_contact_point_vy = 0, sigma_contact_point_speed = 0;
  /// Contact duration dividing the impulse for mean_normal_force (set with it).
  ForceDurationMethod force_duration_method = ForceDurationMethod::located;
  /// Gravity seen by the flights: magnitude and tilt from the file's -y axis (positive: g
  /// has a +x component), from y parabolas and x parabolas of both flights (weighted). A
  /// wrong frame rate scales the magnitude (by the square of the rate's error); a turned
  /// camera tilts it.
  double gravity = 0, sigma_gravity = 0;            ///< m/s^2
  double gravity_tilt_deg = 0, sigma_gravity_tilt_deg = 0;  ///< deg
  /// Plain-language warnings (floor unknown, gravity not 9.8 m/s^2 or tilted), empty if none.
  std::vector<std::string> warnings;
};

/// Analyses tracks `a` and `b` (the two tips). Throws InputError when the tracks share too
/// few frames, no impact is found, or a segment has too few points for its fits.
BounceAnalysis analyze_bounce(const track::Track& a, const track::Track& b,
                              const BounceAnalyzeOptions& options = {});

}  // namespace tribolab::analysis
