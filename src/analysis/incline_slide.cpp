#include "analysis/incline_slide.hpp"

#include "numerics/error.hpp"
#include "numerics/message_number.hpp"
#include "track/outliers.hpp"
#include "numerics/units.hpp"
#include "numerics/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace tribolab::analysis {

std::string SlideOptions::validate() const {
  if (phi && !(std::isfinite(*phi) && *phi > 0 && *phi < M_PI / 2))
    return "phi must be in (0, 90) degrees";
  if (!(std::isfinite(sigma_phi) && sigma_phi >= 0)) return "sigma_phi must be >= 0";
  if (!(std::isfinite(g) && g > 0)) return "g must be > 0";
  if (min_points < 4) return "min_points must be >= 4";
  return {};
}

namespace {

/// The straight path through the points: its direction along the motion and each point's
/// distance along it (from the first point) and across it (from the centroid), m.
struct AlongPath {
  double dx = 0, dy = 0;
  std::vector<double> s, d;
};

/// The points along and across their straight path, oriented along the motion.
AlongPath along_path(const std::vector<track::TrackPoint>& pts) {
  const std::size_t n = pts.size();
  double mx = 0, my = 0;
  for (const auto& p : pts) mx += p.x, my += p.y;
  mx /= n;
  my /= n;
  double sxx = 0, syy = 0, sxy = 0;
  for (const auto& p : pts) {
    sxx += (p.x - mx) * (p.x - mx);
    syy += (p.y - my) * (p.y - my);
    sxy += (p.x - mx) * (p.y - my);
  }
  const double angle = 0.5 * std::atan2(2 * sxy, sxx - syy);
  AlongPath a;
  double& dx = a.dx;
  double& dy = a.dy;
  dx = std::cos(angle), dy = std::sin(angle);
  // Orient along the motion (from the first point toward the last).
  if ((pts.back().x - pts.front().x) * dx + (pts.back().y - pts.front().y) * dy < 0) dx = -dx, dy = -dy;
  a.s.resize(n), a.d.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    a.s[i] = (pts[i].x - pts.front().x) * dx + (pts[i].y - pts.front().y) * dy;
    a.d[i] = -(pts[i].x - mx) * dy + (pts[i].y - my) * dx;
  }
  return a;
}

/// The distance a point must move from the first to count as released; throws when the path shows no motion.
double release_threshold(const std::vector<double>& s, const SlideOptions& o, const std::string& where) {
  const std::size_t n = s.size();
  std::vector<double> dd;
  for (std::size_t i = 1; i + 1 < n; ++i) dd.push_back(std::abs(s[i + 1] - 2 * s[i] + s[i - 1]));
  const double noise = dd.empty() ? 0.0 : upper_median(dd) / 0.6745 / std::sqrt(6.0);
  const double range = *std::max_element(s.begin(), s.end()) - *std::min_element(s.begin(), s.end());
  const double threshold = std::max(5 * noise, 0.02 * range);
  const std::string stuck =
      o.phi ? "; the disc is stuck, so the static coefficient is >= tan(phi) = " + message_number(std::tan(*o.phi), 4)
            : "; the disc is stuck";
  if (!(range > 10 * noise) || range < 1e-4)
    throw InputError(where, "shows no motion along a path (range " + message_number(range, 4) + " m, noise " +
                                message_number(noise, 4) + " m)" + stuck);
  return threshold;
}

/// Throws unless the slide speeds up (a more than 2 sd above 0).
void check_accelerating(const SlideResult& r, const SlideOptions& o, const std::string& where) {
  if (!(r.a - 2 * r.sigma_a > 0)) {
    std::string msg = "is not accelerating along its path (a = " + message_number(r.a, 4) + " +- " + message_number(r.sigma_a, 4) +
                      " m/s^2): the disc decelerates or is stuck";
    if (o.phi) msg += ", so mu >= tan(phi) = " + message_number(std::tan(*o.phi), 4);
    throw InputError(where, msg + "; eq (a) needs a slide released from rest that speeds up");
  }
}

/// The speeds by central differences and the line through them (its slope a second a).
void add_velocity_line(SlideResult& r, const std::string& where) {
  for (std::size_t k = 1; k + 1 < r.t.size(); ++k) {
    r.v_t.push_back(r.t[k]);
    r.v.push_back((r.s[k + 1] - r.s[k - 1]) / (r.t[k + 1] - r.t[k - 1]));
  }
  if (r.v.size() >= 3) {
    r.velocity_line = numerics::fit_polynomial(r.v_t, r.v, 1, where + " speeds");
    r.a_velocity_line = r.velocity_line.coef[1];
    r.sigma_a_velocity_line = r.velocity_line.sigma[1];
  }
}

/// mu and its standard error from a and phi (seed 000, eq a).
void add_mu(SlideResult& r, const SlideOptions& o) {
  // seed 000, eq (a): mu = (g sin phi - a)/(g cos phi) = tan(phi) - a/(g cos phi).
  const double phi = *o.phi, c = std::cos(phi);
  r.mu = std::tan(phi) - r.a / (o.g * c);
  const double dmu_da = -1 / (o.g * c);
  const double dmu_dphi = 1 / (c * c) - r.a * std::sin(phi) / (o.g * c * c);
  r.sigma_mu = std::hypot(dmu_da * r.sigma_a, dmu_dphi * o.sigma_phi);
}

