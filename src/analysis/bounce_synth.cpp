// docs/theory.md#bounce-synthetic.
#include "analysis/bounce_synth.hpp"

#include "numerics/physical_range.hpp"

#include "bounce/flight.hpp"
#include "bounce/impact.hpp"
#include "numerics/error.hpp"
#include "numerics/units.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <numbers>
#include <random>

namespace tribolab::analysis {

namespace {
[[noreturn]] void throw_invalid(const std::string& e) { throw input_error_of(e); }
}  // namespace

std::string SynthVideoOptions::validate() const {
  if (auto e = ball.validate(); !e.empty()) return e;
  if (auto e = law.validate(); !e.empty()) return e;
  if (auto e = friction.validate(); !e.empty()) return e;
  // Physical ranges: numerics/physical_range.hpp (docs/cli.md#physical-ranges).
  for (const auto& [v, r, name] :
       {std::tuple{height, ranges::height, "height"}, {theta_deg, ranges::angle_deg, "theta-deg"},
        {omega, ranges::spin, "omega"}, {vx, ranges::velocity, "vx"}, {vy, ranges::velocity, "vy"},
        {time_factor, PhysicalRange{1e-3, 1e5, ""}, "time-factor"}})
    if (auto e = range_error(v, r, name); !e.empty()) return e;
  for (double v : {after, fps, noise})
    if (!std::isfinite(v)) return "options must be finite numbers";
  if (!(height > ball.a)) return "height: the release height must exceed the semi-major axis a";
  if (!(after > 0 && after <= 10)) return "after: must lie in (0, 10] s";
  if (!(fps >= 10 && fps <= 100000)) return "fps: must lie in [10, 100000]";
  if (!(noise >= 0 && noise < 0.1)) return "noise: must lie in [0, 0.1) m";
  if (!(time_factor > 0)) return "time-factor: must be positive";
  return {};
}

double SynthVideoTruth::vy_flight(bool pre, double t) const {
  return pre ? touch.vy - g * (t - t_touch) : separation.vy - g * (t - t_separation);
}

ThrowMotion simulate_throw(const SynthVideoOptions& o) {
  if (auto e = o.validate(); !e.empty()) throw_invalid(e);
  const double g = kDefaultG;  // the synthetic videos fall at the studies' g
  ThrowMotion m;
  bounce::BodyState& s0 = m.release;
  s0.y = o.height;
  s0.theta = o.theta_deg / kDegPerRad;  // not to_rad(): the same bits as before
  s0.omega = o.omega;
  s0.vx = o.vx;
  s0.vy = o.vy;
  bounce::FlightOptions fo;
  fo.g = g;
  const auto first = bounce::first_contact(o.ball, s0, fo);
  if (first.status != bounce::FlightStatus::contact) throw InputError("the release touches the floor");
  // The whole impact (bounce::simulate_impact): a ball that leaves the floor still moving
  // down, or touches again before its apex, is filmed through its further contacts, as
  // `bounce simulate` and the maps follow it; the history holds every contact, and the
  // flights between them are free flight, which state()'s cubic Hermite reproduces exactly.
  bounce::ImpactOptions io;
  io.contact.g = g;
  const auto impact = bounce::simulate_impact(o.ball, o.law, o.friction, first.state, io, &m.contact);
  const bounce::ContactResult& c = impact.whole;
  // Still on the floor (or chattering) is what the input asks for; a failed integration is not.
  if (impact.status == bounce::ImpactStatus::rest || impact.status == bounce::ImpactStatus::max_contacts)
    throw InputError("the contact did not end: " + std::string(impact.message));
  if (impact.status != bounce::ImpactStatus::free_flight) throw SolverError("the contact did not end: " + std::string(impact.message));
  SynthVideoTruth& tr = m.truth;
  tr.g = g;
  tr.t_touch = first.t_contact;
  tr.touch = first.state;
  tr.t_separation = first.t_contact + c.contact_duration;
  tr.separation = c.out;
  // simulate_contact starts from the touch state itself, so out.x and the history's x are
  // already positions in the video's frame.
  tr.floor_y = 0;
  tr.release_apex = o.vy > 0 ? o.height + o.vy * o.vy / (2 * g) : o.height;
  tr.post_apex = tr.separation.y + std::max(0.0, tr.separation.vy) * std::max(0.0, tr.separation.vy) / (2 * g);
  // The motion ends `after` s after separation or at the next touch.
  m.t_end = tr.t_separation + o.after;
  const auto next = bounce::first_contact(o.ball, tr.separation, fo);
  if (next.status == bounce::FlightStatus::contact) m.t_end = std::min(m.t_end, tr.t_separation + next.t_contact);
  return m;
}

bounce::BodyState ThrowMotion::state(double t) const {
  if (t < truth.t_touch || contact.empty()) return bounce::free_flight(release, truth.g, t);
  if (t >= truth.t_separation) return bounce::free_flight(truth.separation, truth.g, t - truth.t_separation);
  const double tc = t - truth.t_touch;
  // The history sample at or before tc and the next one (steps are far below a frame).
  auto it = std::upper_bound(contact.begin(), contact.end(), tc,
                             [](double v, const bounce::ContactSample& c) { return v < c.t; });
  if (it == contact.begin()) return contact.front().state;
  if (it == contact.end()) return contact.back().state;
  const bounce::BodyState& p = std::prev(it)->state;
  const bounce::BodyState& q = it->state;
  const double h = it->t - std::prev(it)->t;
  if (!(h > 0)) return q;
  // Cubic Hermite on [t_i, t_i+1] from positions and their rates; rates interpolated linearly.
  const double u = (tc - std::prev(it)->t) / h;
  const double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u);
  const double h01 = u * u * (3 - 2 * u), h11 = u * u * (u - 1);
  auto hermite = [&](double a, double da, double b, double db) { return h00 * a + h10 * h * da + h01 * b + h11 * h * db; };
  bounce::BodyState s;
  s.x = hermite(p.x, p.vx, q.x, q.vx);
  s.y = hermite(p.y, p.vy, q.y, q.vy);
  s.theta = hermite(p.theta, p.omega, q.theta, q.omega);
  s.vx = p.vx + u * (q.vx - p.vx);
  s.vy = p.vy + u * (q.vy - p.vy);
  s.omega = p.omega + u * (q.omega - p.omega);
  return s;
}

