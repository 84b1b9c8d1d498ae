// `tribolab incline render` as a workflow of the application layer (docs/cli.md#incline-render,
// docs/theory.md#rendering): a disc launched across the incline (model B, seed 000) filmed
// face-on to a video, with its true path. The physics options are `incline simulate`'s launch
// (incline_launch_fields), the camera options those of `bounce render`. No printing; files only
// where a path is given, each whole or not at all.
#pragma once

#include "app/common/option_fields.hpp"
#include "app/incline/incline_launch.hpp"

#include "track/track.hpp"
#include "video/render.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace tribolab::app {

struct InclineRenderOptions {
  InclineLaunchOptions launch;  ///< --mu, --phi-deg, --v0 (required), --g, --mu-static
  std::string out;              ///< output video: .avi (MJPG) or .mp4 (mp4v) (required)
  std::string truth;            ///< CSV of the true path (track,frame,t,x,y,x_px,y_px); empty = none
  /// Film length after the launch, s; unset = until 0.3 s after the stop, or 1.5 s if it never stops.
  std::optional<double> duration;
  double fps = 60;              ///< camera frame rate, 1/s (a phone camera)
  std::string size = "640x480"; ///< image size WIDTHxHEIGHT, px
  std::optional<double> scale;  ///< m per px as `track video --scale` takes it; unset: fit the path in view
  double radius = 0.02;         ///< disc radius, m
  std::string background = "gradient";                       ///< plain|gradient|texture
  double noise = video::RenderOptions{}.noise_sigma;         ///< Gaussian sensor noise, grey levels
  double shutter = video::RenderOptions{}.shutter_fraction;  ///< exposure, fraction of the frame period
  int blur_samples = video::RenderOptions{}.blur_samples;    ///< sub-frames averaged across the exposure
  int supersample = video::RenderOptions{}.supersample;      ///< anti-aliasing sub-pixels per axis
  std::uint64_t seed = 1;       ///< the launch's phase within a frame period, the texture and the noise
};

/// The declaration of every option of `incline render` (app/common/option_fields.hpp).
inline const Fields<InclineRenderOptions>& incline_render_fields() {
  using O = InclineRenderOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.group(&O::launch, incline_launch_fields(true));
    d.add("out", &O::out, "", "output video: .avi (MJPG) or .mp4 (mp4v)").as(FieldRole::output_path).needed();
    d.add("truth", &O::truth, "", "CSV of the true path: track disc, track,frame,t,x,y,x_px,y_px (s, m, px)")
        .as(FieldRole::output_path);
    d.add("duration", &O::duration, "s", "film length after the launch (unset: until 0.3 s after the stop, or 1.5 s)")
        .in(ranges::step);
    d.add("fps", &O::fps, "1/s", "camera frame rate").in(ranges::frame_rate);
    d.add("size", &O::size, "px", "image size WIDTHxHEIGHT");
    d.add("scale", &O::scale, "m/px", "length of a pixel, as track video --scale takes it (unset: fit the path in view)");
    d.add("radius", &O::radius, "m", "disc radius").in(ranges::size);
    d.add("background", &O::background, "", "background").one_of({"plain", "gradient", "texture"});
    d.add("noise", &O::noise, "", "Gaussian sensor noise, grey levels");
    d.add("shutter", &O::shutter, "", "exposure as a fraction of the frame period, 0..1");
    d.add("blur_samples", &O::blur_samples, "", "sub-frames averaged across the exposure");
    d.add("supersample", &O::supersample, "", "anti-aliasing sub-pixels per axis");
    d.add("seed", &O::seed, "", "random seed: the launch's phase within a frame period, the texture and the noise");
    return d;
  }();
  return f;
}
/// The keys of `incline render --json` (docs/cli.md#incline-render). In incline_render.cpp.
const ResultKeys& incline_render_result_keys();

struct InclineRenderResult {
  nlohmann::json json;    ///< exactly what `--json` prints
  track::TrackSet truth;  ///< the true path, track "disc", at each frame (video time, world m, origin at the launch)
};

InclineRenderResult incline_render(const InclineRenderOptions& o);

}  // namespace tribolab::app
