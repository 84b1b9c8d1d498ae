#include "app/bounce/bounce_synth.hpp"

#include "app/common/output_paths.hpp"

#include "analysis/bounce_fit.hpp"
#include "bounce/geometry.hpp"
#include "io/atomic_file.hpp"
#include "io/tracker_export.hpp"
#include "numerics/error.hpp"
#include "numerics/units.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>
#include <utility>

namespace tribolab::app {

using nlohmann::json;

BounceSynthVideoResult bounce_synth_video(const BounceSynthVideoOptions& opts) {
  check_output_paths({}, {{"out", opts.out}});  // before any work (app/common/output_paths.hpp)
  analysis::SynthVideoOptions o;
  apply_throw(opts, o);
  o.fps = opts.fps;
  o.noise = opts.noise;
  o.time_factor = opts.time_factor;
  BounceSynthVideoResult res;
  res.video = analysis::synth_video(o);
  const auto& v = res.video;
  io::AtomicFile file(opts.out);
  file.stream() << io::write_export_text({v.tip_a, v.tip_b});
  file.commit();
  const auto& t = v.truth;
  res.json = {{"out", opts.out}, {"frames", v.tip_a.points.size()},
              {"t_touch", t.t_touch}, {"t_separation", t.t_separation},
              {"vx_in", t.touch.vx}, {"vy_in", t.touch.vy}, {"omega_in", t.touch.omega},
              {"theta_touch_deg", to_deg(bounce::wrap_angle(t.touch.theta))},
              {"vx_out", t.separation.vx}, {"vy_out", t.separation.vy}, {"omega_out", t.separation.omega},
              {"release_apex", t.release_apex}, {"post_apex", t.post_apex},
              {"e_height", std::sqrt(t.post_apex / t.release_apex)}};
  return res;
}

BounceSynthTableResult bounce_synth_table(const BounceSynthTableOptions& opts) {
  check_output_paths({}, {{"out", opts.out}});  // before any work (app/common/output_paths.hpp)
  analysis::SynthTableOptions o;
  o.ball = opts.ball.ball;
  checked_ball(o.ball);
  opts.law.apply(o.law, o.friction);
  o.rows = opts.rows;
  o.speed_min = opts.speed_min;
  o.speed_max = opts.speed_max;
  o.vx_max = opts.vx_max;
  o.omega_max = opts.omega_max;
  o.noise_v = opts.noise_v;
  o.noise_omega = opts.noise_omega;
  o.outlier_fraction = opts.outlier_fraction;
  o.outlier_v = opts.outlier_v;
  o.seed = opts.seed;
  for (auto [v, name] : {std::pair{o.speed_min, field("speed_min")}, {o.speed_max, field("speed_max")}, {o.vx_max, field("vx_max")},
                         {o.omega_max, field("omega_max")}, {o.noise_v, field("noise_v")}, {o.noise_omega, field("noise_omega")},
                         {o.outlier_fraction, field("outlier_fraction")}, {o.outlier_v, field("outlier_v")}})
    check_finite(v, name);
  BounceSynthTableResult res;
  res.rows = analysis::synth_table(o);
  io::AtomicFile file(opts.out);
  file.stream() << io::write_bounce_table(res.rows);
  file.commit();
  // The truth `bounce fit` should recover, with the keys it prints (K, n, D, mu).
  json truth = {{"model", std::string(bounce::to_string(o.law.model))},
                {"K", o.law.K},
                {"n", o.law.n},
                {"D", o.law.restitution ? json(nullptr) : json(o.law.D)},
                {"restitution", o.law.restitution ? json(*o.law.restitution) : json(nullptr)},
                {"friction", std::string(bounce::to_string(o.friction.kind))},
                {"mu", o.friction.mu},
                {"a", o.ball.a}, {"b", o.ball.b}, {"mass", o.ball.mass}, {"inertia", o.ball.inertia},
                {"noise_v", o.noise_v}, {"noise_omega", o.noise_omega},
                {"outlier_fraction", o.outlier_fraction}};
  if (o.friction.kind == bounce::FrictionKind::regularized) truth["slip_scale"] = o.friction.slip_scale;
  // The table records each row's whole impact (what a film measures and `bounce fit`
  // predicts); the rows where the ball touches the floor again are listed.
  const auto again = analysis::whole_impact_differences(res.rows, o.ball, o.law, o.friction, 1e-10, 0);
  res.json = {{"out", opts.out}, {"rows", res.rows.size()}, {"truth", truth},
              {"rows_touching_again", again.rows}, {"warnings", json::array()}};
  return res;
}

const ResultKeys& bounce_synth_video_result_keys() {
  static const ResultKeys k = {
      {"out", "", ""}, {"frames", "", ""}, {"t_touch", "s", "real time from release"},
      {"t_separation", "s", "real time from release"}, {"vx_in", "m/s", ""}, {"vy_in", "m/s", ""},
      {"omega_in", "rad/s", ""}, {"theta_touch_deg", "deg", ""}, {"vx_out", "m/s", ""}, {"vy_out", "m/s", ""},
      {"omega_out", "rad/s", ""}, {"release_apex", "m", ""}, {"post_apex", "m", ""}, {"e_height", "", ""},
  };
  return k;
}

const ResultKeys& bounce_synth_table_result_keys() {
  static const ResultKeys k = {
      {"out", "", ""}, {"rows", "", ""}, {"truth.model", "", ""}, {"truth.K", "N/m^n", ""}, {"truth.n", "", ""},
      {"truth.D", "N s/m^(n+1)", ""}, {"truth.restitution", "", ""}, {"truth.friction", "", ""}, {"truth.mu", "", ""},
      {"truth.a", "m", ""}, {"truth.b", "m", ""}, {"truth.mass", "kg", ""}, {"truth.inertia", "kg m^2", ""},
      {"truth.noise_v", "m/s", ""}, {"truth.noise_omega", "rad/s", ""}, {"truth.outlier_fraction", "", ""},
      {"truth.slip_scale", "m/s", ""}, {"warnings", "", ""},
      {"rows_touching_again", "", "rows whose impact has a second contact (recorded whole, as a film shows it)"},
  };
  return k;
}

}  // namespace tribolab::app