SynthVideo synth_video(const SynthVideoOptions& o) {
  const ThrowMotion m = simulate_throw(o);
  SynthVideo v;
  v.truth = m.truth;
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> phase(0, 1);
  std::normal_distribution<double> noise(0, 1);
  const double dt = 1 / o.fps;
  const double t0 = phase(rng) * dt;  // the first frame falls anywhere within a frame period
  v.tip_a.name = "A";
  v.tip_b.name = "B";
  for (int k = 0;; ++k) {
    const double t = t0 + k * dt;
    if (t > m.t_end) break;
    // The motion's state at the frame's time: free flight, or inside the contact the Hermite
    // interpolation of the contact history (a frame once took the history sample at or before
    // its time, up to ~0.5 mm off and dependent on the integrator's step choice).
    const bounce::BodyState s = m.state(t);
    const double ca = o.ball.a * std::cos(s.theta), sa = o.ball.a * std::sin(s.theta);
    // A is the tip at -a along the major axis, B at +a, so theta = atan2(B - A).
    const track::TrackPoint pa{k, t * o.time_factor, s.x - ca + o.noise * noise(rng), s.y - sa + o.noise * noise(rng)};
    const track::TrackPoint pb{k, t * o.time_factor, s.x + ca + o.noise * noise(rng), s.y + sa + o.noise * noise(rng)};
    v.tip_a.points.push_back(pa);
    v.tip_b.points.push_back(pb);
  }
  return v;
}

