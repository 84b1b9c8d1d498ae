// Synthetic tracked runs of the disc on the incline (seed 000), made by the project's own
// simulators with realistic measurement noise: the test data of the incline analyses and the
// demo's data (`tribolab incline synth`). The disc rests at the launch point until the launch
// time, is launched along +x, and rests after it stops; with v0 = 0 it is released from rest
// there and slides straight down the fall line (-y) when tan(phi) > mu_s (the straight slide
// of seed 000, 肆-一-(二), eq a, closed form: y = -(beta - alpha) t^2 / 2). Model B runs use the closed form
// (src/incline/closed_form.hpp), model A runs (normal_accel != 0) the integrator
// (src/incline/numeric.hpp). See docs/theory.md#incline-analysis.
#pragma once

#include "incline/closed_form.hpp"
#include "incline/params.hpp"
#include "track/track.hpp"

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace tribolab::analysis {

struct InclineSynthOptions {
  /// mu, phi, v0, g and (model A) normal_accel of the simulated launch; v0 = 0 releases
  /// the disc from rest (model B only; it must slide: tan(phi) > mu_s).
  incline::Parameters params;
  double fps = 80;          ///< frame rate, 1/s (seed 000: 80; 80-240 typical)
  double noise = 0.001;     ///< standard deviation of the Gaussian position noise, m (1 mm)
  double t_launch = 0.1;    ///< launch instant in the file's time (frame 0 is t = 0), s
  double x0 = 0.05, y0 = 0.0;  ///< launch point in the file's frame, m
  /// Camera frame turned against the incline, rad (0: aligned; a plumb line set off: ~0.01):
  /// the marked points are the incline-frame ones rotated counterclockwise by this angle
  /// about the launch point (analysis/frame_rotation.hpp). Within +-20 deg.
  double frame_rotation = 0;
  /// Recording length, s; 0 = until 0.3 s after the stop (or 1.5 s after the launch when
  /// the disc does not stop).
  double duration = 0;
  std::uint64_t seed = 1;   ///< noise seed: the same seed gives the same run, bit for bit
  std::string track_name = "disc";

  /// Empty when valid, else a message naming the bad field.
  std::string validate() const;
};

struct InclineSynthRun {
  track::Track track;                 ///< noisy marked points, file time and frame
  std::vector<incline::State> truth;  ///< noise-free state at each point (file time, frame)
  std::optional<double> t_stop;       ///< stop instant in the file's time, s
};

/// Makes one run. Throws InputError for invalid options.
InclineSynthRun synthesize_incline_run(const InclineSynthOptions& options);

/// Standard normal deviates from a 64-bit Mersenne Twister by the Box-Muller transform,
/// identical on every platform (std::normal_distribution is implementation-defined).
class PortableNormal {
 public:
  explicit PortableNormal(std::uint64_t seed) : rng_(seed) {}
  double operator()();

 private:
  std::mt19937_64 rng_;
  std::optional<double> spare_;
};

}  // namespace tribolab::analysis
