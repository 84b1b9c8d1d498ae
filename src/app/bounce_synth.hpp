// `tribolab bounce synth-video|synth-table|render` as workflows of the application layer
// (docs/design.md, "Application layer: bounce"; docs/cli.md#bounce-analyze): synthetic data
// with known truth. Each default is the core generator's own (analysis::SynthVideoOptions,
// SynthTableOptions, video::RenderOptions), read from a default-constructed core struct so
// that it is written once. Errors are InputError naming the option; nothing is printed.
#pragma once

#include "app/bounce_options.hpp"
#include "app/bounce_truth_law.hpp"

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

struct BounceRenderResult {
  nlohmann::json json;     ///< exactly what `--json` prints
  track::TrackSet truth;   ///< true tracks ball, ball.A, ball.B at each frame (video time, world m)
};

BounceRenderResult bounce_render(const BounceRenderOptions& o);

}  // namespace tribolab::app