std::string SynthTableOptions::validate() const {
  if (auto e = ball.validate(); !e.empty()) return e;
  if (auto e = law.validate(); !e.empty()) return e;
  if (auto e = friction.validate(); !e.empty()) return e;
  if (rows < 1 || rows > 100000) return "rows: must lie in 1..100000";
  if (!(speed_min > 0 && speed_max >= speed_min && speed_max < 100)) return "speed-min: need 0 < speed-min <= speed-max < 100 m/s";
  if (!(vx_max >= 0 && vx_max < 100)) return "vx-max: must lie in [0, 100) m/s";
  if (!(omega_max >= 0 && omega_max < 1000)) return "omega-max: must lie in [0, 1000) rad/s";
  if (!(noise_v >= 0 && noise_v < 10)) return "noise-v: must lie in [0, 10) m/s";
  if (!(noise_omega >= 0 && noise_omega < 100)) return "noise-omega: must lie in [0, 100) rad/s";
  if (!(outlier_fraction >= 0 && outlier_fraction <= 1)) return "outlier-fraction: must lie in [0, 1]";
  if (!(outlier_v >= 0 && outlier_v < 100)) return "outlier-v: must lie in [0, 100) m/s";
  return {};
}

std::vector<BounceRow> synth_table(const SynthTableOptions& o) {
  if (auto e = o.validate(); !e.empty()) throw_invalid(e);
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> n(0, 1);
  std::vector<BounceRow> rows;
  // A draw whose contact point does not approach the floor, or whose contact does not end in
  // a separation, is drawn again. A law that never bounces the ball back hung here (K =
  // 1e-310: every contact failed; K = 1e-6, D = 0: the ball sinks for the whole
  // max_duration); so 200 draws in a row without a bounce end it with an error.
  constexpr int kMaxMisses = 200;
  int misses = 0, no_approach = 0, stuck = 0, failed = 0;
  while (static_cast<int>(rows.size()) < o.rows) {
    if (misses == kMaxMisses) {
      throw InputError(std::to_string(kMaxMisses) + " random drops in a row gave no bounce (" +
                       std::to_string(stuck) + " still in contact after the maximum duration, " +
                       std::to_string(failed) + " failed, " + std::to_string(no_approach) +
                       " not approaching the floor; " + std::to_string(rows.size()) + " of " +
                       std::to_string(o.rows) +
                       " rows made): these law parameters and speeds give no bounce table");
    }
    ++misses;
    bounce::BodyState s;
    s.theta = (u(rng) - 0.5) * std::numbers::pi;
    s.vx = (2 * u(rng) - 1) * o.vx_max;
    s.vy = -(o.speed_min + (o.speed_max - o.speed_min) * u(rng));
    s.omega = (2 * u(rng) - 1) * o.omega_max;
    const auto sp = bounce::support(o.ball, s.theta);
    if (!(s.vy + s.omega * sp.X < -0.2)) {  // the contact point must approach the floor
      ++no_approach;
      continue;
    }
    // The whole impact, as a film records it (a second touch included): what fit_bounces predicts.
    const bounce::ImpactResult impact = bounce::simulate_impact(o.ball, o.law, o.friction, s);
    if (impact.first.status != bounce::ContactStatus::separated || impact.status != bounce::ImpactStatus::free_flight) {
      ++(impact.first.status == bounce::ContactStatus::max_duration || impact.status == bounce::ImpactStatus::rest ? stuck
                                                                                                                  : failed);
      continue;
    }
    const bounce::ContactResult& c = impact.whole;
    BounceRow r;
    r.theta_deg = to_deg(s.theta);
    r.vx_in = s.vx;
    r.vy_in = s.vy;
    r.omega_in = s.omega;
    r.vx_out = c.out.vx + o.noise_v * n(rng);
    r.vy_out = c.out.vy + o.noise_v * n(rng);
    r.omega_out = c.out.omega + o.noise_omega * n(rng);
    if (o.outlier_fraction > 0 && u(rng) < o.outlier_fraction) {
      const double size = o.outlier_v * (1 + u(rng)) * (u(rng) < 0.5 ? -1 : 1);
      const double which = u(rng);
      if (which < 1.0 / 3) {
        r.vx_out += size;
      } else if (which < 2.0 / 3) {
        r.vy_out += size;
      } else {
        r.omega_out += size / o.ball.b;
      }
    }
    rows.push_back(r);
    misses = no_approach = stuck = failed = 0;
  }
  return rows;
}

}  // namespace tribolab::analysis
