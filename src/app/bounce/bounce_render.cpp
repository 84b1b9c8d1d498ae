// `bounce render` (src/app/bounce/bounce_synth.hpp): film a simulated throw to a video with its truth
#include "app/common/result_keys.hpp"

#include "app/common/film_options.hpp"
#include "app/common/output_paths.hpp"
// (docs/cli.md#bounce-render, docs/theory.md#rendering).
#include "app/bounce/bounce_synth.hpp"

#include "bounce/geometry.hpp"
#include "io/atomic_file.hpp"
#include "io/track_csv.hpp"
#include "io/tracker_trk.hpp"
#include "numerics/error.hpp"
#include "numerics/units.hpp"
#include "video/source.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

namespace tribolab::app {
namespace {

using nlohmann::json;

// The project Tracker opens with the rendered video: the clip is every frame, frame k at
// k / fps, and the image coordinate system is the film's (origin on the floor line below the
// release, px per m = 1 / scale), so `track video FILE.trk` lands in world metres.
io::TrkWriteSpec trk_spec(const video::ThrowFilm& film, const std::string& video_path, const std::string& trk_path) {
  namespace fs = std::filesystem;
  io::TrkWriteSpec spec;
  io::TrkCoordFrame c;
  c.origin_x = film.view.origin_x_px;
  c.origin_y = film.view.origin_y_px;
  c.xscale = c.yscale = 1 / film.view.scale_m_per_px;
  spec.coords = {video::to_tracker_pixels(c)};  // Tracker's pixel centres are at +0.5 px
  spec.step_count = film.frames;
  spec.frame_duration_ms = 1000 / film.render.fps;
  spec.length_unit = "m";
  std::error_code ec;
  const fs::path dir = fs::absolute(fs::path(trk_path), ec).parent_path();
  const fs::path video = fs::absolute(fs::path(video_path), ec);
  const fs::path rel = video.lexically_relative(dir);
  spec.video_path = (rel.empty() ? video : rel).generic_string();
  spec.video_frame_count = film.frames;
  return spec;
}

// Exact decimal text of a number for options a user pastes into `track video`.
std::string exact(double v) { return fmt::format("{}", v); }

video::ThrowFilmOptions film_options(const BounceRenderOptions& opts) {
  video::ThrowFilmOptions o;
  auto& m = o.motion;
  apply_throw(opts, m);
  o.sticker = opts.sticker;
  auto& r = o.render;
  r.fps = opts.fps;
  r.noise_sigma = opts.noise;
  r.shutter_fraction = opts.shutter;
  r.blur_samples = opts.blur_samples;
  r.supersample = opts.supersample;
  check_finite(r.fps, field("fps"));
  const double scale = opts.scale.value_or(0.0);  // 0: the core fits the throw in view
  check_finite(scale, field("scale"));
  const auto [w, h] = parse_frame_size(opts.size);
  r.width = w;
  r.height = h;
  apply_background(opts.background, r);
  r.seed = m.seed;
  o.scale_m_per_px = scale;
  o.floor_band = !opts.no_floor;
  return o;
}

}  // namespace

BounceRenderResult bounce_render(const BounceRenderOptions& opts) {
  check_output_paths({}, {{"out", opts.out}, {"truth", opts.truth}, {"write_trk", opts.write_trk}});  // before any work (app/common/output_paths.hpp)
  const video::ThrowFilm film = video::plan_throw_film(film_options(opts));
  // Outputs appear whole or not at all: the truth is written to a temporary file first and
  // renamed after the video is complete.
  std::optional<io::AtomicFile> truth;
  if (!opts.truth.empty()) {
    truth.emplace(opts.truth);
    io::write_tidy_csv(truth->stream(), film.truth);
  }
  std::optional<io::AtomicFile> trk;
  if (!opts.write_trk.empty()) {
    if (std::filesystem::path(opts.write_trk).extension() != ".trk") {
      throw InputError(field("write_trk") + " " + opts.write_trk, "the project file must end in .trk");
    }
    trk.emplace(opts.write_trk);
    // The truth goes in as tracks truth, truth.A, truth.B (a project needs a track, and
    // Tracker then shows the truth beside what `track video` finds as ball, ball.A, ball.B).
    auto tracks = film.truth.tracks;
    for (auto& t : tracks) t.name.replace(0, 4, "truth");
    trk->stream() << io::write_trk(tracks, trk_spec(film, opts.out, opts.write_trk));
  }
  video::write_video(opts.out, film.scene, film.frames, film.render);
  if (truth || trk) {
    try {
      if (truth) truth->commit();
      if (trk) trk->commit();
    } catch (...) {
      std::error_code ec;
      std::filesystem::remove(opts.out, ec);
      if (truth && trk) std::filesystem::remove(opts.truth, ec);  // the project failed after the truth
      throw;
    }
  }
  const auto& t = film.motion.truth;
  const auto& v = film.view;
  const cv::Point2d start = v.to_px(film.truth.tracks[0].points[0].x, film.truth.tracks[0].points[0].y);
  const std::string calibration = "--scale " + exact(v.scale_m_per_px) + " --origin " + exact(v.origin_x_px) + "," +
                                  exact(v.origin_y_px);
  const std::string ellipse = fmt::format("--ellipse ball={:.1f},{:.1f}@0", start.x, start.y);
  BounceRenderResult res;
  res.truth = film.truth;
  res.json = {{"out", opts.out},
              {"truth_file", opts.truth.empty() ? json(nullptr) : json(opts.truth)},
              {"write_trk", opts.write_trk.empty() ? json(nullptr) : json(opts.write_trk)},
              {"frames", film.frames},
              {"fps", film.render.fps},
              {"width", film.render.width},
              {"height", film.render.height},
              {"scale_m_per_px", v.scale_m_per_px},
              {"origin_px", {v.origin_x_px, v.origin_y_px}},
              {"t0", film.t0},
              {"ball_in_view", film.ball_in_view},
              {"ball_start_px", {start.x, start.y}},
              {"track_video_options", calibration + " " + ellipse},
              {"truth",
               {{"t_touch", t.t_touch - film.t0},
                {"t_separation", t.t_separation - film.t0},
                {"vx_in", t.touch.vx},
                {"vy_in", t.touch.vy},
                {"omega_in", t.touch.omega},
                {"theta_touch_deg", to_deg(bounce::wrap_angle(t.touch.theta))},
                {"vx_out", t.separation.vx},
                {"vy_out", t.separation.vy},
                {"omega_out", t.separation.omega},
                {"e_velocity", -t.separation.vy / t.touch.vy},
                {"release_apex", t.release_apex},
                {"post_apex", t.post_apex},
                {"e_height", std::sqrt(t.post_apex / t.release_apex)}}}};
  return res;
}


const ResultKeys& bounce_render_result_keys() {
  static const ResultKeys k = {
      {"out", "", ""}, {"truth_file", "", ""}, {"write_trk", "", ""}, {"frames", "", ""}, {"fps", "1/s", ""},
      {"width", "px", "frame width"}, {"height", "px", "frame height"},
      {"scale_m_per_px", "m/px", "length of a pixel"}, {"origin_px", "px", "world origin in the image"},
      {"t0", "s", "time of the first frame"}, {"ball_in_view", "", ""}, {"ball_start_px", "px", ""},
      {"track_video_options", "", ""},
      {"truth.t_touch", "s", ""}, {"truth.t_separation", "s", ""}, {"truth.vx_in", "m/s", ""}, {"truth.vy_in", "m/s", ""},
      {"truth.omega_in", "rad/s", ""}, {"truth.theta_touch_deg", "deg", ""}, {"truth.vx_out", "m/s", ""},
      {"truth.vy_out", "m/s", ""}, {"truth.omega_out", "rad/s", ""}, {"truth.e_velocity", "", ""},
      {"truth.release_apex", "m", ""}, {"truth.post_apex", "m", ""}, {"truth.e_height", "", ""},
  };
  return k;
}
}  // namespace tribolab::app
