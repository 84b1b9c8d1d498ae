// Benchmarks of the bounce engine (docs/benchmarks.md#bounce): one contact per normal law and
// per friction mode, the first-contact search, and the seed's own method — explicit steps of
// 1 microsecond (seed 001, 實驗四 (二)) — as the baseline at equal accuracy.
#include "app/bounce/bounce_cell.hpp"
#include "bounce/contact.hpp"
#include "bounce/flight.hpp"
#include "bounce/seed_method.hpp"
#include "numerics/units.hpp"
#include "sweep/runner.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using namespace tribolab::bounce;

// The reference impact: the seed's fitted law, seed-like state (axis 30 deg, 4 m/s down,
// 0.5 m/s forward, 40 rad/s).
BodyState reference_touch() {
  BodyState s;
  s.theta = tribolab::to_rad(30);
  s.vx = 0.5;
  s.vy = -4;
  s.omega = 40;
  return s;
}

NormalLaw law_for(NormalModel m) {
  NormalLawSpec spec;
  spec.model = m;
  if (m == NormalModel::hertz) {
    spec.n = 1.5;
    spec.D = 0;
  } else if (m == NormalModel::hooke) {
    spec.n = 1;
    spec.restitution = 0.5;
  } else if (m != NormalModel::hunt_crossley) {
    spec.restitution = 0.5;
  }
  const Ball ball;
  const BodyState s = reference_touch();
  return resolve(spec, -contact_point_velocity(ball, s.theta, s.vx, s.vy, s.omega).vy, ball.mass);
}

/// The seed's method: explicit steps of dt with f = -mu N sign(v_t), velocities first then
/// positions (symplectic Euler), until the penetration returns to zero
/// (src/bounce/seed_method.cpp, the tight loop of issue 15; Hunt–Crossley law only).
ContactResult seed_euler(const Ball& ball, const NormalLaw& law, double mu, const BodyState& in, double dt,
                         double g = tribolab::kDefaultG) {
  seed::SeedParams p;
  p.a = ball.a;
  p.b = ball.b;
  p.mass = ball.mass;
  p.inertia = ball.inertia;
  p.K = law.K;
  p.n = law.n;
  p.chi = law.D / law.K;
  p.mu = mu;
  p.g = g;
  const seed::SeedOut o = seed::seed_contact(p, in.theta, in.vx, in.vy, in.omega, dt);
  ContactResult r;
  r.out.vx = o.vx;
  r.out.vy = o.vy;
  r.out.omega = o.omega;
  r.contact_duration = o.duration;
  return r;
}

const ContactResult& reference() {
  static const ContactResult ref = simulate_contact(Ball{}, law_for(NormalModel::hunt_crossley), FrictionModel{},
                                                    reference_touch(), contact_options_with_tolerance(1e-13));
  return ref;
}

/// Error of the outgoing state against the reference, m/s (omega scaled by b to a speed).
double error_of(const ContactResult& r) {
  const ContactResult& ref = reference();
  return std::max({std::abs(r.out.vx - ref.out.vx), std::abs(r.out.vy - ref.out.vy),
                   std::abs(r.out.omega - ref.out.omega) * Ball{}.b});
}

void BM_ContactLaw(benchmark::State& state) {
  const auto model = static_cast<NormalModel>(state.range(0));
  const NormalLaw law = law_for(model);
  const Ball ball;
  const BodyState s = reference_touch();
  ContactResult r;
  for (auto _ : state) {
    r = simulate_contact(ball, law, FrictionModel{}, s);
    benchmark::DoNotOptimize(r);
  }
  state.SetLabel(std::string(to_string(model)));
  state.counters["steps"] = static_cast<double>(r.steps);
  state.counters["rhs_calls"] = static_cast<double>(r.rhs_calls);
}
BENCHMARK(BM_ContactLaw)->DenseRange(0, 5)->Unit(benchmark::kMicrosecond);

void BM_ContactFriction(benchmark::State& state) {
  FrictionModel f;
  f.kind = static_cast<FrictionKind>(state.range(0));
  const NormalLaw law = law_for(NormalModel::hunt_crossley);
  const Ball ball;
  const BodyState s = reference_touch();
  ContactResult r;
  for (auto _ : state) {
    r = simulate_contact(ball, law, f, s);
    benchmark::DoNotOptimize(r);
  }
  state.SetLabel(std::string(to_string(f.kind)));
  state.counters["steps"] = static_cast<double>(r.steps);
  state.counters["phases"] = static_cast<double>(r.n_phases);
}
BENCHMARK(BM_ContactFriction)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);

