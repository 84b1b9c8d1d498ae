// Plain-language explanations shown as the footer of the analysis commands' help: what the
// models are and what each reported diagnostic means (docs/theory.md#incline-analysis,
// #bounce-analysis, #bounce-fit). The wrap pass (help_wrap.hpp) breaks them at 80 columns;
// each line here is one paragraph.
#pragma once

namespace tribolab::cli::help {

/// Models A and B of the incline study, for every command that fits or simulates them.
inline constexpr const char* kInclineModels =
    "Model B: Coulomb friction with one coefficient mu through the whole slide: a force of "
    "fixed size mu m g cos(phi) that always points straight against the velocity (the "
    "incline study's closed form, equations 1-9 (一-九)).\n"
    "Model A: model B plus a sideways friction force of constant size (normal_accel = f_N/m, "
    "m/s^2) at right angles to the velocity, positive to its left; with f_N = 0 it is model B. "
    "The incline study asked whether such a normal component exists, and found none.\n";

inline constexpr const char* kInclineAnalyze =
    "\nBoth models are fitted to every tracked point, with the launch point, time and speed and "
    "the camera's tilt against the incline (frame_rotation_deg).\n"
    "verdict: \"present\" when model A fits significantly better than model B: the 95 % "
    "interval of f_N/m excludes 0 and the F-test's p-value is below 0.05; \"absent\" means no "
    "sideways friction was detected, not that it is proven to be zero.\n"
    "p_value: the chance that a run without sideways friction fits model A at least this much "
    "better than model B; a small p-value is evidence for sideways friction.\n"
    "test_size (5 %): how often the test errs: about one run in twenty without sideways "
    "friction is called \"present\".\n"
    "a_N against sin(theta), equation b: the acceleration toward the centre of the path's "
    "bend against the direction of motion. Without sideways friction it is a line through 0 "
    "with slope g sin(phi); an intercept away from 0 is sideways friction. A weaker test, shown "
    "beside the verdict; it decides only with --no-model-a (verdict_source says which).\n"
    "theta_c, equation c: the direction of motion (from straight down the slope) where the "
    "disc moves down the slope fastest; model B predicts cos(theta_c) = tan(phi)/mu.\n"
    "rms_residual: the typical distance between the tracked points and the fitted path, m.\n"
    "\nSeveral files: mu is the weighted mean over the runs; chi2/dof near 1 means the runs "
    "agree within their uncertainties, well above 1 that they scatter more (the mean's sigma "
    "is then scaled by sqrt(chi2/dof)); the stop-point slopes test t_stop ~ v0 and x_stop, "
    "y_stop ~ v0^2 (equations 7-9 (七-九)).";

inline constexpr const char* kInclineMuFromStop =
    "Model B (Coulomb friction with one mu, always against the velocity) makes the ratio "
    "r = |x_stop/y_stop| of the stop point depend on k = tan(phi)/mu alone: "
    "r k^3 - 8 k^2 - 4 r k + 8 = 0 (the incline study's equation 10A (十A)). So mu = tan(phi)/k "
    "needs only the angle and where the disc stopped, not the launch speed, which is then "
    "implied (v0, equation 8 (八)).\n"
    "sigma_mu: the standard uncertainty of mu from --sigma-phi-deg and --sigma-pos.\n"
    "--plate-size: advice on the angle that gives the most precise mu on a plate that size.";

inline constexpr const char* kInclineMuFromSlide =
    "A disc released from rest slides straight down the fall line with constant acceleration "
    "a = g sin(phi) - mu g cos(phi) (the incline study's equation a), so "
    "mu = tan(phi) - a/(g cos(phi)). a is fitted as a parabola to the distance travelled.\n"
    "r_squared: how well the parabola fits (1 = perfectly).\n"
    "straightness_rms: how far the points stray from a straight path, m (a large value: the "
    "disc turned, or the axes are not along the slope).\n"
    "a_velocity_line: the acceleration from a line through the speeds, as the study did by "
    "hand; a cross-check whose sigma is understated.\n"
    "\nSeveral files: mu is the weighted mean; chi2/dof near 1 means the runs agree within their "
    "uncertainties.";

inline constexpr const char* kInclineNormalFrictionTest =
    "\nEquation c of the incline study: where the disc moves down the slope fastest, its "
    "direction of motion theta_c (from straight down the slope) obeys "
    "cos(theta_c) = tan(phi)/mu when there is no sideways friction (model B). Over runs at "
    "several angles, cos(theta_c) against tan(phi) is then a line through 0 with slope 1/mu.\n"
    "verdict: \"present\" when the 95 % interval of the line's intercept excludes 0 (sideways "
    "friction shifts the line), \"absent\" otherwise; at this 5 % size about one test in "
    "twenty without sideways friction says \"present\".\n"
    "mu, sigma_mu: 1/slope and its standard uncertainty.";

inline constexpr const char* kBounceAnalyze =
    "From the two tracked tips: the centre's flight before and after the bounce (x a line, "
    "y a parabola in time) and the spin omega (the tips' angle a line in time).\n"
    "collision_angle_deg: at the first touch, the angle at the centre between the ray to the "
    "point touching the floor and the ray to the rear tip (the tip behind the centre in the "
    "direction of motion; the rugby-ball study's figure 30): 90 = long axis level, near 0 = "
    "rear tip down, near 180 = front tip down.\n"
    "e_velocity: the coefficient of restitution, minus the centre's vertical velocity at the "
    "separation over the one at the first touch; e > 1 means the ball rebounds faster than it "
    "fell (spin turned into height). e_height: sqrt(H'/H) from the heights of the flights' "
    "tops, which needs a known floor.\n"
    "energy_pre, energy_post: kinetic energy (moving and spinning) at the touch and at the "
    "separation.\n"
    "mean_normal_force: the floor's impulse divided by the contact duration; "
    "force_duration_method says which duration: \"given\" (--contact-duration, counted in "
    "frames) or \"located\" (from the fitted touch to the fitted separation).\n"
    "floor_method: how the floor was found: \"given\" (--floor-y), \"contact_duration\" (the "
    "two flights touch it T apart) or \"bracket\" (neither: only bounded, so e_height, the "
    "touch uncertainties and the force are left out).\n"
    "gravity, gravity_tilt_deg: g as the flights see it; far from 9.8 m/s^2 means a wrong "
    "frame rate or scale, a tilt means the camera is not level (warned).\n"
    "\nSeveral files: e is averaged per band of collision angle; chi2/dof and p_value say "
    "whether the throws share one e; above_one counts throws with e significantly above 1.";

inline constexpr const char* kBounceFit =
    "Each bounce of the table is simulated from its incoming state with the candidate contact "
    "law, and K, n, D (or e) and mu are adjusted until the predicted outgoing vx, vy and "
    "b*omega match the measured ones (all in m/s).\n"
    "Contact law (the default --model hunt-crossley, the law the rugby-ball study cites): the "
    "floor pushes with N = K d^n + D d^n d' (d the depth the ball presses in, d' its rate); K is the stiffness, n the "
    "exponent (1.5 for Hertz), D the damping that takes energy out, mu the friction "
    "coefficient at the contact point.\n"
    "sigma_*: standard uncertainties, robust to a few bad rows (the Huber loss); K and n are "
    "weakly determined by outgoing velocities alone, the ratio D/K well.\n"
    "rms: the typical mismatch between predicted and measured outgoing values, m/s.";

}  // namespace tribolab::cli::help
