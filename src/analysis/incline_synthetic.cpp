#include "analysis/incline_synthetic.hpp"

#include "analysis/frame_rotation.hpp"

#include "incline/numeric.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"

#include <cmath>
#include <tuple>

namespace tribolab::analysis {

std::string InclineSynthOptions::validate() const {
  if (const std::string e = params.validate(); !e.empty()) return e;
  if (!(params.v0 >= 0)) return "v0 must be >= 0 (0: released from rest)";
  if (params.v0 == 0 && params.normal_accel != 0)
    return "a release from rest (v0 = 0) is a model B slide: normal_accel must be 0";
  if (params.v0 == 0 && params.stays_at_rest())
    return "released from rest the disc stays (tan(phi) <= mu_s): give v0 > 0 or a steeper phi";
  // Physical ranges: numerics/physical_range.hpp (docs/cli.md#physical-ranges).
  for (const auto& [v, r, name] : {std::tuple{fps, ranges::frame_rate, "fps"}, {noise, ranges::noise, "noise"},
                                   {t_launch, ranges::duration, "t_launch"}, {x0, ranges::position, "x0"},
                                   {y0, ranges::position, "y0"}, {duration, ranges::duration, "duration"}})
    if (auto e = range_error(v, r, name); !e.empty()) return e;
  if (!(std::isfinite(frame_rotation) && std::abs(frame_rotation) <= 0.35))
    return "frame rotation must be within +-20 degrees";
  if (track_name.empty()) return "track name must not be empty";
  return {};
}

double PortableNormal::operator()() {
  if (spare_) {
    const double v = *spare_;
    spare_.reset();
    return v;
  }
  // Uniform deviates in (0, 1) from the top 53 bits.
  auto uniform = [this] { return (static_cast<double>(rng_() >> 11) + 0.5) * 0x1p-53; };
  const double u1 = uniform(), u2 = uniform();
  const double r = std::sqrt(-2.0 * std::log(u1));
  spare_ = r * std::sin(2 * M_PI * u2);
  return r * std::cos(2 * M_PI * u2);
}

InclineSynthRun synthesize_incline_run(const InclineSynthOptions& o) {
  if (const std::string e = o.validate(); !e.empty()) throw InputError("synthetic run", e);
  const incline::Parameters& p = o.params;
  const bool model_a = p.normal_accel != 0.0;

  // Stop time after the launch (infinite when the disc never stops).
  double t_stop_rel = incline::ClosedForm(p).t_stop();
  if (model_a) {
    incline::NumericOptions no;
    no.model = incline::Model::A;
    no.t_max = 60.0;
    const auto r = incline::simulate(p, {}, no);
    t_stop_rel = r.t_stop ? *r.t_stop : INFINITY;
  }
  double duration = o.duration;
  if (duration == 0)
    duration = o.t_launch + (std::isfinite(t_stop_rel) ? t_stop_rel + 0.3 : 1.5);
  const double n_frames_real = std::floor(duration * o.fps * (1 + 1e-12)) + 1;
  if (n_frames_real > 1e7) throw InputError("synthetic run", "more than 10^7 frames");
  const int n_frames = static_cast<int>(n_frames_real);

  std::vector<double> rel;  // times after the launch, for the simulators
  for (int i = 0; i < n_frames; ++i) {
    const double t = i / o.fps;
    if (t > o.t_launch) rel.push_back(t - o.t_launch);
  }
  std::vector<incline::State> moving;
  if (model_a) {
    incline::NumericOptions no;
    no.model = incline::Model::A;
    const auto r = incline::simulate(p, rel, no);
    if (r.status == incline::NumericStatus::failed)
      throw SolverError("synthetic run", "integration failed: " + r.message);
    moving = r.samples;
  } else {
    moving = incline::ClosedForm(p).trajectory(rel);
  }

  InclineSynthRun run;
  run.track.name = o.track_name;
  if (std::isfinite(t_stop_rel)) run.t_stop = o.t_launch + t_stop_rel;
  PortableNormal normal(o.seed);
  std::size_t m = 0;
  for (int i = 0; i < n_frames; ++i) {
    const double t = i / o.fps;
    incline::State s;  // at rest before the launch
    if (t > o.t_launch) s = moving[m++];
    s.t = t;
    s = rotate_state(s, o.frame_rotation, o.x0, o.y0);
    run.truth.push_back(s);
    const double nx = normal(), ny = normal();
    run.track.points.push_back({i, t, s.x + o.noise * nx, s.y + o.noise * ny});
  }
  return run;
}

}  // namespace tribolab::analysis