// Our solver at several tolerances, with the error it reaches (counter "error", m/s).
void BM_ContactTolerance(benchmark::State& state) {
  const double tol = std::pow(10.0, -static_cast<double>(state.range(0)));
  const NormalLaw law = law_for(NormalModel::hunt_crossley);
  const ContactOptions o = contact_options_with_tolerance(tol);
  const Ball ball;
  const BodyState s = reference_touch();
  ContactResult r;
  for (auto _ : state) {
    r = simulate_contact(ball, law, FrictionModel{}, s, o);
    benchmark::DoNotOptimize(r);
  }
  state.counters["error"] = error_of(r);
  state.counters["steps"] = static_cast<double>(r.steps);
  state.counters["rhs_calls"] = static_cast<double>(r.rhs_calls);
}
BENCHMARK(BM_ContactTolerance)->DenseRange(3, 12, 1)->Unit(benchmark::kMicrosecond);

// The seed's method; range(0) = step in nanoseconds (1000 = the seed's 1 us).
void BM_SeedEuler(benchmark::State& state) {
  const double dt = static_cast<double>(state.range(0)) * 1e-9;
  const NormalLaw law = law_for(NormalModel::hunt_crossley);
  const Ball ball;
  const BodyState s = reference_touch();
  ContactResult r;
  for (auto _ : state) {
    r = seed_euler(ball, law, 0.5, s, dt);
    benchmark::DoNotOptimize(r);
  }
  state.counters["error"] = error_of(r);
  state.counters["steps"] = r.contact_duration / dt;
}
BENCHMARK(BM_SeedEuler)->Arg(1000)->Arg(100)->Arg(10)->Unit(benchmark::kMicrosecond);

// Independent contacts on every thread: the solver shares nothing and allocates nothing.
void BM_ContactThreads(benchmark::State& state) {
  const NormalLaw law = law_for(NormalModel::hunt_crossley);
  const Ball ball;
  BodyState s = reference_touch();
  s.omega += state.thread_index();
  for (auto _ : state) benchmark::DoNotOptimize(simulate_contact(ball, law, FrictionModel{}, s));
}
BENCHMARK(BM_ContactThreads)->Threads(1)->Threads(2)->UseRealTime()->Unit(benchmark::kMicrosecond);

void BM_FirstContact(benchmark::State& state) {
  const Ball ball;
  const double omega = static_cast<double>(state.range(0));
  FlightResult r;
  for (auto _ : state) {
    r = first_contact_from_apex(ball, 0.7, omega, 0.2);
    benchmark::DoNotOptimize(r);
  }
  state.counters["iterations"] = static_cast<double>(r.iterations);
}
BENCHMARK(BM_FirstContact)->Arg(0)->Arg(40)->Arg(500)->Unit(benchmark::kMicrosecond);

// ---- The seed's full phase diagram (docs/benchmarks.md#bounce-sweep-phase-diagram) ----
// Collision angle 100..170 deg (71 values) x spin 30..50 rad/s (21 values) at vy = -4 m/s,
// vx = 0, mu = 0.5, the seed's fitted law: the grid of its figure 53 at 1 deg x 1 rad/s.
// Each cell is the library's bounce cell model (app/bounce/bounce_cell.hpp, the model of `bounce
// sweep`; its default tolerance is 1e-6, the loosest with no cell less accurate than the
// seed's method), first contact phase only: the phase the seed's method integrates.

tribolab::sweep::GridSpec seed_map_grid() {
  tribolab::sweep::GridSpec g;
  g.axes = {tribolab::sweep::Axis{tribolab::sweep::Quantity::theta_deg, 100, 170, 71},
            tribolab::sweep::Axis{tribolab::sweep::Quantity::omega, 30, 50, 21}};
  g.fixed_speed = 4;
  g.fixed_mu = 0.5;
  return g;
}

BodyState seed_map_touch(const tribolab::sweep::CellInput& in) {
  BodyState s;
  s.theta = theta_for_collision_angle(Ball{}, in.theta_deg, 1);
  s.vy = -in.speed;
  s.omega = in.omega;
  return s;
}

/// Outgoing vx, vy, omega, e of a cell (first contact phase) by our solver at `tol`.
tribolab::sweep::CellModel seed_map_model(double tol) {
  tribolab::app::BounceCellOptions o;  // the seed's ball and fitted law, Coulomb, g = kDefaultG
  o.law.tol = tol;
  return tribolab::app::bounce_cell_model(tribolab::app::make_bounce_cell(o, tribolab::app::BounceCellKind::contact));
}

