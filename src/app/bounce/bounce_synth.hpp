// `tribolab bounce synth-video|synth-table|render` as workflows of the application layer
// (docs/design.md, "Application layer: bounce"; docs/cli.md#bounce-analyze): synthetic data
// with known truth. Each default is the core generator's own (analysis::SynthVideoOptions,
// SynthTableOptions, video::RenderOptions), read from a default-constructed core struct so
// that it is written once. Errors are InputError naming the option; nothing is printed.
#pragma once

#include "app/common/option_fields.hpp"
#include "app/bounce/bounce_options.hpp"
#include "app/bounce/bounce_truth_law.hpp"

#include "analysis/bounce_synth.hpp"
#include "io/bounce_table.hpp"
#include "track/track.hpp"
#include "video/render.hpp"
#include "video/render_throw.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tribolab::app {

/// The throw of `opts` (BounceSynthVideoOptions or BounceRenderOptions: ball, law, release
/// height, orientation, spin, speeds, video after the separation, seed) into the motion `m`,
/// the ball checked (InputError naming the field).
template <class Opts>
void apply_throw(const Opts& opts, analysis::SynthVideoOptions& m) {
  m.ball = opts.ball.ball;
  checked_ball(m.ball);
  opts.law.apply(m.law, m.friction);
  m.height = opts.height;
  m.theta_deg = opts.theta_deg;
  m.omega = opts.omega;
  m.vx = opts.vx;
  m.vy = opts.vy;
  m.after = opts.after;
  m.seed = opts.seed;
}

/// The declarations of a filmed throw (`synth-video`, `render`): the ball, the truth law and the
/// release --height --theta-deg --omega --vx --vy --after (and --fps: `fps_help`).
template <class O>
void add_throw_fields(Fields<O>& d) {
  d.group(&O::ball, ball_fields());
  d.group(&O::law, truth_law_fields());
  d.add("height", &O::height, "m", "centre height at release").in(ranges::height);
  d.add("theta_deg", &O::theta_deg, "deg", "orientation at release").in(ranges::angle_deg);
  d.add("omega", &O::omega, "rad/s", "spin at release").in(ranges::spin);
  d.add("vx", &O::vx, "m/s", "horizontal speed").in(ranges::velocity);
  d.add("vy", &O::vy, "m/s", "vertical speed at release").in(ranges::velocity);
  d.add("after", &O::after, "s", "seconds of video after the separation");
  d.add("fps", &O::fps, "1/s", "camera frame rate").in(ranges::frame_rate);
}

/// `bounce synth-video`: a synthetic Tracker export of one bounce (tips A and B).
struct BounceSynthVideoOptions {
  BallOptions ball;
  TruthLawOptions law;
  std::string out;  ///< output file (Tracker Export Data text; required)
  double height = analysis::SynthVideoOptions{}.height;            ///< centre height at release, m
  double theta_deg = analysis::SynthVideoOptions{}.theta_deg;      ///< orientation at release, deg
  double omega = analysis::SynthVideoOptions{}.omega;              ///< spin at release, rad/s
  double vx = analysis::SynthVideoOptions{}.vx;                    ///< horizontal speed, m/s
  double vy = analysis::SynthVideoOptions{}.vy;                    ///< vertical speed at release, m/s
  double after = analysis::SynthVideoOptions{}.after;              ///< s of video after the separation
  double fps = analysis::SynthVideoOptions{}.fps;                  ///< camera frame rate, 1/s
  double noise = analysis::SynthVideoOptions{}.noise;              ///< position noise sd of each tip coordinate, m
  double time_factor = analysis::SynthVideoOptions{}.time_factor;  ///< file time = real time x this
  std::uint64_t seed = analysis::SynthVideoOptions{}.seed;         ///< random seed
};

