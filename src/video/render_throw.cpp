// docs/theory.md#rendering.
#include "video/render_throw.hpp"

#include "numerics/error.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

namespace tribolab::video {
namespace {

// "field: message" -> InputError naming the field (numerics/error.hpp).
[[noreturn]] void throw_invalid(const std::string& e) { throw input_error_of(e); }

}  // namespace

std::string ThrowFilmOptions::validate() const {
  // The camera's own rate decides the frames; the motion's fps is not used (kept valid).
  analysis::SynthVideoOptions m = motion;
  m.fps = 240;
  m.noise = 0;
  if (auto e = m.validate(); !e.empty()) return e;
  if (auto e = render.validate(); !e.empty()) return e;
  if (!std::isfinite(scale_m_per_px) || scale_m_per_px < 0 || scale_m_per_px > 1) {
    return "scale: must lie in (0, 1] m per px, or 0 to fit the throw in view";
  }
  return {};
}

ThrowFilm plan_throw_film(const ThrowFilmOptions& o) {
  if (auto e = o.validate(); !e.empty()) throw_invalid(e);
  ThrowFilm film;
  film.motion = analysis::simulate_throw(o.motion);
  const auto& m = film.motion;
  const auto& ball = o.motion.ball;
  film.render = o.render;
  RenderOptions& r = film.render;
  const double dt = 1 / r.fps;
  {  // the first frame falls anywhere within a frame period, as in analysis::synth_video
    std::mt19937_64 rng(o.motion.seed);
    film.t0 = std::uniform_real_distribution<double>(0, 1)(rng) * dt;
  }
  film.frames = static_cast<int>(std::floor((m.t_end - film.t0) / dt)) + 1;
  if (film.frames > 100000) throw InputError(field("after"), "the video would hold more than 100000 frames");

  // Layout: the floor line at 88 % of the height; the whole path of the ball (centre range
  // +- a) inside 90 % of the width and between the floor and 5 % below the top edge.
  double xmin = 0, xmax = 0, ymax = o.motion.height;
  for (int k = 0; k <= 400; ++k) {
    const auto s = m.state(m.t_end * k / 400.0);
    xmin = std::min(xmin, s.x);
    xmax = std::max(xmax, s.x);
    ymax = std::max(ymax, s.y);
  }
  ymax = std::max({ymax, m.truth.release_apex, m.truth.post_apex});
  ThrowView& v = film.view;
  v.origin_y_px = std::round(0.88 * r.height) - 0.5;  // on a pixel edge: the band starts cleanly
  v.scale_m_per_px = o.scale_m_per_px;
  if (v.scale_m_per_px == 0) {
    v.scale_m_per_px = std::max((xmax - xmin + 2 * ball.a) / (0.9 * r.width), (ymax + ball.a) / (v.origin_y_px - 0.05 * r.height));
  }
  v.origin_x_px = 0.5 * (r.width - 1) - 0.5 * (xmin + xmax) / v.scale_m_per_px;
  if (ball.b / v.scale_m_per_px < 2) {
    throw InputError(field("scale"), "the ball's semi-minor axis would be " + std::to_string(ball.b / v.scale_m_per_px) +
                                    " px; need at least 2 px (a larger image or a smaller scale)");
  }
  if (o.floor_band) r.floor_y_px = v.origin_y_px;

  // The ball contrasts with the background: dark red on a light background, pale yellow on a dark one.
  film.ball_colour = contrasting_colour(r.background_colour);
  const ThrowView view = v;
  const cv::Scalar colour = film.ball_colour;
  const double t0 = film.t0, s_px = 1 / v.scale_m_per_px;
  const bool sticker = o.sticker;
  auto pose = [view, colour, s_px, ball, sticker](const bounce::BodyState& s) {
    ShapePose p;
    const cv::Point2d c = view.to_px(s.x, s.y);
    p.cx_px = c.x;
    p.cy_px = c.y;
    p.a_px = ball.a * s_px;
    p.b_px = ball.b * s_px;
    p.angle_rad = s.theta;  // counter-clockwise in the world (y up) = on screen
    p.colour = colour;
    if (sticker) {
      p.mark = true;
      p.mark_u_px = 0.5 * p.a_px;
      p.mark_size_px = std::min(0.9 * p.b_px, 0.4 * p.a_px);
    }
    return p;
  };
  // The scene holds its own copy of the motion (the film may be moved or copied).
  auto shared = std::make_shared<analysis::ThrowMotion>(film.motion);
  film.scene = [shared, pose, t0](double t) { return std::vector<ShapePose>{pose(shared->state(t + t0))}; };

  // Truth at each frame's time and whether the ball stays in view.
  track::Track centre{"ball", {}}, tip_a{"ball.A", {}}, tip_b{"ball.B", {}};
  for (int k = 0; k < film.frames; ++k) {
    const double t = k * dt;
    const auto s = m.state(t + t0);
    const double ca = ball.a * std::cos(s.theta), sa = ball.a * std::sin(s.theta);
    centre.points.push_back({k, t, s.x, s.y});
    tip_a.points.push_back({k, t, s.x - ca, s.y - sa});
    tip_b.points.push_back({k, t, s.x + ca, s.y + sa});
    const cv::Point2d c = v.to_px(s.x, s.y);
    const double reach = ball.a * s_px;
    if (c.x - reach < 0 || c.y - reach < 0 || c.x + reach > r.width - 1 || c.y + reach > r.height - 1) film.ball_in_view = false;
  }
  film.truth.tracks = {centre, tip_a, tip_b};
  film.truth.format = "tidy_csv";
  return film;
}

}  // namespace tribolab::video
