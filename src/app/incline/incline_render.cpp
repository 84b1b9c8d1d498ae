// `incline render` (src/app/incline/incline_render.hpp): film a launch across the incline to a
// video with its truth (docs/cli.md#incline-render, docs/theory.md#rendering).
#include "app/incline/incline_render.hpp"

#include "app/common/film_options.hpp"
#include "app/common/output_paths.hpp"

#include "incline/params.hpp"
#include "io/atomic_file.hpp"
#include "numerics/error.hpp"
#include "numerics/units.hpp"
#include "video/render_incline.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <optional>
#include <random>
#include <string>

namespace tribolab::app {
namespace {

using nlohmann::json;

video::InclineFilmOptions film_options(const InclineRenderOptions& opts) {
  video::InclineFilmOptions o;
  o.launch = incline_launch_parameters(opts.launch);
  auto& r = o.render;
  r.fps = check_range(opts.fps, ranges::frame_rate, field("fps"));
  r.noise_sigma = opts.noise;
  r.shutter_fraction = opts.shutter;
  r.blur_samples = opts.blur_samples;
  r.supersample = opts.supersample;
  const auto [w, h] = parse_frame_size(opts.size);
  r.width = w;
  r.height = h;
  apply_background(opts.background, r);
  r.seed = opts.seed;
  // Unset: 0, the core fits the path in view.
  if (opts.scale) o.scale_m_per_px = check_range(*opts.scale, PhysicalRange{0, 1, "m/px", true}, field("scale"));
  o.disc_radius = check_range(opts.radius, ranges::size, field("radius"));
  if (opts.duration) o.duration = check_range(*opts.duration, ranges::step, field("duration"));
  // The launch falls anywhere within a frame period, as a real camera's frames do.
  std::mt19937_64 rng(opts.seed);
  o.launch_phase = std::uniform_real_distribution<double>(0, 1)(rng);
  return o;
}

// Exact decimal text of a number for options a user pastes into `track video`.
std::string exact(double v) { return fmt::format("{}", v); }

json optional_number(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

}  // namespace

InclineRenderResult incline_render(const InclineRenderOptions& opts) {
  check_output_paths({}, {{"out", opts.out}, {"truth", opts.truth}});  // before any work (app/common/output_paths.hpp)
  const video::InclineFilm film = video::plan_incline_film(film_options(opts));
  const video::FilmView& v = film.view;
  // Outputs appear whole or not at all: the truth is written to a temporary file first and
  // renamed after the video is complete.
  std::optional<io::AtomicFile> truth;
  if (!opts.truth.empty()) {
    truth.emplace(opts.truth);
    auto& out = truth->stream();
    out << "track,frame,t,x,y,x_px,y_px\n";
    for (const auto& p : film.truth.tracks.front().points) {
      const cv::Point2d px = v.to_px(p.x, p.y);
      out << fmt::format("disc,{},{},{},{},{},{}\n", p.frame, p.t, p.x, p.y, px.x, px.y);
    }
  }
  video::write_video(opts.out, film.scene, film.frames, film.render);
  if (truth) {
    try {
      truth->commit();
    } catch (...) {
      std::error_code ec;
      std::filesystem::remove(opts.out, ec);
      throw;
    }
  }
  const auto& first = film.truth.tracks.front().points.front();
  const cv::Point2d start = v.to_px(first.x, first.y);
  const incline::Parameters& p = film.launch;
  InclineRenderResult res;
  res.truth = film.truth;
  res.json = {{"out", opts.out},
              {"truth_file", opts.truth.empty() ? json(nullptr) : json(opts.truth)},
              {"frames", film.frames},
              {"fps", film.render.fps},
              {"width", film.render.width},
              {"height", film.render.height},
              {"scale_m_per_px", v.scale_m_per_px},
              {"origin_px", {v.origin_x_px, v.origin_y_px}},
              {"disc_radius_px", film.disc_radius_px},
              {"disc_start_px", {start.x, start.y}},
              {"disc_in_view", film.disc_in_view},
              {"track_video_options", "--scale " + exact(v.scale_m_per_px) + " --origin " + exact(v.origin_x_px) + "," +
                                          exact(v.origin_y_px) + fmt::format(" --ellipse disc={:.1f},{:.1f}@0", start.x, start.y)},
              {"truth",
               {{"mu", p.mu},
                {"phi_deg", to_deg(p.phi)},
                {"v0", p.v0},
                {"g", p.g},
                {"k", p.k()},
                {"regime", incline::to_string(p.regime())},
                {"t0", film.t_launch},
                {"x0", 0.0},
                {"y0", 0.0},
                {"t_stop", optional_number(film.t_stop)},
                {"x_stop", optional_number(film.x_stop)},
                {"y_stop", optional_number(film.y_stop)}}}};
  return res;
}

const ResultKeys& incline_render_result_keys() {
  static const ResultKeys k = {
      {"out", "", ""}, {"truth_file", "", ""}, {"frames", "", ""}, {"fps", "1/s", ""},
      {"width", "px", "frame width"}, {"height", "px", "frame height"},
      {"scale_m_per_px", "m/px", "length of a pixel"}, {"origin_px", "px", "world origin (the launch point) in the image"},
      {"disc_radius_px", "px", ""}, {"disc_start_px", "px", "the disc's centre in frame 0"},
      {"disc_in_view", "", ""}, {"track_video_options", "", ""},
      {"truth.mu", "", ""}, {"truth.phi_deg", "deg", ""}, {"truth.v0", "m/s", ""}, {"truth.g", "m/s^2", ""},
      {"truth.k", "", "tan(phi)/mu"}, {"truth.regime", "", ""}, {"truth.t0", "s", "launch time in the video's clock"},
      {"truth.x0", "m", "launch point"}, {"truth.y0", "m", "launch point"}, {"truth.t_stop", "s", "video time; null: never stops"},
      {"truth.x_stop", "m", ""}, {"truth.y_stop", "m", ""},
  };
  return k;
}

}  // namespace tribolab::app