/// The declaration of every option of `bounce synth-video` (app/common/option_fields.hpp).
inline const Fields<BounceSynthVideoOptions>& bounce_synth_video_fields() {
  using O = BounceSynthVideoOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.add("out", &O::out, "", "output file (Tracker Export Data text)").as(FieldRole::output_path).needed();
    add_throw_fields(d);
    d.add("noise", &O::noise, "m", "position noise sd of each tip coordinate").in(ranges::noise);
    d.add("time_factor", &O::time_factor, "", "file time = real time x this (8: 240 fps shown at 30)");
    d.add("seed", &O::seed, "", "random seed");
    return d;
  }();
  return f;
}
/// The keys of `bounce synth-video --json`. In bounce_synth.cpp.
const ResultKeys& bounce_synth_video_result_keys();

struct BounceSynthVideoResult {
  nlohmann::json json;           ///< exactly what `--json` prints
  analysis::SynthVideo video;    ///< the tips A and B (file time) and the truth (real time)
};

BounceSynthVideoResult bounce_synth_video(const BounceSynthVideoOptions& o);

/// `bounce synth-table`: a synthetic bounce table for `bounce fit`.
struct BounceSynthTableOptions {
  BallOptions ball;
  TruthLawOptions law;
  std::string out;  ///< output CSV (required)
  int rows = analysis::SynthTableOptions{}.rows;                          ///< bounces
  double speed_min = analysis::SynthTableOptions{}.speed_min;             ///< smallest incoming |vy|, m/s
  double speed_max = analysis::SynthTableOptions{}.speed_max;             ///< largest incoming |vy|, m/s
  double vx_max = analysis::SynthTableOptions{}.vx_max;                   ///< incoming vx in [-vx_max, vx_max], m/s
  double omega_max = analysis::SynthTableOptions{}.omega_max;             ///< incoming omega in [-omega_max, omega_max], rad/s
  double noise_v = analysis::SynthTableOptions{}.noise_v;                 ///< noise sd of the outgoing vx, vy, m/s
  double noise_omega = analysis::SynthTableOptions{}.noise_omega;         ///< noise sd of the outgoing omega, rad/s
  double outlier_fraction = analysis::SynthTableOptions{}.outlier_fraction;  ///< fraction of rows with a gross error
  double outlier_v = analysis::SynthTableOptions{}.outlier_v;             ///< size of a gross error, m/s (omega: v/b)
  std::uint64_t seed = analysis::SynthTableOptions{}.seed;                ///< random seed
};

/// The declaration of every option of `bounce synth-table` (app/common/option_fields.hpp).
inline const Fields<BounceSynthTableOptions>& bounce_synth_table_fields() {
  using O = BounceSynthTableOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.add("out", &O::out, "", "output CSV").as(FieldRole::output_path).needed();
    d.group(&O::ball, ball_fields());
    d.group(&O::law, truth_law_fields());
    d.add("rows", &O::rows, "", "bounces");
    d.add("speed_min", &O::speed_min, "m/s", "smallest incoming |vy|");
    d.add("speed_max", &O::speed_max, "m/s", "largest incoming |vy|");
    d.add("vx_max", &O::vx_max, "m/s", "incoming vx in [-vx-max, vx-max]");
    d.add("omega_max", &O::omega_max, "rad/s", "incoming omega in [-omega-max, omega-max]");
    d.add("noise_v", &O::noise_v, "m/s", "noise sd of the outgoing vx, vy");
    d.add("noise_omega", &O::noise_omega, "rad/s", "noise sd of the outgoing omega");
    d.add("outlier_fraction", &O::outlier_fraction, "", "fraction of rows with a gross error on one outgoing value");
    d.add("outlier_v", &O::outlier_v, "m/s", "size of a gross error: uniform in [v, 2v], random sign; omega: v/b");
    d.add("seed", &O::seed, "", "random seed");
    return d;
  }();
  return f;
}
/// The keys of `bounce synth-table --json`. In bounce_synth.cpp.
const ResultKeys& bounce_synth_table_result_keys();

struct BounceSynthTableResult {
  nlohmann::json json;                 ///< exactly what `--json` prints
  std::vector<analysis::BounceRow> rows;  ///< the table written
};

BounceSynthTableResult bounce_synth_table(const BounceSynthTableOptions& o);

