// mu from a straight slide down the incline (seed 000, 肆-一-(二), eq a):
//   mu = (g sin(phi) - a) / (g cos(phi)),
// with a the acceleration along the fall line. The disc slides straight, so positions are
// projected on the fitted straight path (principal axis of the points; this works whether or
// not the camera frame is aligned with the fall line) and the distance along it s(t) is
// fitted with a parabola s = c0 + c1 t + c2 t^2 (a = 2 c2; the seed's y–t parabola), over the
// moving points only (rest before the release is excluded). The seed's v–t line (slope of
// Tracker's central-difference speeds) is reported as a cross-check; its sigma understates
// the uncertainty because neighbouring speeds share points. See docs/theory.md#mu-from-a-slide.
#pragma once

#include "numerics/polyfit.hpp"
#include "track/track.hpp"
#include "numerics/units.hpp"

#include <optional>
#include <string>
#include <vector>

namespace tribolab::analysis {

struct SlideOptions {
  std::optional<double> phi;  ///< incline angle, rad, in (0, pi/2); empty: report a only
  double sigma_phi = 0;       ///< standard uncertainty of phi, rad (0 = exact)
  double g = kDefaultG;       ///< m/s^2
  int min_points = 6;         ///< fewest moving points accepted for the parabola

  std::string validate() const;
};

struct SlideResult {
  double a = 0;            ///< acceleration along the path (down the slope), m/s^2, e.g. 1.76
  double sigma_a = 0;      ///< standard error of a, m/s^2
  std::optional<double> mu, sigma_mu;  ///< eq (a) and its propagated uncertainty (needs phi)
  double r_squared = 0;    ///< of the parabola s(t)
  int n_points = 0;        ///< moving points used
  double a_velocity_line = 0;        ///< slope of the v–t line (seed's method), m/s^2
  double sigma_a_velocity_line = 0;  ///< its naive standard error, m/s^2 (understated)
  double direction_deg = 0;  ///< direction of motion in the file's frame, deg (-90 = straight down y)
  double straightness_rms = 0;  ///< rms distance of the points from the straight path, m
  // For figures: the projected data and the fits.
  std::vector<double> t, s;     ///< moving points: time, s; distance along the path, m
  std::vector<double> v_t, v;   ///< Tracker central-difference speeds along the path, m/s
  numerics::PolyFit parabola;   ///< s(t)
  numerics::PolyFit velocity_line;  ///< v(t)
  /// Plain-language warnings: an acceleration no incline gives (a > g: times or lengths wrong),
  /// or more than the angle given allows without friction (mu < 0: the angle is wrong, e.g.
  /// radians typed as degrees). Empty when none.
  std::vector<std::string> warnings;
};

/// Fits one straight slide. Throws InputError when the data cannot support the fit: too few
/// points, no motion (the disc is stuck: mu_s >= tan(phi)), or no acceleration down the slope
/// (the disc decelerates: mu >= tan(phi), eq (a) needs a slide that speeds up).
SlideResult mu_from_slide(const track::Track& track, const SlideOptions& options);

}  // namespace tribolab::analysis