/// Map column k as a velocity, m/s: vx, vy and b * omega.
double as_velocity(const std::vector<double>& map, std::size_t c, std::size_t k) {
  return map[4 * c + k] * (k == 2 ? Ball{}.b : 1.0);
}

const std::vector<double>& seed_map_reference() {
  static const std::vector<double> ref = tribolab::sweep::evaluate_grid(seed_map_grid(), seed_map_model(1e-12));
  return ref;
}

/// Accuracy of a map against the tol-1e-12 reference map: the largest error of
/// (vx, vy, b omega) over all cells, m/s, and the number of cells off by more than
/// 1e-3 m/s. Such cells are "flips": near grazing, the support point lifts off for a
/// moment (d returns to 0) and a method that steps over that dip continues a contact
/// the reference ends (docs/benchmarks.md#bounce-sweep-phase-diagram).
struct MapError {
  double max = 0;
  int flips = 0;
};
MapError seed_map_error(const std::vector<double>& map) {
  const std::vector<double>& ref = seed_map_reference();
  MapError e;
  for (std::size_t c = 0; c < ref.size() / 4; ++c) {
    double err = 0;
    for (std::size_t k = 0; k < 3; ++k) err = std::max(err, std::abs(as_velocity(map, c, k) - as_velocity(ref, c, k)));
    e.max = std::max(e.max, err);
    e.flips += err > 1e-3;
  }
  return e;
}

/// The seed's method (explicit 1 us steps) over the map, cell outputs as in seed_map_model.
std::vector<double> seed_map_seed_euler() {
  const tribolab::sweep::GridSpec g = seed_map_grid();
  const NormalLaw law = resolve(NormalLawSpec{}, 1, Ball{}.mass);  // no restitution: D as given
  std::vector<double> map(static_cast<std::size_t>(g.cell_count()) * 4);
  for (std::int64_t i = 0; i < g.cell_count(); ++i) {
    const ContactResult r = seed_euler(Ball{}, law, 0.5, seed_map_touch(g.cell(i)), 1e-6);
    map[4 * i] = r.out.vx;
    map[4 * i + 1] = r.out.vy;
    map[4 * i + 2] = r.out.omega;
    map[4 * i + 3] = r.out.vy / 4;
  }
  return map;
}

/// Cells where `map` is less accurate than the seed's method (against the 1e-12 reference).
int cells_worse_than_seed(const std::vector<double>& map) {
  static const std::vector<double> seed = seed_map_seed_euler();
  const std::vector<double>& ref = seed_map_reference();
  int worse = 0;
  for (std::size_t c = 0; c < ref.size() / 4; ++c) {
    double ours = 0, theirs = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      ours = std::max(ours, std::abs(as_velocity(map, c, k) - as_velocity(ref, c, k)));
      theirs = std::max(theirs, std::abs(as_velocity(seed, c, k) - as_velocity(ref, c, k)));
    }
    worse += ours > theirs;
  }
  return worse;
}

// Our solver over the whole map; range(0) = -log10(tol), range(1) = threads. Counters:
// max_error and flips as above, worse_than_seed = cells less accurate than the seed's method.
void BM_SeedMapOurs(benchmark::State& state) {
  const double tol = std::pow(10.0, -static_cast<double>(state.range(0)));
  const tribolab::sweep::GridSpec g = seed_map_grid();
  const tribolab::sweep::CellModel m = seed_map_model(tol);
  tribolab::sweep::RunOptions ro;
  ro.threads = static_cast<int>(state.range(1));
  std::vector<double> map;
  for (auto _ : state) {
    map = tribolab::sweep::evaluate_grid(g, m, ro);
    benchmark::DoNotOptimize(map.data());
  }
  state.SetItemsProcessed(state.iterations() * g.cell_count());
  const MapError e = seed_map_error(map);
  state.counters["max_error"] = e.max;
  state.counters["flips"] = e.flips;
  state.counters["worse_than_seed"] = cells_worse_than_seed(map);
}
BENCHMARK(BM_SeedMapOurs)
    ->ArgsProduct({{5, 6, 8, 10}, {1, 2}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// The seed's method (explicit 1 us steps) over the same map, one thread.
void BM_SeedMapSeedEuler(benchmark::State& state) {
  const tribolab::sweep::GridSpec g = seed_map_grid();
  std::vector<double> map;
  for (auto _ : state) {
    map = seed_map_seed_euler();
    benchmark::DoNotOptimize(map.data());
  }
  state.SetItemsProcessed(state.iterations() * g.cell_count());
  const MapError e = seed_map_error(map);
  state.counters["max_error"] = e.max;
  state.counters["flips"] = e.flips;
}
BENCHMARK(BM_SeedMapSeedEuler)->Iterations(1)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
