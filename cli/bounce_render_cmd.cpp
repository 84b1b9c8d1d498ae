// `tribolab bounce render`: film a simulated throw (flight, bounce, flight) to a video with
// its truth (docs/cli.md#bounce-render, docs/theory.md#rendering). The workflow is
// app::bounce_render (src/app/bounce_render.cpp); this file binds its options to flags.
#include "bounce_render_cmd.hpp"

#include "app.hpp"
#include "bounce_options.hpp"

#include "app/bounce_synth.hpp"

#include <memory>

namespace tribolab::cli {

void register_bounce_render(CLI::App* area) {
  struct Opts {
    BounceRenderOptions o;
    bool json = false;
  };
  auto opts = std::make_shared<Opts>();
  auto& o = opts->o;
  auto* cmd = area->add_subcommand("render", "film a simulated throw (flight, bounce, flight) to a video with its truth");
  cmd->add_option("--out", o.out, "output video: .avi (MJPG) or .mp4 (mp4v)")->required();
  cmd->add_option("--truth", o.truth, "CSV of the true tracks ball, ball.A, ball.B (track,frame,t,x,y; m, s)");
  cmd->add_option("--write-trk", o.write_trk,
                  "a Tracker project (.trk): the video, its clip, time base, calibration and the truth as tracks truth, truth.A, truth.B");
  add_throw_options(cmd, o);
  cmd->add_option("--size", o.size, "image size WIDTHxHEIGHT, px");
  cmd->add_option("--scale", o.scale, "metres per pixel, as `track video --scale` takes it; unset: fit the throw in view");
  cmd->add_option("--background", o.background, "plain|gradient|texture");
  cmd->add_flag("--no-floor", o.no_floor, "no dark floor band below the floor line");
  cmd->add_flag("--sticker", o.sticker, "a 3x3 checker sticker on the ball, half-way to tip B");
  cmd->add_option("--noise", o.noise, "Gaussian sensor noise, grey levels");
  cmd->add_option("--shutter", o.shutter, "exposure as a fraction of the frame period, 0..1");
  cmd->add_option("--blur-samples", o.blur_samples, "sub-frames averaged across the exposure");
  cmd->add_option("--supersample", o.supersample, "anti-aliasing sub-pixels per axis");
  cmd->add_option("--seed", o.seed, "random seed: the first frame's phase, the texture and the noise");
  add_json_flag(*cmd, opts->json);
  cmd->callback([opts] { print_result(bounce_render(opts->o).json, opts->json); });
}

}  // namespace tribolab::cli
