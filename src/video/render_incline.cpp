// docs/theory.md#rendering.
#include "video/render_incline.hpp"

#include "incline/closed_form.hpp"
#include "incline/numeric.hpp"
#include "numerics/error.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace tribolab::video {
namespace {

/// The simulated path sampled densely (every frame time among the samples), evaluated at any
/// time since the launch by cubic Hermite interpolation of (x, vx) and (y, vy). Before the
/// launch the disc moves at the launch velocity (it was being pushed in).
struct InclineSampledPath {
  std::vector<double> t;
  std::vector<incline::State> s;
  double v0 = 0;
  cv::Point2d at(double tl) const {
    if (tl <= 0) return {v0 * tl, 0};
    auto it = std::upper_bound(t.begin(), t.end(), tl);
    if (it == t.end()) return {s.back().x, s.back().y};  // past the last sample: never asked (the samples cover the film)
    const std::size_t i = static_cast<std::size_t>(it - t.begin()) - 1;
    const double h = t[i + 1] - t[i], u = (tl - t[i]) / h;
    const double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u), h01 = u * u * (3 - 2 * u),
                 h11 = u * u * (u - 1);
    const auto& a = s[i];
    const auto& b = s[i + 1];
    return {h00 * a.x + h10 * h * a.vx + h01 * b.x + h11 * h * b.vx, h00 * a.y + h10 * h * a.vy + h01 * b.y + h11 * h * b.vy};
  }
};

}  // namespace

std::string InclineFilmOptions::validate() const {
  if (auto e = launch.validate(); !e.empty()) return e;
  if (launch.normal_accel != 0) return "normal_accel: the film is of model B (no normal friction)";
  if (auto e = render.validate(); !e.empty()) return e;
  if (!std::isfinite(disc_radius) || disc_radius <= 0 || disc_radius > 1) return "radius: must lie in (0, 1] m";
  if (!std::isfinite(scale_m_per_px) || scale_m_per_px < 0 || scale_m_per_px > 1) {
    return "scale: must lie in (0, 1] m per px, or 0 to fit the path in view";
  }
  if (!std::isfinite(duration) || duration < 0 || duration > 3600) return "duration: must lie in [0, 3600] s (0: until 0.3 s after the stop)";
  if (!std::isfinite(launch_phase) || launch_phase < 0 || launch_phase >= 1) return "launch_phase: must lie in [0, 1)";
  if (launch_px && (!std::isfinite(launch_px->x) || !std::isfinite(launch_px->y))) return "launch_px: must be finite";
  return {};
}