/// `bounce render`: film a simulated throw (flight, bounce, flight) to a video with its truth.
struct BounceRenderOptions {
  BallOptions ball;
  TruthLawOptions law;
  std::string out;        ///< output video: .avi (MJPG) or .mp4 (mp4v) (required)
  std::string truth;      ///< CSV of the true tracks ball, ball.A, ball.B; empty = none
  std::string write_trk;  ///< Tracker project (.trk) of the video and the truth; empty = none
  double height = analysis::SynthVideoOptions{}.height;        ///< centre height at release, m
  double theta_deg = analysis::SynthVideoOptions{}.theta_deg;  ///< orientation at release, deg
  double omega = analysis::SynthVideoOptions{}.omega;          ///< spin at release, rad/s
  double vx = analysis::SynthVideoOptions{}.vx;                ///< horizontal speed, m/s
  double vy = analysis::SynthVideoOptions{}.vy;                ///< vertical speed at release, m/s
  double after = analysis::SynthVideoOptions{}.after;          ///< s of video after the separation
  double fps = video::RenderOptions{}.fps;                     ///< camera frame rate, 1/s
  std::string size = "640x480";                                ///< image size WIDTHxHEIGHT, px
  std::optional<double> scale;             ///< m per px as `track video --scale` takes it; unset: fit the throw in view
  std::string background = "gradient";     ///< plain|gradient|texture
  bool no_floor = false;                   ///< no dark floor band below the floor line
  bool sticker = false;                    ///< a 3x3 checker sticker on the ball, half-way to tip B
  double noise = video::RenderOptions{}.noise_sigma;            ///< Gaussian sensor noise, grey levels
  double shutter = video::RenderOptions{}.shutter_fraction;     ///< exposure, fraction of the frame period
  int blur_samples = video::RenderOptions{}.blur_samples;       ///< sub-frames averaged across the exposure
  int supersample = video::RenderOptions{}.supersample;         ///< anti-aliasing sub-pixels per axis
  std::uint64_t seed = analysis::SynthVideoOptions{}.seed;      ///< first frame's phase, texture and noise
};

/// The declaration of every option of `bounce render` (app/common/option_fields.hpp).
inline const Fields<BounceRenderOptions>& bounce_render_fields() {
  using O = BounceRenderOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.add("out", &O::out, "", "output video: .avi (MJPG) or .mp4 (mp4v)").as(FieldRole::output_path).needed();
    d.add("truth", &O::truth, "", "CSV of the true tracks ball, ball.A, ball.B (track,frame,t,x,y; m, s)")
        .as(FieldRole::output_path);
    d.add("write_trk", &O::write_trk, "",
          "a Tracker project (.trk): the video, its clip, time base, calibration and the truth as tracks truth, truth.A, "
          "truth.B")
        .as(FieldRole::output_path);
    add_throw_fields(d);
    d.add("size", &O::size, "px", "image size WIDTHxHEIGHT");
    d.add("scale", &O::scale, "m/px", "length of a pixel, as track video --scale takes it (unset: fit the throw in view)");
    d.add("background", &O::background, "", "background").one_of({"plain", "gradient", "texture"});
    d.add("no_floor", &O::no_floor, "", "no dark floor band below the floor line");
    d.add("sticker", &O::sticker, "", "a 3x3 checker sticker on the ball, half-way to tip B");
    d.add("noise", &O::noise, "", "Gaussian sensor noise, grey levels");
    d.add("shutter", &O::shutter, "", "exposure as a fraction of the frame period, 0..1");
    d.add("blur_samples", &O::blur_samples, "", "sub-frames averaged across the exposure");
    d.add("supersample", &O::supersample, "", "anti-aliasing sub-pixels per axis");
    d.add("seed", &O::seed, "", "random seed: the first frame's phase, the texture and the noise");
    return d;
  }();
  return f;
}

struct BounceRenderResult {
  nlohmann::json json;     ///< exactly what `--json` prints
  track::TrackSet truth;   ///< true tracks ball, ball.A, ball.B at each frame (video time, world m)
};

BounceRenderResult bounce_render(const BounceRenderOptions& o);

}  // namespace tribolab::app
