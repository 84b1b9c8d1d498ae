// `tribolab bounce render`: film a simulated throw (flight, bounce, flight) to a video with
// its truth (docs/cli.md#bounce-render, docs/theory.md#rendering).
#include "bounce_render_cmd.hpp"

#include "app.hpp"
#include "bounce_options.hpp"
#include "bounce_truth_law.hpp"

#include "bounce/geometry.hpp"
#include "io/atomic_file.hpp"
#include "io/track_csv.hpp"
#include "io/tracker_trk.hpp"
#include "numerics/error.hpp"
#include "video/render_throw.hpp"
#include "video/source.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <numbers>
#include <optional>
#include <string>

namespace tribolab::cli {
namespace {

using nlohmann::json;

std::pair<int, int> parse_size(const std::string& text) {
  const auto x = text.find_first_of("xX");
  int w = 0, h = 0;
  std::size_t used_w = 0, used_h = 0;
  try {
    if (x == std::string::npos) throw std::invalid_argument("no x");
    w = std::stoi(text.substr(0, x), &used_w);
    h = std::stoi(text.substr(x + 1), &used_h);
  } catch (const std::exception&) {
    throw InputError("--size", "expected WIDTHxHEIGHT in pixels (e.g. 640x480), got '" + text + "'");
  }
  if (used_w != x || used_h != text.size() - x - 1) {
    throw InputError("--size", "expected WIDTHxHEIGHT in pixels (e.g. 640x480), got '" + text + "'");
  }
  return {w, h};
}

video::RenderOptions::Background parse_background(const std::string& name) {
  if (name == "plain") return video::RenderOptions::Background::plain;
  if (name == "gradient") return video::RenderOptions::Background::gradient;
  if (name == "texture") return video::RenderOptions::Background::texture;
  throw InputError("--background", "unknown background '" + name + "' (plain, gradient, texture)");
}

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

}  // namespace

void register_bounce_render(CLI::App* area) {
  struct Opts {
    video::ThrowFilmOptions o;
    TruthLaw law;
    std::string out, truth, write_trk, size = "640x480", background = "gradient";
    double scale = 0;
    bool no_floor = false, json = false;
  };
  auto opts = std::make_shared<Opts>();
  opts->o.render.fps = 240;
  auto* cmd = area->add_subcommand("render", "film a simulated throw (flight, bounce, flight) to a video with its truth");
  cmd->add_option("--out", opts->out, "output video: .avi (MJPG) or .mp4 (mp4v)")->required();
  cmd->add_option("--truth", opts->truth, "CSV of the true tracks ball, ball.A, ball.B (track,frame,t,x,y; m, s)");
  cmd->add_option("--write-trk", opts->write_trk,
                  "a Tracker project (.trk): the video, its clip, time base, calibration and the truth as tracks truth, truth.A, truth.B");
  add_ball_options(cmd, opts->o.motion.ball);
  opts->law.add(cmd);
  auto& m = opts->o.motion;
  cmd->add_option("--height", m.height, "centre height at release, m (default 0.8)");
  cmd->add_option("--theta-deg", m.theta_deg, "orientation at release, deg (default 20)");
  cmd->add_option("--omega", m.omega, "spin at release, rad/s (default 45)");
  cmd->add_option("--vx", m.vx, "horizontal speed, m/s (default 1.5)");
  cmd->add_option("--vy", m.vy, "vertical speed at release, m/s (default 0)");
  cmd->add_option("--after", m.after, "seconds of video after the separation (default 0.3)");
  auto& r = opts->o.render;
  cmd->add_option("--fps", r.fps, "camera frame rate, 1/s (default 240)");
  cmd->add_option("--size", opts->size, "image size WIDTHxHEIGHT, px (default 640x480)");
  cmd->add_option("--scale", opts->scale, "metres per pixel, as `track video --scale` takes it (default: fit the throw in view)");
  cmd->add_option("--background", opts->background, "plain|gradient|texture (default gradient)");
  cmd->add_flag("--no-floor", opts->no_floor, "no dark floor band below the floor line");
  cmd->add_flag("--sticker", opts->o.sticker, "a 3x3 checker sticker on the ball, half-way to tip B");
  cmd->add_option("--noise", r.noise_sigma, "Gaussian sensor noise, grey levels (default 2)");
  cmd->add_option("--shutter", r.shutter_fraction, "exposure as a fraction of the frame period, 0..1 (default 0.5)");
  cmd->add_option("--blur-samples", r.blur_samples, "sub-frames averaged across the exposure (default 8)");
  cmd->add_option("--supersample", r.supersample, "anti-aliasing sub-pixels per axis (default 4)");
  cmd->add_option("--seed", m.seed, "random seed: the first frame's phase, the texture and the noise (default 1)");
  add_json_flag(*cmd, opts->json);
  cmd->callback([opts] {
    video::ThrowFilmOptions o = opts->o;
    checked_ball(o.motion.ball);
    opts->law.apply(o.motion.law, o.motion.friction);
    check_finite(o.render.fps, "--fps");
    check_finite(opts->scale, "--scale");
    const auto [w, h] = parse_size(opts->size);
    o.render.width = w;
    o.render.height = h;
    o.render.background = parse_background(opts->background);
    o.render.background_colour = o.render.background == video::RenderOptions::Background::texture
                                     ? cv::Scalar(180, 185, 190)
                                     : cv::Scalar(200, 200, 200);
    o.render.seed = o.motion.seed;
    o.scale_m_per_px = opts->scale;
    o.floor_band = !opts->no_floor;
    const video::ThrowFilm film = video::plan_throw_film(o);
    // Outputs appear whole or not at all: the truth is written to a temporary file first and
    // renamed after the video is complete.
    std::optional<io::AtomicFile> truth;
    if (!opts->truth.empty()) {
      truth.emplace(opts->truth);
      io::write_tidy_csv(truth->stream(), film.truth);
    }
    std::optional<io::AtomicFile> trk;
    if (!opts->write_trk.empty()) {
      if (std::filesystem::path(opts->write_trk).extension() != ".trk") {
        throw InputError("--write-trk " + opts->write_trk, "the project file must end in .trk");
      }
      trk.emplace(opts->write_trk);
      // The truth goes in as tracks truth, truth.A, truth.B (a project needs a track, and
      // Tracker then shows the truth beside what `track video` finds as ball, ball.A, ball.B).
      auto tracks = film.truth.tracks;
      for (auto& t : tracks) t.name.replace(0, 4, "truth");
      trk->stream() << io::write_trk(tracks, trk_spec(film, opts->out, opts->write_trk));
    }
    video::write_video(opts->out, film.scene, film.frames, film.render);
    if (truth || trk) {
      try {
        if (truth) truth->commit();
        if (trk) trk->commit();
      } catch (...) {
        std::error_code ec;
        std::filesystem::remove(opts->out, ec);
        if (truth && trk) std::filesystem::remove(opts->truth, ec);  // the project failed after the truth
        throw;
      }
    }
    const auto& t = film.motion.truth;
    const auto& v = film.view;
    const cv::Point2d start = v.to_px(film.truth.tracks[0].points[0].x, film.truth.tracks[0].points[0].y);
    const std::string calibration = "--scale " + exact(v.scale_m_per_px) + " --origin " + exact(v.origin_x_px) + "," +
                                    exact(v.origin_y_px);
    const std::string ellipse = fmt::format("--ellipse ball={:.1f},{:.1f}@0", start.x, start.y);
    const double deg = 180 / std::numbers::pi;
    print_result({{"out", opts->out},
                  {"truth_file", opts->truth.empty() ? json(nullptr) : json(opts->truth)},
                  {"write_trk", opts->write_trk.empty() ? json(nullptr) : json(opts->write_trk)},
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
                    {"theta_touch_deg", bounce::wrap_angle(t.touch.theta) * deg},
                    {"vx_out", t.separation.vx},
                    {"vy_out", t.separation.vy},
                    {"omega_out", t.separation.omega},
                    {"e_velocity", -t.separation.vy / t.touch.vy},
                    {"release_apex", t.release_apex},
                    {"post_apex", t.post_apex},
                    {"e_height", std::sqrt(t.post_apex / t.release_apex)}}}},
                 opts->json);
  });
}

}  // namespace tribolab::cli