InclineFilm plan_incline_film(const InclineFilmOptions& o) {
  if (auto e = o.validate(); !e.empty()) throw input_error_of(e);  // naming the field (numerics/error.hpp)
  InclineFilm film;
  film.launch = o.launch;
  film.render = o.render;
  RenderOptions& r = film.render;
  const double dt = 1 / r.fps;
  const double phase = o.launch_phase * dt;  // time since the launch of frame 0
  film.t_launch = -phase;

  // How long: the closed form's stop (seed 000, eq 七) decides the default length.
  const incline::Prediction stop = incline::ClosedForm(o.launch).predict();
  double duration = o.duration;
  if (duration == 0) duration = stop.t_stop ? *stop.t_stop + 0.3 : 1.5;
  film.frames = static_cast<int>(std::ceil((duration - phase) * r.fps - 1e-9));
  if (film.frames > 100000) throw InputError(field("duration"), "the video would hold more than 100000 frames");
  if (film.frames < 1) throw InputError(field("duration"), "the video would hold no frame");

  // The path at every frame time and 32 times per frame in between, up to half an exposure past
  // the last frame: cubic Hermite between samples 1/(32 fps) apart is exact to ~h^4 |x''''| / 384,
  // far below a micrometre for any launch a camera films.
  const double t_last = (film.frames - 1) * dt + phase + 0.5 * r.shutter_fraction * dt + dt;
  auto path = std::make_shared<InclineSampledPath>();
  path->v0 = o.launch.v0;
  {
    const int fine = 32;
    const long n = static_cast<long>(std::ceil(t_last * r.fps * fine));
    std::vector<double>& t = path->t;
    t.reserve(static_cast<std::size_t>(n + film.frames + 1));
    for (long i = 0; i <= n; ++i) t.push_back(static_cast<double>(i) / (r.fps * fine));
    for (int k = 0; k < film.frames; ++k) t.push_back(k * dt + phase);
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(), t.end()), t.end());
    const incline::NumericResult run = incline::simulate(o.launch, t);
    if (run.samples.size() != t.size()) throw InputError("the simulation of the launch ended early: " + run.message);
    path->s = run.samples;
    if (run.t_stop) {
      film.t_stop = *run.t_stop - phase;
      film.x_stop = run.x_stop;
      film.y_stop = run.y_stop;
    } else if (stop.t_stop) {  // v0 = 0 on a slope that holds it: at rest from the start
      film.t_stop = *stop.t_stop - phase;
      film.x_stop = stop.x_stop;
      film.y_stop = stop.y_stop;
    }
  }

  // Layout: the whole path (centre range +- the radius) inside 90 % of the image, centred;
  // or the launch point where asked.
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  for (const auto& s : path->s) {
    xmin = std::min(xmin, s.x);
    xmax = std::max(xmax, s.x);
    ymin = std::min(ymin, s.y);
    ymax = std::max(ymax, s.y);
  }
  xmin = std::min(xmin, -o.launch.v0 * 0.5 * r.shutter_fraction * dt);  // the first exposure may start before the launch
  FilmView& v = film.view;
  v.scale_m_per_px = o.scale_m_per_px;
  if (v.scale_m_per_px == 0) {
    v.scale_m_per_px = std::max((xmax - xmin + 2 * o.disc_radius) / (0.9 * r.width),
                                (ymax - ymin + 2 * o.disc_radius) / (0.9 * r.height));
  }
  if (o.launch_px) {
    v.origin_x_px = o.launch_px->x;
    v.origin_y_px = o.launch_px->y;
  } else {
    v.origin_x_px = 0.5 * (r.width - 1) - 0.5 * (xmin + xmax) / v.scale_m_per_px;
    v.origin_y_px = 0.5 * (r.height - 1) + 0.5 * (ymin + ymax) / v.scale_m_per_px;
  }
  film.disc_radius_px = o.disc_radius / v.scale_m_per_px;
  if (film.disc_radius_px < 2) {
    throw InputError(field("scale"), "the disc's radius would be " + std::to_string(film.disc_radius_px) +
                                         " px; need at least 2 px (a larger image, a smaller scale or a larger radius)");
  }

  // The disc contrasts with the background: dark red on a light background, pale yellow on a dark one.
  film.disc_colour = o.disc_colour.value_or(contrasting_colour(r.background_colour));
  const FilmView view = v;
  const cv::Scalar colour = film.disc_colour;
  const double radius_px = film.disc_radius_px;
  film.scene = [path, view, colour, radius_px, phase](double t) {
    const cv::Point2d w = path->at(t + phase);
    ShapePose disc;
    const cv::Point2d c = view.to_px(w.x, w.y);
    disc.cx_px = c.x;
    disc.cy_px = c.y;
    disc.a_px = disc.b_px = radius_px;
    disc.colour = colour;
    return std::vector<ShapePose>{disc};
  };

  // Truth at each frame's time (exact samples of the simulation) and whether the disc stays in view.
  track::Track disc{"disc", {}};
  for (int k = 0; k < film.frames; ++k) {
    const double tl = k * dt + phase;
    const auto it = std::lower_bound(path->t.begin(), path->t.end(), tl);
    const auto& s = path->s[static_cast<std::size_t>(it - path->t.begin())];
    disc.points.push_back({k, k * dt, s.x, s.y});
    const cv::Point2d c = v.to_px(s.x, s.y);
    if (c.x - radius_px < 0 || c.y - radius_px < 0 || c.x + radius_px > r.width - 1 || c.y + radius_px > r.height - 1) {
      film.disc_in_view = false;
    }
  }
  film.truth.tracks = {disc};
  film.truth.format = "tidy_csv";
  return film;
}

}  // namespace tribolab::video