/// Warnings when a exceeds what any incline, or the given one, allows.
void add_plausibility_warnings(SlideResult& r, const SlideOptions& o) {
  const double a_low = r.a - 3 * r.sigma_a;
  if (a_low > o.g) {
    r.warnings.push_back("the disc slides at a = " + message_number(r.a, 4) + " +- " + message_number(r.sigma_a, 4) + " m/s^2, more than g = " +
                         message_number(o.g, 4) + " m/s^2, which no incline gives: the times or the lengths are wrong. If the lengths "
                         "are right, the file's times must be multiplied by at least " + message_number(std::sqrt(r.a / o.g), 4) +
                         " (slow motion analysed as real time gives 1/8 at 240 fps played at 30)");
  } else if (o.phi && a_low > o.g * std::sin(*o.phi)) {
    const double given_deg = to_deg(*o.phi), least_deg = to_deg(std::asin(std::min(1.0, r.a / o.g)));
    std::string w = "the disc slides at a = " + message_number(r.a, 4) + " +- " + message_number(r.sigma_a, 4) + " m/s^2, more than g sin(phi) = " +
                    message_number(o.g * std::sin(*o.phi), 4) + " m/s^2 that an incline at phi_deg = " + message_number(given_deg, 4) +
                    " deg gives without friction (mu = " + message_number(*r.mu, 4) + " < 0): the incline is at least " +
                    message_number(least_deg, 4) + " deg";
    if (given_deg <= M_PI / 2 && to_deg(given_deg) >= least_deg)
      w += "; " + message_number(given_deg, 4) + " looks like the angle in radians (" + message_number(given_deg, 4) + " rad = " +
           message_number(to_deg(given_deg), 4) + " deg): give phi_deg in degrees";
    else
      w += "; check the angle (and the time scale)";
    r.warnings.push_back(w);
  }
}

}  // namespace

SlideResult mu_from_slide(const track::Track& tracked, const SlideOptions& o) {
  if (const std::string e = o.validate(); !e.empty()) throw InputError("mu-from-slide", e);
  // An isolated value far off its neighbours' motion is left out first and named
  // (docs/theory.md#plausibility-checks, "isolated outliers").
  const std::vector<track::Outlier> outliers = track::isolated_outliers(tracked);
  const track::Track track = track::without(tracked, outliers);
  const auto& pts = track.points;
  const std::string where = "track '" + track.name + "'";
  if (static_cast<int>(pts.size()) < o.min_points)
    throw InputError(where, "has " + std::to_string(pts.size()) + " points; a slide fit needs at least " +
                                std::to_string(o.min_points));
  const std::size_t n = pts.size();

  // Straight path: principal axis of the points (largest eigenvector of their covariance).
  const AlongPath path = along_path(pts);
  const std::vector<double>& s = path.s;

  // Noise from second differences of s (robust: median absolute value / 0.6745 / sqrt(6)).
  const double threshold = release_threshold(s, o, where);

  // Rest before the release: points still within `threshold` of the first are excluded (the
  // parabola holds only while the disc slides; one moving point lost is a small price).
  std::size_t first = 0;
  while (first < n && s[first] - s[0] < threshold) ++first;
  SlideResult r;
  for (const auto& x : outliers) r.warnings.push_back(track::outlier_warning(tracked, x));
  for (std::size_t i = first; i < n; ++i) {
    r.t.push_back(pts[i].t);
    r.s.push_back(s[i]);
  }
  r.n_points = static_cast<int>(r.t.size());
  if (r.n_points < o.min_points)
    throw InputError(where, "has " + std::to_string(r.n_points) +
                                " moving points; a slide fit needs at least " + std::to_string(o.min_points));
  r.parabola = numerics::fit_polynomial(r.t, r.s, 2, where + " distance along the path");
  r.a = 2 * r.parabola.coef[2];
  r.sigma_a = 2 * r.parabola.sigma[2];
  r.r_squared = r.parabola.r_squared;
  r.direction_deg = to_deg(std::atan2(path.dy, path.dx));
  double dsum = 0;
  for (double v : path.d) dsum += v * v;
  r.straightness_rms = std::sqrt(dsum / n);
  check_accelerating(r, o, where);
  // The seed's v–t line: central differences of consecutive frames (Tracker's stencil).
  add_velocity_line(r, where);
  if (o.phi) add_mu(r, o);
  // What the slide itself says (docs/theory.md#mu-from-a-slide): a <= g sin(phi) <= g on any
  // incline (friction only slows it), so a above g means wrong times or lengths, and a above
  // g sin(phi) an angle too small: the incline is at least asin(a / g). 3 sd of a.
  add_plausibility_warnings(r, o);
  return r;
}

}  // namespace tribolab::analysis
